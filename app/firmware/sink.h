/*
 * sink.h - the firmware's display: where finished bands go. The default
 * (sink_stream.c) streams them over the console in a framed format the
 * host turns back into an image (rt receive); a board with a real panel
 * brings its own sink (BOARD_SINK in its board.mk).
 *
 * Stream records, all integers little-endian:
 *   'R' 'T' 'F' '1' fmt:u8 width:u16 height:u16     frame header
 *   'B' y:u16 lines:u16 pixels[lines*line_bytes] adler32:u32   one band
 *       (fmt: rt_fb_format_t; line_bytes = RT_FB_LINE_BYTES(fmt, width), rt_fb.h)
 *   'E' adler32:u32                                  frame end: checksum
 *                                                    of all pixel bytes
 *   'T' len:u16 text[len]                            a report line
 * Report lines go to the console on every board (report.c).
 */
#ifndef SINK_H
#define SINK_H

#include "rt_fb.h"

/* A sink with one band buffer of `bytes` for whole frames (no viewport,
 * pitch 0). Time inside it is excluded from the render's counts. */
void sink_init(rt_fb_sink_t *sink, rt_fb_format_t format, uint8_t *band, size_t bytes);

/* A sink brackets its work (output, checksums, waiting for a transfer)
 * in these, not nested (sink_io.c); the totals are what main.c takes
 * from the render's instructions and, on a port that counts them
 * (BOARD_CYCLES), its cycles (sink_io_cycles: the calling core's). */
void sink_io_begin(void);
void sink_io_end(void);
uint64_t sink_io_instructions(void);
uint64_t sink_io_cycles(void);

/* After a band of `lines` of a frame `height` rows high has gone out:
 * the board's heartbeat (port_heartbeat), and a report line
 * "progress_rows N" (rows drawn so far) at the first band, each tenth of
 * the frame and its last band. Call it inside sink_io_begin/end. */
void sink_progress(uint32_t lines, uint32_t height);

/* 1 when the frame stays on a panel after the run (a board's display
 * sink sets it in BOARD_CFLAGS): the firmware then reports "drawn 1" and
 * idles instead of exiting, so that the host can capture the panel. */
#ifndef SINK_HOLDS_FRAME
#define SINK_HOLDS_FRAME 0
#endif

/* One report line "key value" ('T' record). */
void report_value(const char *key, uint64_t value);

#endif
