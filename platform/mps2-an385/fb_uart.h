/*
 * fb_uart.h - the board's "display": finished bands streamed over UART0
 * in a framed format the host turns back into an image (rt receive).
 *
 * Records, all integers little-endian:
 *   'R' 'T' 'F' '1' fmt:u8 width:u16 height:u16     frame header
 *   'B' y:u16 lines:u16 pixels[lines*line_bytes] adler32:u32   one band
 *       (fmt: rt_fb_format_t; line_bytes = RT_FB_LINE_BYTES(fmt, width), rt_fb.h)
 *   'E' adler32:u32                                  frame end: checksum
 *                                                    of all pixel bytes
 *   'T' len:u16 text[len]                            a report line
 */
#ifndef FB_UART_H
#define FB_UART_H

#include "rt_fb.h"

/* A sink with one band buffer of `bytes`; flush time is excluded from
 * the instruction count (see fb_uart_io_instructions). It streams whole
 * frames: no viewport, tightly packed lines (pitch 0). */
void fb_uart_init(rt_fb_sink_t *sink, rt_fb_format_t format, uint8_t *band, size_t bytes);

/* Instructions spent inside the sink (UART output and checksums). */
uint64_t fb_uart_io_instructions(void);

/* One 'T' record; and one reading "key value". */
void uart_report(const char *text);
void uart_report_value(const char *key, uint64_t value);

#endif
