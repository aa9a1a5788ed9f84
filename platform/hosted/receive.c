/*
 * receive.c - `rt receive [STREAM] -o OUT.png`: decode the framed stream
 * that the board's UART sink writes (format in platform/mps2-an385/fb_uart.h),
 * verify every checksum, print the report lines and write the image.
 * Exit status 2 on a truncated or corrupt stream, never a partial image.
 */
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "image.h"
#include "receive.h"

typedef struct {
    FILE *in;
    const char *name;
    long offset;
} stream_t;

static bool get(stream_t *s, void *buf, size_t n)
{
    size_t got = fread(buf, 1, n, s->in);
    s->offset += (long)got;
    return got == n;
}

static unsigned u16(const unsigned char *p) { return (unsigned)p[0] | (unsigned)p[1] << 8; }
static unsigned long u32(const unsigned char *p) { return u16(p) | (unsigned long)u16(p + 2) << 16; }

static int fail(const stream_t *s, const char *what)
{
    fprintf(stderr, "rt receive: %s: %s (at byte %ld)\n", s->name, what, s->offset);
    return 2;
}

int cmd_receive(int argc, char **argv)
{
    const char *in_path = NULL, *out_path = NULL;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "-o") && i + 1 < argc)
            out_path = argv[++i];
        else if (argv[i][0] != '-' && !in_path)
            in_path = argv[i];
        else {
            fprintf(stderr, "rt receive: unexpected argument '%s'\nusage: rt receive [STREAM] -o OUT.png\n", argv[i]);
            return 2;
        }
    }
    if (!out_path) {
        fprintf(stderr, "rt receive: no output file given (-o OUT.png)\n");
        return 2;
    }
    stream_t s = { stdin, "stdin", 0 };
    if (in_path) {
        s.in = fopen(in_path, "rb");
        s.name = in_path;
        if (!s.in) {
            fprintf(stderr, "rt receive: cannot open '%s': %s\n", in_path, strerror(errno));
            return 2;
        }
    }
    image_t img = { 0, 0, NULL };
    unsigned bpp = 3, lines_done = 0;
    uLong frame_adler = adler32(0L, Z_NULL, 0);
    bool started = false, finished = false;
    unsigned char *band = NULL;
    int rc = 0;
    int c;
    while (rc == 0 && !finished && (c = fgetc(s.in)) != EOF) {
        s.offset++;
        unsigned char h[8];
        if (c == 'T') {
            if (!get(&s, h, 2)) { rc = fail(&s, "stream truncated in a text record"); break; }
            unsigned n = u16(h);
            char text[65536];
            if (!get(&s, text, n)) { rc = fail(&s, "stream truncated in a text record"); break; }
            printf("%.*s\n", (int)n, text);
        } else if (c == 'R') {
            if (!get(&s, h, 8) || memcmp(h, "TF1", 3) != 0) { rc = fail(&s, "bad frame header"); break; }
            if (started) { rc = fail(&s, "a second frame header inside a frame"); break; }
            unsigned fmt = h[3];
            img.width = (int)u16(h + 4);
            img.height = (int)u16(h + 6);
            if (fmt > 1 || img.width == 0 || img.height == 0) { rc = fail(&s, "bad frame header values"); break; }
            bpp = fmt == 1 ? 2 : 3;
            img.rgb = calloc((size_t)img.width * img.height, 3);
            if (!img.rgb) { rc = fail(&s, "out of memory"); break; }
            started = true;
        } else if (c == 'B') {
            if (!started) { rc = fail(&s, "band before the frame header"); break; }
            if (!get(&s, h, 4)) { rc = fail(&s, "stream truncated in a band header"); break; }
            unsigned y = u16(h), n = u16(h + 2);
            if (y != lines_done || n == 0 || y + n > (unsigned)img.height) { rc = fail(&s, "band out of order or out of the frame"); break; }
            size_t bytes = (size_t)n * img.width * bpp;
            unsigned char *grown = realloc(band, bytes);
            if (!grown) { rc = fail(&s, "out of memory"); break; } /* band is freed below */
            band = grown;
            if (!get(&s, band, bytes) || !get(&s, h, 4)) { rc = fail(&s, "stream truncated in a band"); break; }
            if (adler32(adler32(0L, Z_NULL, 0), band, (uInt)bytes) != u32(h)) { rc = fail(&s, "band checksum mismatch"); break; }
            frame_adler = adler32(frame_adler, band, (uInt)bytes);
            for (size_t i = 0; i < (size_t)n * img.width; i++) {
                unsigned char *dst = img.rgb + ((size_t)y * img.width + i) * 3;
                if (bpp == 3) {
                    memcpy(dst, band + 3 * i, 3);
                } else {
                    unsigned v = u16(band + 2 * i);
                    dst[0] = (unsigned char)(((v >> 11) * 255 + 15) / 31);
                    dst[1] = (unsigned char)((((v >> 5) & 63) * 255 + 31) / 63);
                    dst[2] = (unsigned char)(((v & 31) * 255 + 15) / 31);
                }
            }
            lines_done += n;
        } else if (c == 'E') {
            if (!started) { rc = fail(&s, "frame end without a frame"); break; }
            if (!get(&s, h, 4)) { rc = fail(&s, "stream truncated in the frame end"); break; }
            if (lines_done != (unsigned)img.height) { rc = fail(&s, "frame ended early"); break; }
            if (u32(h) != frame_adler) { rc = fail(&s, "frame checksum mismatch"); break; }
            finished = true;
        } else {
            char msg[64];
            snprintf(msg, sizeof msg, "unexpected byte 0x%02x", c);
            rc = fail(&s, msg);
        }
    }
    /* report lines after the frame */
    while (rc == 0 && finished && (c = fgetc(s.in)) == 'T') {
        unsigned char h[2];
        char text[65536];
        s.offset++;
        if (!get(&s, h, 2) || !get(&s, text, u16(h))) { rc = fail(&s, "stream truncated in a text record"); break; }
        printf("%.*s\n", (int)u16(h), text);
    }
    if (rc == 0 && !finished) {
        char msg[80];
        snprintf(msg, sizeof msg, started ? "stream truncated: %u of %d lines" : "no frame in the stream",
                 lines_done, img.height);
        rc = fail(&s, msg);
    }
    if (in_path)
        fclose(s.in);
    free(band);
    if (rc == 0) {
        char why[256];
        if (image_write(out_path, &img, why, sizeof why) != 0) {
            fprintf(stderr, "rt receive: %s\n", why);
            rc = 1;
        }
    }
    image_free(&img);
    return rc;
}
