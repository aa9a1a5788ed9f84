/*
 * sink_stream_test.c - the stream sink (app/firmware/sink_stream.c)
 * and its output accounting (sink_io.c) on the host, against a console
 * whose every byte takes time, as a real UART's does (QEMU's is always
 * ready, so no board run shows it): each of begin(), flush() and end()
 * must count all the time its bytes took as output (sink_io_cycles,
 * sink_io_instructions), which main.c takes from the render's counts,
 * and nothing else. Built by tests/boards/board-tests.sh with BOARD_CYCLES=1;
 * prints one line per check and "sink-stream: N passed, M failed".
 */
#include <stdio.h>

#include "port.h"
#include "sink.h"

/* A fake clock: only the console advances it, BYTE_TIME a byte (a byte
 * at 115200 baud is about 14,600 cycles at 168 MHz) */
#define BYTE_TIME 1000u
static uint64_t now;
static size_t written;
static uint8_t last[5]; /* the last five bytes out */

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        now += BYTE_TIME;
        last[written++ % sizeof last] = p[i];
    }
}

void port_icount_start(void) {}
uint64_t port_icount_read(void) { return now; }
uint64_t port_cycles_read(void) { return now; }

static int pass, fail;

/* What one sink call wrote, against what it counted as output */
static void check_call(const char *call, size_t bytes_before, uint64_t cycles_before, uint64_t instr_before)
{
    size_t bytes = written - bytes_before;
    uint64_t cycles = sink_io_cycles() - cycles_before, instr = sink_io_instructions() - instr_before;
    int ok = bytes > 0 && cycles == bytes * BYTE_TIME && instr == cycles;
    printf("  %s  %s: %zu bytes out, %llu of their %llu cycles counted as output\n", ok ? "ok  " : "FAIL", call,
           bytes, (unsigned long long)cycles, (unsigned long long)(bytes * BYTE_TIME));
    ok ? pass++ : fail++;
}

int main(void)
{
    enum { W = 6, H = 5, BAND_LINES = 2 };
    static uint8_t band[BAND_LINES * W * 3];
    static rt_fb_sink_t sink;
    sink_init(&sink, RT_FB_RGB888, band, sizeof band);
    for (size_t i = 0; i < sizeof band; i++)
        band[i] = (uint8_t)(i * 37u);

    size_t b = written;
    uint64_t c = sink_io_cycles(), n = sink_io_instructions();
    int rc = sink.begin(&sink, W, H);
    check_call("begin (the frame header)", b, c, n);
    for (uint16_t y = 0; y < H && rc == 0; y += BAND_LINES) {
        rt_fb_area_t a = { 0, y, W - 1, (uint16_t)(y + BAND_LINES - 1 < H ? y + BAND_LINES - 1 : H - 1) };
        char what[64];
        snprintf(what, sizeof what, "flush of rows %u to %u (and its progress line)", a.y1, a.y2);
        b = written, c = sink_io_cycles(), n = sink_io_instructions();
        sink.flushing = true;
        rc = sink.flush(&sink, &a, band);
        check_call(what, b, c, n);
    }
    b = written, c = sink_io_cycles(), n = sink_io_instructions();
    rc |= sink.end(&sink);
    check_call("end (the end record)", b, c, n);

    int ok = rc == 0 && last[(written - 5) % 5] == 'E' && sink_io_cycles() == written * BYTE_TIME;
    printf("  %s  the frame: %zu bytes, the last record 'E'; all their time is output, none the render's\n",
           ok ? "ok  " : "FAIL", written);
    ok ? pass++ : fail++;
    printf("sink-stream: %d passed, %d failed\n", pass, fail);
    return fail != 0;
}
