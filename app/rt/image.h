/* image.h - 8-bit RGB images on disk (PNG, binary PPM) and their comparison,
 * for the hosted CLI. Needs libpng and libm (-lpng -lm). Every reason put
 * in why reads "path: what is wrong" (one line, no newline). */
#ifndef IMAGE_H
#define IMAGE_H

#include <stdint.h>
#include <stddef.h>

typedef struct {
    int width, height;
    uint8_t *rgb; /* width*height*3 bytes, malloc'd, row-major top to bottom */
} image_t;

/* Writes PNG (8-bit RGB) when path ends in ".png", binary PPM (P6, maxval
 * 255) when it ends in ".ppm" (both case-insensitive). The data goes to
 * path + ".tmp" first and is renamed into place only when complete, so a
 * failure never leaves a partial file under the real name. Returns 0, or -1
 * with a one-line reason (no newline) in why[why_len]. */
int image_write(const char *path, const image_t *img, char *why, size_t why_len);

/* What image_write can know before there is an image: the extension names
 * a format, and the folder exists and takes new files. Returns 0, or -1
 * with a reason in why. (The write itself may still fail, e.g. disk full.) */
int image_check_output(const char *path, char *why, size_t why_len);

/* Reads PNG (any kind libpng reads, as 8-bit RGB: alpha dropped, 16-bit
 * samples cut to 8) or binary PPM (P6, maxval 255), chosen by the file's
 * magic bytes, not its name. Width and height must be 1..16384. Returns 0 and fills *img (free
 * with image_free), or -1 with a reason in why and *img empty. */
int image_read(const char *path, image_t *img, char *why, size_t why_len);

/* Frees img->rgb and empties *img; safe on an already empty image. */
void image_free(image_t *img);

typedef struct {
    double psnr_db;     /* INFINITY when identical */
    int max_err;        /* max abs channel difference 0..255 */
    double share_over2; /* fraction of pixels (0..1) with any channel differing by more than 2 */
    double share_over8; /* same, more than 8 */
    double mse;         /* mean squared channel difference */
} image_diff_t;

/* Returns 0, or -1 if the sizes differ (reason in why).
 * PSNR = 10*log10(255^2/MSE) over all channels of all pixels. blur > 0:
 * both images are first blurred by a Gaussian of that many pixels (the
 * way an eye sees a small panel's pixels: dithering's measure), the
 * differences taken unrounded (max_err rounded up). */
int image_compare(const image_t *a, const image_t *b, double blur, image_diff_t *d, char *why, size_t why_len);

#endif
