/* out_mps2.c - the consumer's output on the MPS2 AN385: UART0, which
 * QEMU's -nographic connects to its stdout. */
#include "port.h"

int out_write(const void *p, size_t n);

int out_write(const void *p, size_t n)
{
    static int ready;
    if (!ready) {
        port_init();
        ready = 1;
    }
    port_write(p, n);
    return 0;
}
