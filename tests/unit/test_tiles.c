/*
 * test_tiles.c - checker tiles stay in place at any distance. A checker
 * along one axis, of a size not exact in binary (0.3, 0.2, 0.1, 1/3, 7,
 * 0.0013) or exact (0.5), is sampled at points from the origin to the far
 * cube on each axis and both sides of it, in scenes of two scales. The
 * expected tile is the exact model's, floor(P / size) for the point P as
 * the backend holds it (rounded to its position grid), computed in long
 * double from the size's decimal value; every point sits at least
 * `margin` of a tile from an edge. The fixed build must get every tile
 * right at 0.2% of a tile from an edge (it is within 2^-12 of a tile by
 * construction: its 1 / size is the correctly rounded value, and the
 * product and floor are exact); float within 2% (its P itself carries
 * 2^-24 relative); double within 0.2%.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "backend.h"
#include "testlib.h"

static const char *const sizes[] = { "0.3", "0.2", "0.1", "0.3333333333333333", "7", "0.0013", "0.5" };
static const char axis_name[3] = { 'x', 'y', 'z' };
/* the scene's scale: a unit sphere seen from 5 units (k = 3, far cube 64)
 * or a sphere of radius 100 from 500 (k = -3, far cube 4096) */
static const struct { const char *radius, *from; } scales[] = { { "1", "5" }, { "100", "500" } };

static bool load(const rt_backend_t *b, const char *size, int axis, int scale, rt_error_t *err)
{
    char text[512];
    snprintf(text, sizeof text,
             "v\nfrom 0 -%s 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 8 8\n"
             "f 1 1 1 1 0 10 0 1\nchecker %s  0 0 0  1 1 1  %c\ns 0 0 0 %s\n",
             scales[scale].from, size, axis_name[axis], scales[scale].radius);
    return b->load(text, strlen(text), err);
}

/* p as the backend holds it: fixed rounds p 2^k to 2^-20, float to 24 bits */
static long double held(const char *name, double p, int k)
{
    if (!strcmp(name, "fixed")) {
        long double s = ldexpl(1, 20 + k);
        return roundl((long double)p * s) / s;
    }
    if (!strcmp(name, "float"))
        return (long double)(float)(p * ldexp(1, k)) / ldexpl(1, k);
    return p;
}

static void check_backend(const rt_backend_t *b, const char *name, double margin)
{
    for (size_t si = 0; si < sizeof sizes / sizeof sizes[0]; si++) {
        long double size = strtold(sizes[si], 0);
        for (int scale = 0; scale < 2; scale++) {
            rt_error_t err;
            if (!load(b, sizes[si], 0, scale, &err)) {
                /* only a size below 2^-10 in the scene's scale may be refused */
                CHECK(strstr(err.msg, "at least 2^-10") != 0, "%s: checker %s at scale %d refused: %s", name,
                      sizes[si], scale, err.msg);
                continue;
            }
            int k = b->scale_log2();
            double far = ldexp(1, 9 - k) * 0.999;
            long cells = (long)(far / size);
            int bad = 0, n = 0;
            double worst_at = 0;
            for (int axis = 0; axis < 3; axis++) {
                if (!load(b, sizes[si], axis, scale, &err))
                    continue;
                for (int i = 0; i < 600; i++) {
                    /* cells spread from 0 to the far cube, log-uniformly, both signs */
                    double t = (double)i / 599;
                    long cell = (long)floor(pow((double)cells, t)) - (i % 2 ? (long)floor(pow((double)cells, t)) * 2 + 1 : 0);
                    double frac = tl_uniform(margin, 1 - margin);
                    double p[3] = { tl_uniform(-far, far), tl_uniform(-far, far), tl_uniform(-far, far) };
                    p[axis] = (double)(((long double)cell + frac) * size);
                    if (fabs(p[axis]) >= far)
                        continue;
                    long double q = held(name, p[axis], k) / size;
                    long double fl = floorl(q);
                    if (q - fl < margin / 2 || fl + 1 - q < margin / 2)
                        continue; /* the backend's own rounding of P took it near an edge */
                    double rgb[3];
                    if (!b->texture_at(0, p, rgb))
                        continue;
                    bool odd = ((long long)fl & 1) != 0;
                    n++;
                    if ((rgb[0] > 0.5) != odd) {
                        bad++;
                        worst_at = p[axis];
                    }
                }
            }
            CHECK(n > 1000 && bad == 0, "%s: checker %s, scale 2^%d (far cube %g): %d of %d points in the wrong tile (last at %.6g)",
                  name, sizes[si], k, ldexp(1, 9 - k), bad, n, worst_at);
        }
    }
}

int main(void)
{
    printf("far tiles: the tile of points from the origin to the far cube\n");
    check_backend(&rt_backend_fixed, "fixed", 0.002);
    check_backend(&rt_backend_float, "float", 0.02);
    check_backend(&rt_backend_double, "double", 0.002);
    return tl_summary("test_tiles");
}
