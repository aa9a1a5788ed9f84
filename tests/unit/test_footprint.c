/*
 * test_footprint.c - a filtered checker lookup whose footprint lies
 * inside one cell takes the point sample without filtering
 * (footprint_in_cell, src/tracer/texture.h): it must say so only where
 * the whole filter (texture_colour_at, texture.c) gives that very colour.
 * Random checkers (sizes from 1/64 to 64, one to three axes), points on
 * both sides of the origin, unit directions and normals (grazing ones
 * included) and cone widths from far below a cell to far above it, in
 * the fixed build. Also how often it takes the shortcut, so a test that
 * never takes it fails.
 */
#include <math.h>

#include "texture.h"
#include "testlib.h"

static fx_t q(double v) { return (fx_t)llround(v * FX_ONE); }
static double to_double(fx_t v) { return (double)v / FX_ONE; }

static vec3_t unit(double x, double y, double z)
{
    double l = sqrt(x * x + y * y + z * z);
    return v3_unit(v3(q(x / l), q(y / l), q(z / l)));
}

static bool same(colour_t a, colour_t b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

int main(void)
{
    printf("test_footprint: a footprint inside its cell is the point sample\n");
    long n = 0, inside = 0, wrong = 0, filtered_inside = 0;
    for (int i = 0; i < 400000; i++) {
        texture_t tx = { 0 };
        tx.kind = TEXTURE_CHECKER;
        tx.a = v3(FX_ONE, FX_ONE, FX_ONE);
        tx.b = v3(q(0.25), 0, q(0.5));
        tx.axes = (uint8_t)(1 + tl_rand() % 7);
        tx.inv_size = q(pow(2.0, tl_uniform(-6, 6)));
        vec3_t p = v3(q(tl_uniform(-200, 200)), q(tl_uniform(-200, 200)), q(tl_uniform(-200, 200)));
        footprint_t fp;
        fp.dir = unit(tl_uniform(-1, 1), tl_uniform(-1, 1), tl_uniform(-1, 1));
        vec3_t n0 = unit(tl_uniform(-1, 1), tl_uniform(-1, 1), tl_uniform(-1, 1));
        /* the normal faces the ray; one in eight nearly grazing */
        if (tl_rand() % 8 == 0)
            n0 = unit(to_double(fp.dir.y), -to_double(fp.dir.x) + 1e-3, to_double(fp.dir.z) * 1e-3);
        fp.n = v3_dot(n0, fp.dir) < 0 ? n0 : v3_neg(n0);
        fp.width = q(pow(2.0, tl_uniform(-14, 4)) * (tl_rand() % 2 ? 1 : -1));
        if (fp.width == 0)
            continue;
        n++;
        colour_t full = texture_colour_at(&tx, p, &fp), point = checker_at_point(&tx, p);
        if (footprint_in_cell(&tx, p, &fp)) {
            inside++;
            if (!same(full, point) || !same(texture_colour(&tx, p, &fp), full)) {
                if (wrong++ < 5)
                    printf("  inside, but the filter differs: width %g, inv_size %g\n", to_double(fp.width),
                           to_double(tx.inv_size));
            }
        } else if (same(full, point)) {
            filtered_inside++; /* the filter's own verdict: inside (or a mean that rounds to it) */
        }
    }
    printf("  %ld lookups: %ld taken as the point sample (%ld more the filter finds inside)\n", n, inside,
           filtered_inside);
    CHECK(wrong == 0, "every shortcut gives the filter's colour (%ld wrong)", wrong);
    CHECK(inside > n / 4, "the shortcut is taken (%ld of %ld lookups)", inside, n);
    CHECK(inside > 4 * filtered_inside, "it misses few of the footprints the filter finds inside (%ld)",
             filtered_inside);
    return tl_summary("test_footprint");
}
