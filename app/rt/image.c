/* image.c - PNG (through libpng) and binary PPM reading and writing, and
 * image comparison. */
#include "image.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <png.h>

#define MAX_DIM 16384

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

/* ---- libpng glue: its errors become "path: message" in why ---- */

typedef struct {
    FILE *f;
    const char *path;
    char *why;
    size_t why_len;
} png_io_t;

static void png_fail(png_structp png, png_const_charp msg)
{
    png_io_t *io = png_get_error_ptr(png);
    say(io->why, io->why_len, "%s: %s", io->path, msg);
    png_longjmp(png, 1);
}

/* Warnings (ancillary chunks with bad CRCs, odd profiles) change no pixel. */
static void png_quiet(png_structp png, png_const_charp msg)
{
    (void)png;
    (void)msg;
}

static void png_read_bytes(png_structp png, png_bytep data, size_t n)
{
    png_io_t *io = png_get_io_ptr(png);
    errno = 0;
    if (fread(data, 1, n, io->f) == n)
        return;
    if (ferror(io->f)) {
        char msg[128];
        snprintf(msg, sizeof msg, "read error: %s", strerror(errno ? errno : EIO));
        png_error(png, msg);
    }
    png_error(png, "file is truncated");
}

static void png_write_bytes(png_structp png, png_bytep data, size_t n)
{
    png_io_t *io = png_get_io_ptr(png);
    errno = 0;
    if (fwrite(data, 1, n, io->f) != n) {
        char msg[128];
        snprintf(msg, sizeof msg, "cannot write: %s", strerror(errno ? errno : EIO));
        png_error(png, msg);
    }
}

static void png_flush_bytes(png_structp png) { (void)png; }

/* ---- writing ---- */

static int write_png(png_io_t *io, const image_t *img)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, io, png_fail, png_quiet);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_write_struct(&png, NULL);
        say(io->why, io->why_len, "%s: out of memory", io->path);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return -1;
    }
    png_set_write_fn(png, io, png_write_bytes, png_flush_bytes);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < img->height; y++)
        png_write_row(png, img->rgb + (size_t)y * (size_t)img->width * 3);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return 0;
}

static int write_ppm(png_io_t *io, const image_t *img)
{
    errno = 0;
    if (fprintf(io->f, "P6\n%d %d\n255\n", img->width, img->height) < 0 ||
        fwrite(img->rgb, 3, (size_t)img->width * (size_t)img->height, io->f) !=
            (size_t)img->width * (size_t)img->height) {
        say(io->why, io->why_len, "%s: cannot write: %s", io->path, strerror(errno ? errno : EIO));
        return -1;
    }
    return 0;
}

int image_check_output(const char *path, char *why, size_t why_len)
{
    if (!ends_with_ci(path, ".png") && !ends_with_ci(path, ".ppm")) {
        say(why, why_len, "%s: unknown image format (use .png or .ppm)", path);
        return -1;
    }
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        say(why, why_len, "%s: cannot open for writing: %s", path, strerror(EISDIR));
        return -1;
    }
    /* image_write creates path.tmp beside it and renames it: the folder
     * must exist and take new files. */
    const char *slash = strrchr(path, '/');
    char dir[4096];
    if (!slash)
        strcpy(dir, ".");
    else if (slash == path)
        strcpy(dir, "/");
    else if ((size_t)(slash - path) < sizeof dir) {
        memcpy(dir, path, (size_t)(slash - path));
        dir[slash - path] = '\0';
    } else {
        say(why, why_len, "%s: cannot open for writing: %s", path, strerror(ENAMETOOLONG));
        return -1;
    }
    if (access(dir, W_OK | X_OK) != 0) {
        say(why, why_len, "%s: cannot open for writing: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

int image_write(const char *path, const image_t *img, char *why, size_t why_len)
{
    if (!path || !img) {
        say(why, why_len, "image_write: no path or no image");
        return -1;
    }
    int png = ends_with_ci(path, ".png"), ppm = ends_with_ci(path, ".ppm");
    if (!png && !ppm) {
        say(why, why_len, "%s: unknown image format (use .png or .ppm)", path);
        return -1;
    }
    if (img->width <= 0 || img->height <= 0 || !img->rgb) {
        say(why, why_len, "%s: cannot write: the image is empty", path);
        return -1;
    }
    if (img->width > MAX_DIM * 4 || img->height > MAX_DIM * 4) {
        say(why, why_len, "%s: cannot write: %dx%d is too large", path, img->width, img->height);
        return -1;
    }

    size_t n = strlen(path);
    char *tmp = malloc(n + sizeof ".tmp");
    if (!tmp) {
        say(why, why_len, "%s: cannot write: out of memory", path);
        return -1;
    }
    memcpy(tmp, path, n);
    memcpy(tmp + n, ".tmp", sizeof ".tmp");

    errno = 0;
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        say(why, why_len, "%s: cannot open for writing: %s", path, strerror(errno));
        free(tmp);
        return -1;
    }
    png_io_t io = { f, path, why, why_len };
    int rc = png ? write_png(&io, img) : write_ppm(&io, img);
    errno = 0;
    /* fclose flushes, so a full disk may only show up here. */
    if (fclose(f) != 0 && rc == 0) {
        say(why, why_len, "%s: cannot write: %s", path, strerror(errno ? errno : EIO));
        rc = -1;
    }
    if (rc == 0 && rename(tmp, path) != 0) {
        say(why, why_len, "%s: cannot rename %s into place: %s", path, tmp, strerror(errno));
        rc = -1;
    }
    if (rc != 0)
        remove(tmp);
    free(tmp);
    return rc;
}

/* ---- reading ---- */

/* Any PNG libpng reads, as 8-bit RGB: palettes expanded, 16-bit samples
 * cut to their high byte, grey replicated, alpha dropped (not composited). */
static int read_png(png_io_t *io, image_t *img)
{
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, io, png_fail, png_quiet);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!info) {
        png_destroy_read_struct(&png, NULL, NULL);
        say(io->why, io->why_len, "%s: out of memory", io->path);
        return -1;
    }
    /* img->rgb lives in memory the caller owns, so it survives the longjmp. */
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, NULL);
        return -1;
    }
    png_set_read_fn(png, io, png_read_bytes);
    png_set_sig_bytes(png, 8);
    png_set_user_limits(png, MAX_DIM, MAX_DIM);
    png_read_info(png, info);
    int type = png_get_color_type(png, info), depth = png_get_bit_depth(png, info);
    if (type == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (type == PNG_COLOR_TYPE_GRAY && depth < 8)
        png_set_expand_gray_1_2_4_to_8(png);
    if (depth == 16)
        png_set_strip_16(png);
    png_set_strip_alpha(png);
    if (type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA)
        png_set_gray_to_rgb(png);
    int passes = png_set_interlace_handling(png);
    png_read_update_info(png, info);
    png_uint_32 w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 3)
        png_error(png, "unsupported PNG pixel layout");
    img->rgb = malloc((size_t)w * h * 3);
    if (!img->rgb)
        png_error(png, "out of memory");
    img->width = (int)w;
    img->height = (int)h;
    for (int p = 0; p < passes; p++)
        for (png_uint_32 y = 0; y < h; y++)
            png_read_row(png, img->rgb + (size_t)y * w * 3, NULL);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    return 0;
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

static int read_ppm(png_io_t *io, image_t *img)
{
    FILE *f = io->f;
    int c = getc(f);
    if (c == EOF || !(isspace(c) || c == '#')) {
        say(io->why, io->why_len, "%s: bad PPM header", io->path);
        return -1;
    }
    ungetc(c, f);
    long v[3];
    for (int i = 0; i < 3; i++) {
        v[i] = ppm_num(f, &c);
        if (v[i] < 0) {
            say(io->why, io->why_len, "%s: bad PPM header", io->path);
            return -1;
        }
        /* The maxval's single whitespace byte is the last of the header. */
        if (i < 2 && c != EOF)
            ungetc(c, f);
    }
    if (!(c != EOF && isspace(c))) {
        say(io->why, io->why_len, "%s: bad PPM header", io->path);
        return -1;
    }
    if (v[0] == 0 || v[1] == 0 || v[0] > MAX_DIM || v[1] > MAX_DIM) {
        say(io->why, io->why_len, "%s: PPM is %ldx%ld: width and height must be 1..%d", io->path, v[0], v[1],
            MAX_DIM);
        return -1;
    }
    if (v[2] != 255) {
        say(io->why, io->why_len, "%s: PPM maxval %ld is not supported (only 255)", io->path, v[2]);
        return -1;
    }
    size_t n = (size_t)v[0] * (size_t)v[1] * 3;
    img->rgb = malloc(n);
    if (!img->rgb) {
        say(io->why, io->why_len, "%s: out of memory", io->path);
        return -1;
    }
    errno = 0;
    if (fread(img->rgb, 1, n, f) != n) {
        if (ferror(f))
            say(io->why, io->why_len, "%s: read error: %s", io->path, strerror(errno ? errno : EIO));
        else
            say(io->why, io->why_len, "%s: file is truncated (ends inside the PPM pixel data)", io->path);
        return -1;
    }
    img->width = (int)v[0];
    img->height = (int)v[1];
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
        say(why, why_len, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    png_io_t io = { f, path, why, why_len };
    uint8_t m[8];
    int rc = -1;
    errno = 0;
    /* two bytes tell PPM from PNG; PNG's other six are checked after */
    size_t got = fread(m, 1, 2, f);
    if (got < 2 && ferror(f))
        say(why, why_len, "%s: read error: %s", path, strerror(errno ? errno : EIO));
    else if (got < 2)
        say(why, why_len, "%s: %s", path, got ? "file is too short to be an image" : "file is empty");
    else if (m[0] == 'P' && m[1] == '6')
        rc = read_ppm(&io, img);
    else if (m[0] == 'P' && m[1] >= '1' && m[1] <= '7')
        say(why, why_len, "%s: Netpbm format P%c is not supported (only binary PPM, P6)", path, m[1]);
    else if (m[0] == 0x89 && m[1] == 'P') {
        if (fread(m + 2, 1, 6, f) != 6)
            say(why, why_len, "%s: file is truncated (ends inside the PNG signature)", path);
        else if (png_sig_cmp(m, 0, sizeof m) != 0)
            say(why, why_len, "%s: corrupt PNG signature (file damaged by a text-mode transfer?)", path);
        else
            rc = read_png(&io, img);
    } else
        say(why, why_len, "%s: not a PNG or binary PPM file", path);
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

/* The image's channels as doubles, blurred by a Gaussian of `sigma`
 * pixels (separable, cut at 3 sigma, edges clamped); NULL if out of memory. */
static double *blurred(const image_t *img, double sigma)
{
    size_t w = (size_t)img->width, h = (size_t)img->height, n = w * h * 3;
    int r = (int)ceil(3 * sigma);
    double *v = malloc(n * sizeof *v), *t = malloc(n * sizeof *t), *k = malloc((size_t)(2 * r + 1) * sizeof *k);
    if (!v || !t || !k) {
        free(v), free(t), free(k);
        return NULL;
    }
    double sum = 0;
    for (int i = -r; i <= r; i++)
        sum += k[i + r] = exp(-0.5 * i * i / (sigma * sigma));
    for (int i = 0; i <= 2 * r; i++)
        k[i] /= sum;
    for (size_t i = 0; i < n; i++)
        v[i] = img->rgb[i];
    for (int pass = 0; pass < 2; pass++) { /* rows into t, then columns back into v */
        const double *src = pass ? t : v;
        double *dst = pass ? v : t;
        for (size_t y = 0; y < h; y++)
            for (size_t x = 0; x < w; x++)
                for (size_t c = 0; c < 3; c++) {
                    double acc = 0;
                    for (int i = -r; i <= r; i++) {
                        long p = (long)(pass ? y : x) + i, last = (long)(pass ? h : w) - 1;
                        p = p < 0 ? 0 : p > last ? last : p;
                        size_t at = pass ? (size_t)p * w + x : y * w + (size_t)p;
                        acc += k[i + r] * src[at * 3 + c];
                    }
                    dst[(y * w + x) * 3 + c] = acc;
                }
    }
    free(t), free(k);
    return v;
}

int image_compare(const image_t *a, const image_t *b, double blur, image_diff_t *d, char *why, size_t why_len)
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
    if (blur > 0 && pixels) { /* the same measures on the blurred channels */
        double *u = blurred(a, blur), *v = blurred(b, blur), sq = 0, worst_all = 0;
        if (!u || !v) {
            free(u), free(v);
            say(why, why_len, "image_compare: out of memory");
            return -1;
        }
        size_t over2 = 0, over8 = 0;
        for (size_t i = 0; i < pixels; i++) {
            double worst = 0;
            for (size_t c = 0; c < 3; c++) {
                double e = fabs(u[i * 3 + c] - v[i * 3 + c]);
                sq += e * e;
                worst = e > worst ? e : worst;
            }
            over2 += worst > 2;
            over8 += worst > 8;
            worst_all = worst > worst_all ? worst : worst_all;
        }
        free(u), free(v);
        d->max_err = (int)ceil(worst_all - 1e-9);
        d->mse = sq / ((double)pixels * 3);
        d->psnr_db = d->mse > 0 ? 10 * log10(255.0 * 255.0 / d->mse) : INFINITY;
        d->share_over2 = (double)over2 / (double)pixels;
        d->share_over8 = (double)over8 / (double)pixels;
        return 0;
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
