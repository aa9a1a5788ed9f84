/* uart_stream.c - decoder of the board's framed UART stream, and of a
 * stream of report lines only (see uart_stream.h for the
 * resynchronisation and end-of-frame rules). */
#include "uart_stream.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "rt_fb.h"

typedef struct {
    const rx_source_t *src;
    rx_result_t *res;
    uint8_t *buf;
    size_t cap, start, end; /* unconsumed bytes are buf[start..end) */
    bool eof, after_frame;
    int read_errno;
} rx_t;

/* Makes n unconsumed bytes available at r->buf + r->start; false when the
 * input ends (or fails) first. Reads only what it lacks, so a live source
 * is never asked for bytes past the ones the decoder needs. */
static bool need(rx_t *r, size_t n)
{
    while (r->end - r->start < n) {
        if (r->eof)
            return false;
        if (r->cap - r->start < n) {
            if (r->start > 0)
                memmove(r->buf, r->buf + r->start, r->end - r->start);
            r->end -= r->start;
            r->start = 0;
            if (r->cap < n) {
                size_t cap = r->cap * 2 > n ? r->cap * 2 : n;
                if (cap < 4096)
                    cap = 4096;
                uint8_t *nb = realloc(r->buf, cap);
                if (!nb) {
                    r->eof = true;
                    r->read_errno = ENOMEM;
                    return false;
                }
                r->buf = nb;
                r->cap = cap;
            }
        }
        long got = r->src->read(r->src->ctx, r->buf + r->end, r->cap - r->end, r->after_frame);
        if (got <= 0) {
            r->eof = true;
            r->read_errno = got < 0 ? (errno ? errno : EIO) : 0;
            return false;
        }
        r->end += (size_t)got;
    }
    return true;
}

static const uint8_t *at(const rx_t *r) { return r->buf + r->start; }

static void consume(rx_t *r, size_t n)
{
    r->start += n;
    r->res->offset += n;
}

static unsigned u16(const uint8_t *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }
static unsigned long u32(const uint8_t *p) { return u16(p) | (unsigned long)u16(p + 2) << 16; }

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static int fail(rx_t *r, const char *fmt, ...)
{
    char what[120];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (r->read_errno == ENOMEM)
        snprintf(r->res->error, sizeof r->res->error, "out of memory (at byte %lu)", r->res->offset);
    else if (r->read_errno)
        snprintf(r->res->error, sizeof r->res->error, "read error: %s (at byte %lu)", strerror(r->read_errno),
                 r->res->offset);
    else
        snprintf(r->res->error, sizeof r->res->error, "%s (at byte %lu)", what, r->res->offset);
    return -1;
}

static void emit_text(rx_t *r, size_t len)
{
    if (r->src->text)
        r->src->text(r->src->ctx, (const char *)at(r) + 3, len);
    r->res->texts++;
    consume(r, 3 + len);
}

/* Before the frame: is the 'T' at the current byte a report line? Its
 * text must be printable, which a 'T' inside noise or boot text rarely
 * is for long, and a text that ran over the frame header never is (the
 * header's format byte is a small number, RT_FB_FORMATS in rt_fb.h). */
static bool plausible_text(rx_t *r, size_t *len)
{
    if (!need(r, 3))
        return false;
    size_t n = u16(at(r) + 1);
    if (n > RX_TEXT_MAX)
        return false;
    for (size_t i = 0; i < n; i++) {
        if (!need(r, 3 + i + 1))
            return false;
        uint8_t c = at(r)[3 + i];
        if (c < 0x20 || c > 0x7e)
            return false;
    }
    *len = n;
    return true;
}

/* One band record at the current byte; lines_done counts the rows so far. */
static int band(rx_t *r, image_t *img, rt_fb_format_t fmt, unsigned *lines_done, uLong *frame_adler)
{
    if (!need(r, 5))
        return fail(r, "stream truncated in a band header");
    unsigned y = u16(at(r) + 1), n = u16(at(r) + 3);
    if (y != *lines_done || n == 0 || y + n > (unsigned)img->height)
        return fail(r, "band out of order or out of the frame (rows %u..%u of %d, %u received)", y, y + n,
                    img->height, *lines_done);
    size_t line_bytes = RT_FB_LINE_BYTES(fmt, img->width);
    size_t bytes = (size_t)n * line_bytes;
    if (!need(r, 5 + bytes + 4))
        return fail(r, "stream truncated in a band");
    const uint8_t *px = at(r) + 5;
    if (adler32(adler32(0L, Z_NULL, 0), px, (uInt)bytes) != u32(px + bytes))
        return fail(r, "band checksum mismatch (rows %u..%u)", y, y + n - 1);
    *frame_adler = adler32(*frame_adler, px, (uInt)bytes);
    for (size_t l = 0; l < n; l++) {
        uint8_t *dst = img->rgb + ((size_t)y + l) * (size_t)img->width * 3;
        for (size_t x = 0; x < (size_t)img->width; x++)
            rt_fb_expand(fmt, px + l * line_bytes, x, dst + 3 * x);
    }
    *lines_done += n;
    consume(r, 5 + bytes + 4);
    return 0;
}

static int decode(rx_t *r)
{
    rx_result_t *res = r->res;
    image_t *img = &res->img;

    /* Before the frame: report lines, or noise to skip. */
    for (;;) {
        if (!need(r, 1)) {
            res->no_header = !r->read_errno;
            return fail(r, "no frame in the stream");
        }
        uint8_t c = at(r)[0];
        size_t len;
        if (c == 'R' && need(r, 4) && memcmp(at(r), "RTF1", 4) == 0)
            break;
        if (c == 'T' && plausible_text(r, &len)) {
            emit_text(r, len);
        } else {
            consume(r, 1);
            res->skipped++;
        }
    }
    if (!need(r, 9))
        return fail(r, "stream truncated in the frame header");
    const uint8_t *h = at(r);
    unsigned fmt = h[4], w = u16(h + 5), ht = u16(h + 7);
    uint32_t max_pixels = r->src->max_pixels ? r->src->max_pixels : (uint32_t)RX_MAX_DIM * RX_MAX_DIM;
    if (fmt >= RT_FB_N_FORMATS || w == 0 || ht == 0 || w > RX_MAX_DIM || ht > RX_MAX_DIM || (uint64_t)w * ht > max_pixels)
        return fail(r, "bad frame header (format %u, %ux%u)", fmt, w, ht);
    res->format = fmt;
    img->rgb = calloc((size_t)w * ht, 3);
    if (!img->rgb)
        return fail(r, "out of memory for a %ux%u frame", w, ht);
    img->width = (int)w;
    img->height = (int)ht;
    consume(r, 9);

    /* The frame: strict. */
    unsigned lines_done = 0;
    uLong frame_adler = adler32(0L, Z_NULL, 0);
    for (bool ended = false; !ended;) {
        if (!need(r, 1))
            return fail(r, "stream truncated: %u of %u lines", lines_done, ht);
        switch (at(r)[0]) {
        case 'T':
            if (!need(r, 3) || !need(r, 3 + (size_t)u16(at(r) + 1)))
                return fail(r, "stream truncated in a report line");
            emit_text(r, u16(at(r) + 1));
            break;
        case 'B':
            if (band(r, img, (rt_fb_format_t)fmt, &lines_done, &frame_adler) != 0)
                return -1;
            break;
        case 'E':
            if (!need(r, 5))
                return fail(r, "stream truncated in the frame end");
            if (lines_done != ht)
                return fail(r, "frame ended early: %u of %u lines", lines_done, ht);
            if (u32(at(r) + 1) != frame_adler)
                return fail(r, "frame checksum mismatch");
            consume(r, 5);
            ended = true;
            break;
        case 'R':
            return fail(r, "a frame header inside a frame");
        default:
            return fail(r, "unexpected byte 0x%02x inside the frame", at(r)[0]);
        }
    }

    /* After the frame: the report lines that follow it, up to anything
     * else, the end of the input, or (live source) an idle line. */
    r->after_frame = true;
    while (need(r, 1) && at(r)[0] == 'T') {
        if (!need(r, 3) || !need(r, 3 + (size_t)u16(at(r) + 1)))
            return fail(r, "stream truncated in a report line after the frame");
        emit_text(r, u16(at(r) + 1));
    }
    if (r->read_errno)
        return fail(r, "read error");
    return 0;
}

/* Report lines only: noise before the first is skipped as before a frame;
 * from the first on, each must follow the last, whole and printable (a
 * serial line going idle after one ends the stream). */
static int reports(rx_t *r)
{
    rx_result_t *res = r->res;
    while (need(r, 1)) {
        uint8_t c = at(r)[0];
        size_t len;
        if (c == 'R' && need(r, 4) && memcmp(at(r), "RTF1", 4) == 0)
            return fail(r, "a frame header in a stream of report lines only");
        if (c == 'T' && plausible_text(r, &len)) {
            emit_text(r, len);
            r->after_frame = true;
        } else if (res->texts == 0) {
            consume(r, 1);
            res->skipped++;
        } else if (c != 'T') {
            return fail(r, "unexpected byte 0x%02x after a report line", c);
        } else if (!need(r, 3) || !need(r, 3 + (size_t)u16(at(r) + 1))) {
            return fail(r, "stream truncated in a report line");
        } else if (u16(at(r) + 1) > RX_TEXT_MAX) {
            return fail(r, "report line too long (%u bytes)", u16(at(r) + 1));
        } else {
            return fail(r, "a report line with a byte that is not printable text");
        }
    }
    if (r->read_errno)
        return fail(r, "read error");
    if (res->texts == 0)
        return fail(r, "no report line in the stream");
    return 0;
}

int rx_reports(const rx_source_t *src, rx_result_t *res)
{
    memset(res, 0, sizeof *res);
    rx_t r = { .src = src, .res = res };
    int rc = reports(&r);
    free(r.buf);
    return rc;
}

int rx_frame(const rx_source_t *src, rx_result_t *res)
{
    memset(res, 0, sizeof *res);
    rx_t r = { .src = src, .res = res };
    int rc = decode(&r);
    free(r.buf);
    if (rc != 0) {
        /* not image_free: the decoder links without image.c (and libpng) */
        free(res->img.rgb);
        res->img = (image_t){ 0, 0, NULL };
    }
    return rc;
}
