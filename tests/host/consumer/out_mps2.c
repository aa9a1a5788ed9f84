/* out_mps2.c - the consumer's output on the MPS2 AN385 (Cortex-M3) and
 * AN386 (Cortex-M4F, the same UART and timer): UART0, which QEMU's
 * -nographic connects to its stdout. It also counts the render's
 * instructions as the board firmware does (the port's counter, exact
 * under QEMU's -icount shift=0), apart from the output's own: from the
 * first write, the PPM header the sink's begin writes, to the frame's
 * last pixel. The count goes to the debug console through semihosting
 * (QEMU's stderr), so stdout stays the image:
 *   render_instructions N
 */
#include "port.h"
#include "scene_data.h" /* SCENE_WIDTH, SCENE_HEIGHT */

int out_write(const void *p, size_t n);

#define PIXEL_BYTES ((size_t)SCENE_WIDTH * SCENE_HEIGHT * 3u)

static void debug_write(const char *text) /* SYS_WRITE0 */
{
    register uint32_t r0 __asm__("r0") = 0x04u;
    register const char *r1 __asm__("r1") = text;
    __asm__ volatile("bkpt 0xab" : : "r"(r0), "r"(r1) : "memory");
}

static void report_count(uint64_t count)
{
    char line[48] = "render_instructions ", digits[20];
    char *p = line + 20;
    int n = 0;
    do
        digits[n++] = (char)('0' + count % 10);
    while ((count /= 10) != 0);
    while (n > 0)
        *p++ = digits[--n];
    *p++ = '\n';
    *p = '\0';
    debug_write(line);
}

int out_write(const void *p, size_t n)
{
    static int started;
    static uint64_t output; /* instructions spent writing */
    if (!started) {
        port_init();
        port_icount_start();
    }
    uint64_t t0 = port_icount_read();
    port_write(p, n);
    output += port_icount_read() - t0;
    if (started) { /* after the header: pixels */
        static size_t pixel_bytes;
        pixel_bytes += n;
        if (pixel_bytes == PIXEL_BYTES)
            report_count(port_icount_read() - output);
    }
    started = 1;
    return 0;
}
