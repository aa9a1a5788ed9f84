/*
 * fuzz_scenec.c - libFuzzer harness over the scene compiler (rt-scenec):
 * NFF bytes through the reader at the board's capacities and through the
 * emitters (C tables, header, embedded text) into /dev/null, under ASan
 * and UBSan. Any input must either load and emit without fault or fail
 * with a message.
 */
#define SCENEC_NO_MAIN 1
#include "../../tools/scenec.c"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static FILE *null;
    if (!null && !(null = fopen("/dev/null", "w")))
        abort();
    rt_error_t err;
    if (!nff_read((const char *)data, size, &store, &err)) {
        if (err.msg[0] == '\0')
            abort();
        return 0;
    }
    if (scenec_emit(null, null, "fuzz.nff", &store.scene, (const char *)data, size, false) != 0 ||
        scenec_emit(null, NULL, "fuzz.nff", &store.scene, (const char *)data, size, true) != 0)
        abort();
    return 0;
}
