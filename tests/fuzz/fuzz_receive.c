/*
 * fuzz_receive.c - libFuzzer harness over the decoder of the board's UART
 * stream (app/rt/uart_stream.c, what `rt receive` runs), under
 * ASan and UBSan. The input is the stream itself (the seeds are streams
 * from QEMU runs), decoded twice: read whole, as from a file; and handed
 * over 1 to 13 bytes at a time by a source that goes idle right after
 * the frame, as a serial line does. Each must give a whole frame or a
 * reason and no image, and when both give a frame it is the same one.
 * The same input then goes through the report-only decoder (rx_reports,
 * `rt receive --report-only`) both ways: never an image, a reason on
 * failure, and up to the first report line (where the live source goes
 * idle) the same result both ways.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rt_fb.h"
#include "uart_stream.h"

typedef struct {
    const uint8_t *data;
    size_t size, pos, chunk;
    int live;
} mem_source_t;

static long mem_read(void *ctx, uint8_t *buf, size_t cap, bool after_frame)
{
    mem_source_t *m = ctx;
    if (after_frame && m->live)
        return 0;
    size_t n = m->size - m->pos;
    if (n > cap)
        n = cap;
    if (n > m->chunk)
        n = m->chunk;
    memcpy(buf, m->data + m->pos, n);
    m->pos += n;
    return (long)n;
}

/* every byte handed out is read, so ASan checks it is in bounds */
static volatile unsigned sink;

static void text(void *ctx, const char *t, size_t len)
{
    (void)ctx;
    for (size_t i = 0; i < len; i++)
        sink += (unsigned char)t[i];
}

#define MAX_PIXELS (1u << 16) /* keeps each run fast; rt allows RX_MAX_DIM squared */

static int decode(const uint8_t *data, size_t size, size_t chunk, int live, rx_result_t *res)
{
    mem_source_t m = { data, size, 0, chunk, live };
    rx_source_t src = { mem_read, text, &m, MAX_PIXELS };
    int rc = rx_frame(&src, res);
    if (rc == 0) {
        if (!res->img.rgb || res->img.width < 1 || res->img.height < 1 || res->format >= RT_FB_N_FORMATS ||
            (uint64_t)res->img.width * (uint64_t)res->img.height > MAX_PIXELS || res->offset > size ||
            res->skipped > res->offset || res->error[0] != '\0')
            abort();
        for (size_t i = 0; i < (size_t)res->img.width * (size_t)res->img.height * 3; i++)
            sink += res->img.rgb[i];
    } else if (rc != -1 || res->error[0] == '\0' || res->img.rgb || res->offset > size) {
        abort();
    }
    return rc;
}

static int decode_reports(const uint8_t *data, size_t size, size_t chunk, int live, rx_result_t *res)
{
    mem_source_t m = { data, size, 0, chunk, live };
    rx_source_t src = { mem_read, text, &m, MAX_PIXELS };
    int rc = rx_reports(&src, res);
    if (res->img.rgb || res->offset > size || res->skipped > res->offset)
        abort();
    if (rc == 0 ? res->texts == 0 || res->error[0] != '\0' : rc != -1 || res->error[0] == '\0')
        abort();
    return rc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rx_result_t whole, live;
    int a = decode(data, size, size ? size : 1, 0, &whole);
    int b = decode(data, size, 1 + size % 13, 1, &live);
    if (a == 0 && b == 0 &&
        (whole.img.width != live.img.width || whole.img.height != live.img.height ||
         whole.format != live.format || whole.skipped != live.skipped ||
         memcmp(whole.img.rgb, live.img.rgb, (size_t)whole.img.width * (size_t)whole.img.height * 3) != 0))
        abort();
    free(whole.img.rgb);
    free(live.img.rgb);

    a = decode_reports(data, size, size ? size : 1, 0, &whole);
    b = decode_reports(data, size, 1 + size % 13, 1, &live);
    if (b != 0 && live.texts == 0 && (a == 0 || strcmp(whole.error, live.error) != 0))
        abort(); /* up to the first report line both read the same bytes */
    if (a == 0 && b == 0 && (whole.skipped != live.skipped || live.texts > whole.texts))
        abort();
    return 0;
}
