/* uart_stream.h - the decoder of the framed stream the board's UART sink
 * writes (format in app/firmware/sink.h), pulled from any byte
 * source: a file, a pipe, a serial line, or a buffer (the fuzz harness).
 *
 * Before the frame header it resynchronises: bytes that do not start the
 * header ("RTF1") or a plausible report line (a 'T' record of printable
 * text) are skipped as noise (boot text, line noise). From the header on
 * it is strict: every record must be well-formed and every checksum right,
 * or the frame is rejected. After the frame end ('E') it reads only the
 * report lines that follow, and asks the source with after_frame set, so
 * a live source can end the report when the line goes idle.
 *
 * A board whose frame goes to a panel sends report lines only
 * (rx_reports): the same resynchronisation up to the first report line,
 * then strict, and after_frame set from that line on. */
#ifndef UART_STREAM_H
#define UART_STREAM_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "image.h"

#define RX_MAX_DIM 16384 /* largest frame width or height accepted */
#define RX_TEXT_MAX 1024 /* longest report line taken as one before the frame */

typedef struct {
    /* Up to cap bytes into buf: the count, 0 at the end of the input, -1
     * on a read error (errno set). Called only when more bytes are needed. */
    long (*read)(void *ctx, uint8_t *buf, size_t cap, bool after_frame);
    /* One report line ('T' record), without a newline; may be NULL. */
    void (*text)(void *ctx, const char *text, size_t len);
    void *ctx;
    uint32_t max_pixels; /* frames over this are rejected; 0: RX_MAX_DIM squared */
} rx_source_t;

typedef struct {
    image_t img;           /* the frame as 8-bit RGB (expanded by rt_fb_expand) */
    unsigned format;       /* the frame's pixel format (rt_fb_format_t, rt_fb.h) */
    unsigned long skipped; /* noise bytes skipped before the frame header
                            * (rx_reports: before the first report line) */
    unsigned long texts;   /* report lines read */
    bool no_header;        /* rx_frame: the input ended before a frame header */
    unsigned long offset;  /* bytes consumed */
    char error[160];       /* why it failed: "what (at byte N)" */
} rx_result_t;

/* Reads one frame and the report lines after it. Returns 0 with the image
 * in res->img (free with image_free), or -1 with res->error set and no
 * image: no frame at all, a truncated or corrupt frame, or a read error. */
int rx_frame(const rx_source_t *src, rx_result_t *res);

/* Reads a stream of report lines and no frame, to its end (or, live, until
 * the line stays idle after a report line). Returns 0 when it held at
 * least one report line and nothing else after the first (res->img stays
 * empty), or -1 with res->error set: no report line, a truncated or
 * unprintable one, any other byte after the first, a frame header
 * anywhere, or a read error. */
int rx_reports(const rx_source_t *src, rx_result_t *res);

#endif
