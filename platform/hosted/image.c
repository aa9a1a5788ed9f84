/* image.c - PNG and binary PPM reading and writing, and image comparison,
 * with zlib and stdio only. */
#include "image.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#define MAX_DIM 16384
#define IO_CHUNK 65536 /* bytes per stdio read and per IDAT chunk written */

static const uint8_t png_sig[8] = {137, 'P', 'N', 'G', '\r', '\n', 26, '\n'};

#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif

PRINTF_LIKE(3, 4)
static void say(char *why, size_t why_len, const char *fmt, ...)
{
    if (!why || why_len == 0)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, why_len, fmt, ap);
    va_end(ap);
}

static int ends_with_ci(const char *s, const char *suffix)
{
    size_t n = strlen(s), m = strlen(suffix);
    if (n < m)
        return 0;
    s += n - m;
    for (size_t i = 0; i < m; i++)
        if (tolower((unsigned char)s[i]) != tolower((unsigned char)suffix[i]))
            return 0;
    return 1;
}

static uint32_t get_be32(const uint8_t *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static void put_be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

static int paeth(int a, int b, int c)
{
    int p = a + b - c;
    int pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    if (pa <= pb && pa <= pc)
        return a;
    return pb <= pc ? b : c;
}

/* ---- writing ---- */

typedef struct {
    FILE *f;
    int err; /* first errno from a failed write; later writes are skipped */
} out_t;

static void put(out_t *o, const void *p, size_t n)
{
    if (o->err || n == 0)
        return;
    errno = 0;
    if (fwrite(p, 1, n, o->f) != n)
        o->err = errno ? errno : EIO;
}

static void put_chunk(out_t *o, const char *type, const uint8_t *data, uint32_t len)
{
    uint8_t head[8], tail[4];
    put_be32(head, len);
    memcpy(head + 4, type, 4);
    uLong crc = crc32(0L, (const Bytef *)type, 4);
    /* crc32() with a null buffer returns the initial value, not crc. */
    if (len)
        crc = crc32(crc, data, len);
    put_be32(tail, (uint32_t)crc);
    put(o, head, 8);
    put(o, data, len);
    put(o, tail, 4);
}

/* Filters one row all five ways into cand (5 rows of 1 + rowlen bytes) and
 * returns the one with the smallest sum of bytes taken as signed: the usual
 * cheap predictor of which row deflate will squeeze best. */
static const uint8_t *png_filter_row(const uint8_t *cur, const uint8_t *prev, size_t rowlen,
                                     uint8_t *cand)
{
    const size_t bpp = 3;
    unsigned long sum[5] = {0};
    for (size_t k = 0; k < 5; k++)
        cand[k * (rowlen + 1)] = (uint8_t)k;
    for (size_t i = 0; i < rowlen; i++) {
        int x = cur[i], b = prev[i];
        int a = i >= bpp ? cur[i - bpp] : 0;
        int c = i >= bpp ? prev[i - bpp] : 0;
        uint8_t v[5] = {(uint8_t)x, (uint8_t)(x - a), (uint8_t)(x - b), (uint8_t)(x - (a + b) / 2),
                        (uint8_t)(x - paeth(a, b, c))};
        for (size_t k = 0; k < 5; k++) {
            cand[k * (rowlen + 1) + 1 + i] = v[k];
            sum[k] += (unsigned long)abs((int)(int8_t)v[k]);
        }
    }
    size_t best = 0;
    for (size_t k = 1; k < 5; k++)
        if (sum[k] < sum[best])
            best = k;
    return cand + best * (rowlen + 1);
}

/* Returns a reason for a non-I/O failure, or NULL; I/O errors land in o->err. */
static const char *write_png(out_t *o, const image_t *img)
{
    size_t w = (size_t)img->width, h = (size_t)img->height, rowlen = w * 3;
    uint8_t ihdr[13];
    put_be32(ihdr, (uint32_t)w);
    put_be32(ihdr + 4, (uint32_t)h);
    ihdr[8] = 8;  /* bit depth */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering */
    ihdr[12] = 0; /* not interlaced */
    put(o, png_sig, 8);
    put_chunk(o, "IHDR", ihdr, 13);

    const char *fail = NULL;
    int z_ready = 0;
    z_stream zs;
    memset(&zs, 0, sizeof zs);
    uint8_t *zero_row = calloc(rowlen, 1);
    uint8_t *cand = malloc(5 * (rowlen + 1));
    uint8_t *zout = malloc(IO_CHUNK);
    if (!zero_row || !cand || !zout) {
        fail = "out of memory";
        goto done;
    }
    if (deflateInit(&zs, Z_DEFAULT_COMPRESSION) != Z_OK) {
        fail = "zlib deflateInit failed";
        goto done;
    }
    z_ready = 1;
    zs.next_out = zout;
    zs.avail_out = IO_CHUNK;
    /* One pass per row, then one more with Z_FINISH to drain the stream. */
    for (size_t y = 0; y <= h && !o->err; y++) {
        int flush = y == h ? Z_FINISH : Z_NO_FLUSH;
        if (y < h) {
            const uint8_t *cur = img->rgb + y * rowlen;
            const uint8_t *prev = y ? cur - rowlen : zero_row;
            zs.next_in = (Bytef *)png_filter_row(cur, prev, rowlen, cand);
            zs.avail_in = (uInt)(rowlen + 1);
        }
        for (;;) {
            int r = deflate(&zs, flush);
            if (r != Z_OK && r != Z_STREAM_END && r != Z_BUF_ERROR) {
                fail = "zlib deflate failed";
                goto done;
            }
            int full = zs.avail_out == 0, ended = r == Z_STREAM_END;
            size_t have = IO_CHUNK - zs.avail_out;
            if (full || (ended && have)) {
                put_chunk(o, "IDAT", zout, (uint32_t)have);
                zs.next_out = zout;
                zs.avail_out = IO_CHUNK;
            }
            if (ended)
                break;
            if (flush == Z_NO_FLUSH && !full && zs.avail_in == 0)
                break;
            if (r == Z_BUF_ERROR && !full) {
                fail = "zlib deflate made no progress";
                goto done;
            }
        }
    }
    put_chunk(o, "IEND", NULL, 0);
done:
    if (z_ready)
        deflateEnd(&zs);
    free(zero_row);
    free(cand);
    free(zout);
    return fail;
}

static const char *write_ppm(out_t *o, const image_t *img)
{
    char head[64];
    int n = snprintf(head, sizeof head, "P6\n%d %d\n255\n", img->width, img->height);
    put(o, head, (size_t)n);
    put(o, img->rgb, (size_t)img->width * (size_t)img->height * 3);
    return NULL;
}

int image_write(const char *path, const image_t *img, char *why, size_t why_len)
{
    if (!path || !img) {
        say(why, why_len, "image_write: no path or no image");
        return -1;
    }
    int png = ends_with_ci(path, ".png"), ppm = ends_with_ci(path, ".ppm");
    if (!png && !ppm) {
        say(why, why_len, "unknown output format '%s' (use .png or .ppm)", path);
        return -1;
    }
    if (img->width <= 0 || img->height <= 0 || !img->rgb) {
        say(why, why_len, "cannot write '%s': the image is empty", path);
        return -1;
    }
    /* Keeps a filtered row within zlib's uInt and the whole image within size_t. */
    if ((size_t)img->width > (UINT_MAX - 1) / 3
        || (size_t)img->height > SIZE_MAX / 3 / (size_t)img->width) {
        say(why, why_len, "cannot write '%s': %dx%d is too large", path, img->width, img->height);
        return -1;
    }

    size_t n = strlen(path);
    char *tmp = malloc(n + sizeof ".tmp");
    if (!tmp) {
        say(why, why_len, "cannot write '%s': out of memory", path);
        return -1;
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp", sizeof ".tmp");

    errno = 0;
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        say(why, why_len, "cannot open '%s' for writing: %s", path, strerror(errno));
        free(tmp);
        return -1;
    }
    out_t o = {f, 0};
    const char *fail = png ? write_png(&o, img) : write_ppm(&o, img);
    errno = 0;
    /* fclose flushes, so a full disk may only show up here. */
    if (fclose(f) != 0 && !o.err)
        o.err = errno ? errno : EIO;

    int rc = -1;
    if (fail)
        say(why, why_len, "cannot write '%s': %s", path, fail);
    else if (o.err)
        say(why, why_len, "cannot write '%s': %s", path, strerror(o.err));
    else if (rename(tmp, path) != 0)
        say(why, why_len, "cannot rename '%s' to '%s': %s", tmp, path, strerror(errno));
    else
        rc = 0;
    if (rc != 0)
        remove(tmp);
    free(tmp);
    return rc;
}

/* ---- reading ---- */

typedef struct {
    FILE *f;
    const char *path;
    char *why;
    size_t why_len;
} rd_t;

PRINTF_LIKE(2, 3)
static int rd_fail(rd_t *r, const char *fmt, ...)
{
    char msg[160];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    say(r->why, r->why_len, "cannot read '%s': %s", r->path, msg);
    return -1;
}

/* where names the part being read, for the truncation message. */
static int rd_exact(rd_t *r, void *buf, size_t n, const char *where)
{
    errno = 0;
    if (fread(buf, 1, n, r->f) == n)
        return 0;
    if (ferror(r->f))
        return rd_fail(r, "read error: %s", strerror(errno ? errno : EIO));
    return rd_fail(r, "file is truncated (ends inside %s)", where);
}

typedef struct {
    size_t width, height, channels;
    size_t rowlen;       /* bytes of samples per row, without the filter byte */
    uint8_t *cur, *prev; /* 1 + rowlen each; [0] is the filter type; prev starts zeroed */
    size_t fill;         /* bytes of cur inflated so far */
    size_t rows;         /* rows finished */
    uint8_t *rgb;
    z_stream zs;
    int z_ready, z_done;
    char msg[80];
} png_dec_t;

static const char *png_row(png_dec_t *d)
{
    const size_t bpp = d->channels, n = d->rowlen;
    uint8_t *x = d->cur + 1;
    const uint8_t *b = d->prev + 1;
    switch (d->cur[0]) {
    case 0:
        break;
    case 1:
        for (size_t i = bpp; i < n; i++)
            x[i] = (uint8_t)(x[i] + x[i - bpp]);
        break;
    case 2:
        for (size_t i = 0; i < n; i++)
            x[i] = (uint8_t)(x[i] + b[i]);
        break;
    case 3:
        for (size_t i = 0; i < n; i++)
            x[i] = (uint8_t)(x[i] + ((i >= bpp ? x[i - bpp] : 0) + b[i]) / 2);
        break;
    case 4:
        for (size_t i = 0; i < n; i++)
            x[i] = (uint8_t)(x[i] + (i >= bpp ? paeth(x[i - bpp], b[i], b[i - bpp]) : b[i]));
        break;
    default:
        snprintf(d->msg, sizeof d->msg, "unknown PNG filter type %d in row %zu", d->cur[0],
                 d->rows);
        return d->msg;
    }
    uint8_t *o = d->rgb + d->rows * d->width * 3;
    for (size_t px = 0; px < d->width; px++, o += 3, x += bpp) {
        if (bpp < 3) {
            o[0] = o[1] = o[2] = x[0]; /* grey, alpha dropped */
        } else {
            o[0] = x[0];
            o[1] = x[1];
            o[2] = x[2];
        }
    }
    uint8_t *t = d->prev;
    d->prev = d->cur;
    d->cur = t;
    d->fill = 0;
    d->rows++;
    return NULL;
}

static const char *png_feed(png_dec_t *d, const uint8_t *data, size_t n)
{
    d->zs.next_in = (Bytef *)data;
    d->zs.avail_in = (uInt)n;
    while (d->zs.avail_in > 0 && !d->z_done) {
        /* Anything after the last row (other encoders' padding) is ignored. */
        if (d->rows == d->height) {
            d->z_done = 1;
            break;
        }
        d->zs.next_out = d->cur + d->fill;
        d->zs.avail_out = (uInt)(d->rowlen + 1 - d->fill);
        int ret = inflate(&d->zs, Z_NO_FLUSH);
        d->fill = d->rowlen + 1 - d->zs.avail_out;
        if (ret == Z_STREAM_END)
            d->z_done = 1;
        else if (ret == Z_MEM_ERROR)
            return "out of memory";
        else if (ret != Z_OK)
            return "corrupt compressed image data";
        if (d->fill == d->rowlen + 1) {
            const char *e = png_row(d);
            if (e)
                return e;
        }
    }
    return NULL;
}

static int png_ihdr(rd_t *r, png_dec_t *d, const uint8_t *h)
{
    uint32_t w = get_be32(h), ht = get_be32(h + 4);
    int depth = h[8], type = h[9];
    if (w == 0 || ht == 0)
        return rd_fail(r, "PNG has zero width or height");
    if (w > MAX_DIM || ht > MAX_DIM)
        return rd_fail(r, "PNG is %lux%lu, over the %dx%d limit", (unsigned long)w,
                       (unsigned long)ht, MAX_DIM, MAX_DIM);
    switch (type) {
    case 0: d->channels = 1; break;
    case 2: d->channels = 3; break;
    case 4: d->channels = 2; break;
    case 6: d->channels = 4; break;
    case 3: return rd_fail(r, "palette PNGs are not supported");
    default: return rd_fail(r, "invalid PNG colour type %d", type);
    }
    if (depth != 8)
        return rd_fail(r, "%d-bit PNG samples are not supported (only 8-bit)", depth);
    if (h[10] != 0 || h[11] != 0)
        return rd_fail(r, "unknown PNG compression or filter method");
    if (h[12] == 1)
        return rd_fail(r, "interlaced PNGs are not supported");
    if (h[12] != 0)
        return rd_fail(r, "invalid PNG interlace method %d", h[12]);

    d->width = w;
    d->height = ht;
    d->rowlen = d->width * d->channels;
    d->cur = calloc(d->rowlen + 1, 1);
    d->prev = calloc(d->rowlen + 1, 1);
    d->rgb = malloc(d->width * d->height * 3);
    if (!d->cur || !d->prev || !d->rgb)
        return rd_fail(r, "out of memory");
    if (inflateInit(&d->zs) != Z_OK)
        return rd_fail(r, "zlib inflateInit failed");
    d->z_ready = 1;
    return 0;
}

static int read_png(rd_t *r, image_t *img)
{
    png_dec_t d;
    memset(&d, 0, sizeof d);
    int rc = -1, have_ihdr = 0, ended = 0;
    uint8_t *buf = malloc(IO_CHUNK);
    if (!buf) {
        rd_fail(r, "out of memory");
        goto out;
    }
    while (!ended) {
        uint8_t head[8], tail[4];
        if (rd_exact(r, head, 8, "a PNG chunk header"))
            goto out;
        uint32_t len = get_be32(head);
        char type[5] = {0};
        memcpy(type, head + 4, 4);
        for (int i = 0; i < 4; i++)
            if (!isalpha((unsigned char)type[i])) {
                rd_fail(r, "corrupt PNG chunk header");
                goto out;
            }
        if (len > 0x7fffffffu) {
            rd_fail(r, "PNG chunk '%s' has an invalid length", type);
            goto out;
        }
        if (!have_ihdr && strcmp(type, "IHDR") != 0) {
            rd_fail(r, "PNG does not start with an IHDR chunk");
            goto out;
        }
        char where[32];
        snprintf(where, sizeof where, "PNG chunk '%s'", type);
        uLong crc = crc32(0L, head + 4, 4);

        if (strcmp(type, "IHDR") == 0) {
            if (have_ihdr || len != 13) {
                rd_fail(r, "bad PNG IHDR chunk");
                goto out;
            }
            if (rd_exact(r, buf, 13, where) || png_ihdr(r, &d, buf))
                goto out;
            crc = crc32(crc, buf, 13);
            have_ihdr = 1;
        } else {
            if (strcmp(type, "IEND") == 0)
                ended = 1;
            /* A critical chunk we do not know could change the meaning of
             * the pixels; PLTE is only a display hint for RGB images. */
            else if (isupper((unsigned char)type[0]) && strcmp(type, "IDAT") != 0
                     && !(strcmp(type, "PLTE") == 0 && d.channels >= 3)) {
                rd_fail(r, "unsupported PNG chunk '%s'", type);
                goto out;
            }
            int is_idat = strcmp(type, "IDAT") == 0;
            for (uint32_t left = len; left > 0;) {
                size_t n = left < IO_CHUNK ? left : IO_CHUNK;
                if (rd_exact(r, buf, n, where))
                    goto out;
                crc = crc32(crc, buf, (uInt)n);
                left -= (uint32_t)n;
                if (is_idat) {
                    const char *e = png_feed(&d, buf, n);
                    if (e) {
                        rd_fail(r, "%s", e);
                        goto out;
                    }
                }
            }
        }
        if (rd_exact(r, tail, 4, where))
            goto out;
        if (get_be32(tail) != (uint32_t)crc) {
            rd_fail(r, "CRC mismatch in PNG chunk '%s' (corrupt file)", type);
            goto out;
        }
    }
    if (d.rows < d.height) {
        rd_fail(r, "PNG image data is incomplete (%zu of %zu rows)", d.rows, d.height);
        goto out;
    }
    img->width = (int)d.width;
    img->height = (int)d.height;
    img->rgb = d.rgb;
    d.rgb = NULL;
    rc = 0;
out:
    if (d.z_ready)
        inflateEnd(&d.zs);
    free(d.cur);
    free(d.prev);
    free(d.rgb);
    free(buf);
    return rc;
}

/* Reads a header number after any whitespace and # comments; *after gets
 * the character that ended it. Returns -1 when there is no sane number. */
static long ppm_num(FILE *f, int *after)
{
    int c = getc(f);
    for (;;) {
        if (c == '#')
            while (c != '\n' && c != '\r' && c != EOF)
                c = getc(f);
        else if (c != EOF && isspace(c))
            c = getc(f);
        else
            break;
    }
    if (c < '0' || c > '9')
        return -1;
    long v = 0;
    while (c >= '0' && c <= '9') {
        v = v * 10 + (c - '0');
        if (v > 1000000)
            return -1;
        c = getc(f);
    }
    *after = c;
    return v;
}

static int read_ppm(rd_t *r, image_t *img)
{
    int c = getc(r->f);
    if (c == EOF || !(isspace(c) || c == '#'))
        return rd_fail(r, "bad PPM header");
    ungetc(c, r->f);
    long v[3];
    for (int i = 0; i < 3; i++) {
        v[i] = ppm_num(r->f, &c);
        if (v[i] < 0)
            return rd_fail(r, "bad PPM header");
        /* The maxval's single whitespace byte is the last of the header. */
        if (i < 2 && c != EOF)
            ungetc(c, r->f);
    }
    if (!(c != EOF && isspace(c)))
        return rd_fail(r, "bad PPM header");
    if (v[0] == 0 || v[1] == 0)
        return rd_fail(r, "PPM has zero width or height");
    if (v[0] > MAX_DIM || v[1] > MAX_DIM)
        return rd_fail(r, "PPM is %ldx%ld, over the %dx%d limit", v[0], v[1], MAX_DIM, MAX_DIM);
    if (v[2] != 255)
        return rd_fail(r, "PPM maxval %ld is not supported (only 255)", v[2]);

    size_t n = (size_t)v[0] * (size_t)v[1] * 3;
    uint8_t *rgb = malloc(n);
    if (!rgb)
        return rd_fail(r, "out of memory");
    if (rd_exact(r, rgb, n, "the PPM pixel data")) {
        free(rgb);
        return -1;
    }
    img->width = (int)v[0];
    img->height = (int)v[1];
    img->rgb = rgb;
    return 0;
}

int image_read(const char *path, image_t *img, char *why, size_t why_len)
{
    if (!path || !img) {
        say(why, why_len, "image_read: no path or no image");
        return -1;
    }
    img->width = img->height = 0;
    img->rgb = NULL;
    errno = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        say(why, why_len, "cannot open '%s' for reading: %s", path, strerror(errno));
        return -1;
    }
    rd_t r = {f, path, why, why_len};
    uint8_t m[8];
    int rc;
    errno = 0;
    size_t got = fread(m, 1, 2, f);
    if (got < 2 && ferror(f))
        rc = rd_fail(&r, "read error: %s", strerror(errno ? errno : EIO));
    else if (got < 2)
        rc = rd_fail(&r, "%s", got ? "file is too short to be an image" : "file is empty");
    else if (m[0] == png_sig[0] && m[1] == png_sig[1]) {
        rc = rd_exact(&r, m + 2, 6, "the PNG signature");
        if (rc == 0 && memcmp(m, png_sig, 8) != 0)
            rc = rd_fail(&r, "corrupt PNG signature (file damaged by a text-mode transfer?)");
        if (rc == 0)
            rc = read_png(&r, img);
    } else if (m[0] == 'P' && m[1] == '6')
        rc = read_ppm(&r, img);
    else if (m[0] == 'P' && m[1] >= '1' && m[1] <= '7')
        rc = rd_fail(&r, "Netpbm format P%c is not supported (only binary PPM, P6)", m[1]);
    else
        rc = rd_fail(&r, "not a PNG or binary PPM file");
    fclose(f);
    if (rc != 0)
        image_free(img);
    return rc;
}

void image_free(image_t *img)
{
    if (!img)
        return;
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}

/* ---- comparison ---- */

int image_compare(const image_t *a, const image_t *b, image_diff_t *d, char *why, size_t why_len)
{
    if (!a || !b || !d) {
        say(why, why_len, "image_compare: missing argument");
        return -1;
    }
    if (a->width != b->width || a->height != b->height) {
        say(why, why_len, "image sizes differ: %dx%d vs %dx%d", a->width, a->height, b->width,
            b->height);
        return -1;
    }
    size_t pixels = a->width > 0 && a->height > 0 ? (size_t)a->width * (size_t)a->height : 0;
    if (pixels && (!a->rgb || !b->rgb)) {
        say(why, why_len, "image_compare: image has no pixel data");
        return -1;
    }
    /* Exact in a 64-bit integer: at most 3 * 65025 per pixel. */
    unsigned long long sq = 0;
    size_t over2 = 0, over8 = 0;
    int max_err = 0;
    for (size_t i = 0; i < pixels; i++) {
        int worst = 0;
        for (size_t c = 0; c < 3; c++) {
            int e = abs((int)a->rgb[i * 3 + c] - (int)b->rgb[i * 3 + c]);
            sq += (unsigned long long)(e * e);
            if (e > worst)
                worst = e;
        }
        over2 += worst > 2;
        over8 += worst > 8;
        if (worst > max_err)
            max_err = worst;
    }
    d->max_err = max_err;
    d->mse = pixels ? (double)sq / ((double)pixels * 3) : 0;
    d->psnr_db = d->mse > 0 ? 10 * log10(255.0 * 255.0 / d->mse) : INFINITY;
    d->share_over2 = pixels ? (double)over2 / (double)pixels : 0;
    d->share_over8 = pixels ? (double)over8 / (double)pixels : 0;
    return 0;
}
