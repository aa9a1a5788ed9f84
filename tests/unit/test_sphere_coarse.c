/*
 * test_sphere_coarse.c - the fixed build's coarse sphere test
 * (sphere_coarse_miss, src/geometry/sphere.h), which cores without a long
 * multiply run before the exact one: it may say "missed" only where the
 * exact test misses, for rays from anywhere in the range the renderer's
 * rays keep to. Also how many of the exact test's misses it catches, so a
 * test that never rejects cannot pass.
 */
#include <math.h>

#include "geometry/sphere.h"
#include "testlib.h"

_Static_assert(!SPHERE_COARSE, "sphere_hit_inline must be the exact test alone here (no FX_MUL64_PARTIAL)");

static fx_t q(double v) { return (fx_t)llround(v * FX_ONE); }

int main(void)
{
    printf("test_sphere_coarse: the coarse sphere test against the exact one\n");
    long cases = 0, wrong = 0, misses = 0, caught = 0;
    for (long i = 0; i < 4000000; i++) {
        /* spheres up to the coarse test's radius limit and past it; centres
         * and origins across the scene (|l| < 2^10), directions unit */
        double scale = pow(2.0, tl_uniform(-6, 3));
        double rad = pow(2.0, tl_uniform(-7, 6.5));
        sphere_t s;
        if (sphere_init(&s, v3(q(tl_uniform(-1, 1) * 16), q(tl_uniform(-1, 1) * 16), q(tl_uniform(-1, 1) * 16)),
                        q(rad), 0))
            continue;
        ray_t r;
        double o[3], d[3], n = 0;
        for (int k = 0; k < 3; k++) {
            o[k] = tl_uniform(-1, 1) * 16 * scale * 8;
            d[k] = tl_uniform(-1, 1);
            n += d[k] * d[k];
        }
        if (n < 1e-6)
            continue;
        /* aim near the sphere half the time: the interesting cases */
        if (i & 1) {
            double c[3] = { (double)s.centre.x / FX_ONE, (double)s.centre.y / FX_ONE, (double)s.centre.z / FX_ONE };
            n = 0;
            for (int k = 0; k < 3; k++) {
                d[k] = c[k] + tl_uniform(-1.2, 1.2) * rad - o[k];
                n += d[k] * d[k];
            }
            if (n < 1e-6)
                continue;
        }
        fx_t u[3];
        fx_unit3(q(d[0] / sqrt(n) * 1024), q(d[1] / sqrt(n) * 1024), q(d[2] / sqrt(n) * 1024), u);
        r.origin = v3(q(o[0]), q(o[1]), q(o[2]));
        r.dir = v3(u[0], u[1], u[2]);
        r.from = PRIM_NONE;
        r.from_far = false;
        r.leaf = RT_NO_LEAF;
        fx_t tmin = (i % 3) ? 1 : q(tl_uniform(0, 8));
        fx_t tmax = (i % 5) ? FX_MAX : q(tl_uniform(0, 64));
        bool coarse = sphere_coarse_miss(&s, &r, tmin, tmax);
        for (int far = 0; far < 2; far++) {
            fx_t t = tmax;
            bool hit = sphere_hit_inline(&s, &r, tmin, &t, far);
            cases++;
            wrong += coarse && hit;
            misses += !hit;
            caught += coarse && !hit;
        }
    }
    CHECK(wrong == 0, "coarse test: %ld of %ld cases said missed where the exact test hits", wrong, cases);
    CHECK(caught > misses / 2, "coarse test: catches %ld of the exact test's %ld misses (%.1f%%; more than half)",
          caught, misses, 100.0 * caught / misses);
    return tl_summary("test_sphere_coarse");
}
