/* sink_stream.c - the default display: a framed scanline stream on the
 * console (format in sink.h). */
#include "sink.h"

#include "port.h"

static uint32_t frame_adler;
static size_t frame_line_bytes;
static uint16_t frame_height;

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

static int stream_begin(rt_fb_sink_t *s, uint16_t w, uint16_t h)
{
    sink_io_begin();
    uint8_t hdr[9] = { 'R', 'T', 'F', '1', (uint8_t)s->format };
    put_u16(hdr + 5, w);
    put_u16(hdr + 7, h);
    port_write(hdr, sizeof hdr);
    frame_adler = 1;
    frame_height = h;
#ifdef RT_FB_ONLY_FORMAT
    frame_line_bytes = RT_FB_LINE_BYTES(RT_FB_ONLY_FORMAT, w); /* the build's one format */
#else
    frame_line_bytes = RT_FB_LINE_BYTES(s->format, w);
#endif
    sink_io_end();
    return 0;
}

static int stream_flush(rt_fb_sink_t *s, const rt_fb_area_t *a, const uint8_t *px)
{
    sink_io_begin();
    uint16_t lines = (uint16_t)(a->y2 - a->y1 + 1);
    size_t n = (size_t)lines * frame_line_bytes;
    uint8_t hdr[5] = { 'B' }, tail[4];
    put_u16(hdr + 1, a->y1);
    put_u16(hdr + 3, lines);
    port_write(hdr, sizeof hdr);
    port_write(px, n);
    put_u32(tail, adler32(1, px, n));
    port_write(tail, sizeof tail);
    frame_adler = adler32(frame_adler, px, n);
    sink_progress(lines, frame_height);
    rt_fb_flush_ready(s); /* UART writes are synchronous */
    sink_io_end();
    return 0;
}

/* (on a real UART the record's bytes wait for the line, like a band's:
 * output too, not the render's) */
static int stream_end(rt_fb_sink_t *s)
{
    (void)s;
    sink_io_begin();
    uint8_t rec[5] = { 'E' };
    put_u32(rec + 1, frame_adler);
    port_write(rec, sizeof rec);
    sink_io_end();
    return 0;
}

void sink_init(rt_fb_sink_t *sink, rt_fb_format_t format, uint8_t *band, size_t bytes)
{
    sink->format = format;
    sink->band[0] = band;
    sink->band[1] = 0;
    sink->band_bytes = bytes;
    sink->begin = stream_begin;
    sink->flush = stream_flush;
    sink->wait = 0;
    sink->end = stream_end;
    sink->user = 0;
    sink->flushing = false;
}
