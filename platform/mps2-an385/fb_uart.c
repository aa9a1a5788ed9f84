/* fb_uart.c - framed scanline stream over UART0 (format in fb_uart.h). */
#include "fb_uart.h"

#include "board.h"

static uint32_t frame_adler;
static size_t frame_line_bytes;
static uint64_t io_instructions;

static uint32_t adler32(uint32_t adler, const uint8_t *p, size_t n)
{
    uint32_t a = adler & 0xFFFF, b = adler >> 16;
    for (size_t i = 0; i < n; i++) {
        a += p[i];
        if (a >= 65521)
            a -= 65521;
        b += a;
        if (b >= 65521)
            b -= 65521;
    }
    return b << 16 | a;
}

static void put_u16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
}

static void put_u32(uint8_t *p, uint32_t v)
{
    put_u16(p, (uint16_t)v);
    put_u16(p + 2, (uint16_t)(v >> 16));
}

static int uart_begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    uint64_t t0 = icount_read();
    uint8_t hdr[9] = { 'R', 'T', 'F', '1', (uint8_t)s->format };
    put_u16(hdr + 5, w);
    put_u16(hdr + 7, h);
    uart_write(hdr, sizeof hdr);
    frame_adler = 1;
#ifdef RT_FB_ONLY_FORMAT
    frame_line_bytes = RT_FB_LINE_BYTES(RT_FB_ONLY_FORMAT, w); /* the build's one format */
#else
    frame_line_bytes = RT_FB_LINE_BYTES(s->format, w);
#endif
    io_instructions += icount_read() - t0;
    return 0;
}

static int uart_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    uint64_t t0 = icount_read();
    uint16_t lines = (uint16_t)(a->y2 - a->y1 + 1);
    size_t n = (size_t)lines * frame_line_bytes;
    uint8_t hdr[5] = { 'B' }, tail[4];
    put_u16(hdr + 1, a->y1);
    put_u16(hdr + 3, lines);
    uart_write(hdr, sizeof hdr);
    uart_write(px, n);
    put_u32(tail, adler32(1, px, n));
    uart_write(tail, sizeof tail);
    frame_adler = adler32(frame_adler, px, n);
    rt_fb_flush_ready(s); /* UART writes are synchronous */
    io_instructions += icount_read() - t0;
    return 0;
}

static int uart_end(rt_fb_sink_t *s)
{
    (void)s;
    uint8_t rec[5] = { 'E' };
    put_u32(rec + 1, frame_adler);
    uart_write(rec, sizeof rec);
    return 0;
}

void fb_uart_init(rt_fb_sink_t *sink, rt_fb_format_t format, uint8_t *band, size_t bytes)
{
    sink->format = format;
    sink->band[0] = band;
    sink->band[1] = 0;
    sink->band_bytes = bytes;
    sink->begin = uart_begin;
    sink->flush = uart_flush;
    sink->wait = 0;
    sink->end = uart_end;
    sink->user = 0;
    sink->flushing = false;
}

uint64_t fb_uart_io_instructions(void) { return io_instructions; }

void uart_report(const char *text)
{
    uint16_t n = 0;
    while (text[n] != '\0')
        n++;
    uint8_t hdr[3] = { 'T' };
    put_u16(hdr + 1, n);
    uart_write(hdr, sizeof hdr);
    uart_write(text, n);
}

void uart_report_value(const char *key, uint64_t value)
{
    char line[64];
    unsigned n = 0;
    while (*key && n < 40)
        line[n++] = *key++;
    line[n++] = ' ';
    char digits[20];
    unsigned k = 0;
    do {
        digits[k++] = (char)('0' + value % 10);
        value /= 10;
    } while (value != 0);
    while (k)
        line[n++] = digits[--k];
    line[n] = '\0';
    uart_report(line);
}
