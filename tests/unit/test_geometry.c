/*
 * test_geometry.c - each NFF primitive's intersection and normal in the
 * fixed build against the double build.
 *
 * For every primitive, random rays (from outside and from inside) go to
 * both builds. Where both hit, t and the normal must agree within the
 * tolerances below, which are relative to t because a Q16.16 unit
 * direction is only good to ~1e-5 rad: over a distance t it moves the hit
 * by ~1e-5 t, more at grazing angles, so rays with |D.N| < 0.25 are left
 * out of the accuracy figures (the image tests cover them). A hit/miss or
 * far-apart-t disagreement is excused only where the double result itself
 * jumps when the ray is nudged by 1e-3 of the object's size (a silhouette
 * or a rim); those must stay under MAX_MISMATCH of the rays.
 *
 * It also holds the float backend's own power function (src/numeric/real_float.c,
 * the Phong highlight's x^s) to the accuracy stated there, against double
 * pow over a sweep of x and of exponents 1 ... 524287.
 */
#include <math.h>
#include <string.h>

#include "backend.h"
#include "probe_jump.h"
#include "testlib.h"

#define N_RAYS 20000
#define TOL_T_ABS 2e-4   /* |t error| <= TOL_T_ABS + TOL_T_REL * t */
#define TOL_T_REL 5e-4
#define TOL_N 5e-3       /* per normal component */
#define MIN_COS 0.25
#define MAX_MISMATCH 0.002 /* share of rays whose hit/miss differs */

/* `at` (geometry, for the reader's range) lies 8 out, so the scene is read
 * at scale 1 and the random rays, which start up to 8 extents away, stay
 * inside the range that render rays keep to (ulps below are 2^-20). */
static const char *const header =
    "v\nfrom 0 -8 0\nat 0 8 0\nup 0 0 1\nangle 45\nhither 1\nresolution 64 64\n"
    "l 4 -6 5\nf 1 1 1 0.8 0.2 10 0 1\n";

typedef struct {
    const char *name;
    const char *body;
    double extent;   /* rays aim inside a cube of this half-size */
    double offset_ulps; /* origin offset of rays leaving it (tolerance.h); 0: none */
} test_shape_t;

static const test_shape_t shapes[] = {
    { "sphere", "s 0.3 -0.2 0.1 1.5\n", 1.6, 0 },
    { "small sphere", "s 0.01 0.02 0 0.05\n", 0.06, 0 },
    { "cylinder", "c 0 0 -1 0.5 0.2 0.3 1.2 0.5\n", 1.3, 0 },
    { "cone", "c 0 0 -1 1.0 0 0 1 0.2\n", 1.2, 0 },
    { "cone to a point", "c -0.5 0 0 0.8 1 0.5 0.5 0\n", 1.2, 0 },
    { "triangle", "p 3\n-1 0 -1\n1 0.2 -1\n0 -0.3 1.2\n", 1.2, 0 },
    { "concave polygon",
      "p 8\n0 0 1.5\n0.4 0 0.4\n1.5 0 0\n0.4 0 -0.4\n0 0 -1.5\n-0.4 0 -0.4\n-1.5 0 0\n-0.4 0 0.4\n", 1.5, 0 },
    { "patch triangle", "pp 3\n-1 0 -1 -0.3 -1 0\n1 0 -1 0.3 -1 0\n0 0.5 1 0 -1 0.4\n", 1.2, 0 },
    { "patch fan",
      "pp 4\n-1 0 -1 -0.2 -1 -0.2\n1 0 -1 0.2 -1 -0.2\n1 0 1 0.2 -1 0.2\n-1 0 1 -0.2 -1 0.2\n", 1.2, 0 },
    { "box", "transform\nrotate 1 2 3 30\nbox -1 -0.5 -0.7 1 0.5 0.7\nend\n", 1.3, 64 },
    { "torus", "transform\nrotate 1 0 0 60\ntorus 1 0.35\nend\n", 1.4, 512 },
    { "ellipsoid", "transform\nrotate 0 1 1 40\nellipsoid 1.2 0.6 0.9\nend\n", 1.3, 64 },
    { "paraboloid", "transform\ntranslate 0 0 -0.8\nparaboloid 0.8 0.8 1.5\nend\n", 1.3, 64 },
    { "hyperboloid", "transform\nrotate 1 1 0 25\nhyperboloid 0.5 0.5 0.7 1\nend\n", 1.3, 64 },
    { "hyperboloid2", "hyperboloid2 0.4 0.4 0.4 1.2\n", 1.3, 64 },
    { "quadcone", "quadcone 0.6 0.6 1\n", 1.1, 64 },
    { "quadcylinder", "transform\nscale 1 0.5 1\nquadcylinder 0.7 0.7 1\nend\n", 1.1, 64 },
    { "general quadric", "quadric 1 2 1 0.5 0 0 0 0 0 -1 -1 -1 -1 1 1 1\n", 1.1, 64 },
    { "CSG difference", "difference\nbox -0.8 -0.8 -0.8 0.8 0.8 0.8\ns 0.8 -0.8 0.8 0.7\nend\n", 1.2, 64 },
    { "CSG intersection lens", "intersection\ns 0 -0.6 0 1\ns 0 0.6 0 1\nend\n", 1.0, 64 },
    { "CSG union", "union\ntransform\nrotate 1 0 0 90\ntorus 0.8 0.25\nend\nbox -0.3 -0.3 -1 0.3 0.3 1\nend\n", 1.2, 512 },
};

static bool load_both(const test_shape_t *s)
{
    char text[2048];
    rt_error_t err;
    snprintf(text, sizeof text, "%s%s", header, s->body);
    if (!rt_backend_fixed.load(text, strlen(text), &err) ||
        !rt_backend_double.load(text, strlen(text), &err)) {
        printf("  cannot load %s: line %u: %s\n", s->name, (unsigned)err.line, err.msg);
        return false;
    }
    return true;
}

static void random_ray(double extent, bool inside, double o[3], double dir[3])
{
    double target[3];
    for (int k = 0; k < 3; k++)
        target[k] = tl_uniform(-extent, extent);
    if (inside) {
        for (int k = 0; k < 3; k++) {
            o[k] = tl_uniform(-0.3, 0.3) * extent;
            dir[k] = tl_uniform(-1, 1);
        }
    } else {
        /* from a random point 4..8 extents away, towards the target */
        double u[3], l = 0;
        for (int k = 0; k < 3; k++) {
            u[k] = tl_uniform(-1, 1);
            l += u[k] * u[k];
        }
        double r = extent * tl_uniform(4, 8) / sqrt(l);
        for (int k = 0; k < 3; k++) {
            o[k] = u[k] * r;
            dir[k] = target[k] - o[k];
        }
    }
    double l = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int k = 0; k < 3; k++)
        dir[k] /= l;
}

/* How far the fixed build's hit point lies from the exact surface: the
 * double build measures it along its normal, from 1e-3 outside. In units
 * of the fixed last place (the test scenes are read at scale 1). -1 when
 * another surface is in the way. */
static double surface_distance_ulps(const probe_hit_t *hf, const probe_hit_t *hd)
{
    const double step = 1e-3;
    double q[3], back[3];
    for (int k = 0; k < 3; k++) {
        q[k] = hf->point[k] + step * hd->normal[k];
        back[k] = -hd->normal[k];
    }
    probe_hit_t h;
    if (!rt_backend_double.probe(q, back, false, &h) || fabs(h.t - step) > step / 2)
        return -1;
    return fabs(h.t - step) * 1048576.0;
}

static void test_shape(const test_shape_t *s)
{
    if (!load_both(s)) {
        CHECK(0, "%s: scene loads in both builds", s->name);
        return;
    }
    double worst_t = 0, worst_n = 0, worst_dist = 0;
    int hits = 0, mismatch = 0, unexcused = 0;
    const double nudge = 1e-3 * s->extent;
    for (int i = 0; i < N_RAYS; i++) {
        double o[3], dir[3];
        random_ray(s->extent, i % 4 == 3, o, dir);
        probe_hit_t hf, hd;
        bool f = rt_backend_fixed.probe(o, dir, false, &hf);
        bool dd = rt_backend_double.probe(o, dir, false, &hd);
        bool far_apart = f && fabs(hf.t - hd.t) > 0.05 * s->extent;
        for (int k = 0; f && dd && k < 3; k++)
            far_apart |= fabs(hf.normal[k] - hd.normal[k]) > 0.1;
        if (f != dd || far_apart) {
            mismatch++;
            unexcused += !probe_double_jumps(o, dir, nudge, 0.05 * s->extent);
            continue;
        }
        if (!f)
            continue;
        hits++;
        double dist = surface_distance_ulps(&hf, &hd);
        worst_dist = dist > worst_dist ? dist : worst_dist;
        double cosine = fabs(hd.normal[0] * dir[0] + hd.normal[1] * dir[1] + hd.normal[2] * dir[2]);
        if (cosine < MIN_COS)
            continue;
        double et = fabs(hf.t - hd.t) / (TOL_T_ABS + TOL_T_REL * hd.t);
        worst_t = et > worst_t ? et : worst_t;
        for (int k = 0; k < 3; k++) {
            double en = fabs(hf.normal[k] - hd.normal[k]);
            worst_n = en > worst_n ? en : worst_n;
        }
    }
    CHECK(hits > N_RAYS / 10, "%s: %d of %d rays hit (the test exercises hits)", s->name, hits, N_RAYS);
    CHECK(worst_t <= 1, "%s: max |t error| %.2f of the tolerance %.0e + %.0e t", s->name, worst_t,
          TOL_T_ABS, TOL_T_REL);
    CHECK(worst_n <= TOL_N, "%s: max normal component error %.2e (tolerance %.0e)", s->name, worst_n, TOL_N);
    if (s->offset_ulps > 0)
        CHECK(worst_dist <= s->offset_ulps / 2,
              "%s: hit points within %.1f ulps of the exact surface (offset bound: half of %.0f)", s->name,
              worst_dist, s->offset_ulps);
    else
        printf("        %s: hit points within %.1f ulps of the exact surface (rays leaving it skip it)\n",
               s->name, worst_dist);
    /* Tori (offset 512): a ray grazing the tube may find or miss a tangent
     * touch differently in the two builds (tolerance.h): at most 0.1% of
     * them. */
    int unexcused_max = s->offset_ulps >= 512 ? N_RAYS / 1000 : 0;
    CHECK((double)mismatch / N_RAYS <= MAX_MISMATCH && unexcused <= unexcused_max,
          "%s: results differ for %d rays (%.3f%%, limit %.1f%%), %d of them away from a silhouette or rim "
          "(limit %d)",
          s->name, mismatch, 100.0 * mismatch / N_RAYS, 100 * MAX_MISMATCH, unexcused, unexcused_max);
}

static void test_camera(void)
{
    /* eye ray directions across a 512x512 grid, fixed against double */
    const test_shape_t *s = &shapes[0];
    if (!load_both(s))
        return;
    double worst = 0;
    for (int j = 0; j < 512; j += 7)
        for (int i = 0; i < 512; i += 5) {
            double a[3], b[3];
            rt_backend_fixed.eye_dir(512, 512, i, j, a);
            rt_backend_double.eye_dir(512, 512, i, j, b);
            for (int k = 0; k < 3; k++)
                worst = fabs(a[k] - b[k]) > worst ? fabs(a[k] - b[k]) : worst;
        }
    /* one pixel at 512 px and 45 degrees is 1.6e-3 */
    CHECK(worst < 3e-5, "camera: max eye-direction component error %.2e at 512x512 (bound 3e-5, 2%% of a pixel)",
          worst);
}

/* Relative error bound of the float backend's x^s for results in the
 * normal range (src/numeric/real_float.c): 0.54 units in the last place. */
#define POW_FLOAT_REL 6.2e-8

static float float_of_bits(uint32_t u)
{
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static void test_pow_float(void)
{
    static const double exps[] = { 1, 1.5, 2, 3, 7.25, 10, 20, 50, 100, 333, 1000, 1e4, 1e5, 524287 };
    const rt_backend_t *be = &rt_backend_float;
    double worst = 0, worst_x = 0, worst_s = 0, worst_sub = 0, worst_sub_int = 0;
    long n = 0, overflow_wrong = 0;
    for (unsigned e = 0; e < sizeof exps / sizeof exps[0]; e++) {
        double s = exps[e];
        /* x from 2^-24 by an odd stride of floats, then every float in
         * [1 - 2^-9, 1 + 2^-8), where large exponents are sensitive */
        for (uint32_t u = 0x33800000u; u < 0x3F800000u + 0x8000u; u += u >= 0x3F7F8000u ? 1 : 1021) {
            double x = float_of_bits(u), want = pow(x, s), got = be->pow_unit(x, s);
            n++;
            if (want > 0x1.fffffep127) {
                overflow_wrong += got != INFINITY;
            } else if (want >= 0x1p-126) {
                /* integers 2..64 go by binary powers: within s 2^-24 */
                double rel = fabs(got - want) / want;
                if (s >= 2 && s <= 64 && s == floor(s))
                    rel *= POW_FLOAT_REL / (s * 0x1p-24);
                if (rel > worst)
                    worst = rel, worst_x = x, worst_s = s;
            } else if (s >= 2 && s <= 64 && s == floor(s)) {
                /* a shading weight below 2^-100 (real.h's r_pow_unit) */
                if (fabs(got - want) > worst_sub_int)
                    worst_sub_int = fabs(got - want);
            } else if (fabs(got - want) > worst_sub) {
                worst_sub = fabs(got - want);
            }
        }
    }
    CHECK(worst <= POW_FLOAT_REL, "float x^s: max relative error %.3g at x = %a, s = %g over %ld (x, s) (bound %.2g; "
          "for integers s = 2..64 scaled to s 2^-24)",
          worst, worst_x, worst_s, n, POW_FLOAT_REL);
    CHECK(worst_sub <= 0x1p-149, "float x^s: subnormal results within %.2g of x^s (bound 2^-149 = 1.4e-45)",
          worst_sub);
    CHECK(worst_sub_int <= 0x1p-100,
          "float x^s, s an integer 2..64: results below 2^-126 within %.2g of x^s (bound 2^-100 = 7.9e-31: "
          "binary powers whatever the factors)",
          worst_sub_int);
    CHECK(overflow_wrong == 0, "float x^s: %ld results beyond the float range not +inf", overflow_wrong);

    /* the exact cases */
    long exact_wrong = 0;
    for (uint32_t u = 0x33800000u; u < 0x3F800000u; u += 4099) {
        double x = float_of_bits(u);
        exact_wrong += be->pow_unit(x, 1) != x;
        exact_wrong += be->pow_unit(x, 0) != 1;
    }
    for (unsigned e = 0; e < sizeof exps / sizeof exps[0]; e++) {
        exact_wrong += be->pow_unit(1, exps[e]) != 1;
        exact_wrong += be->pow_unit(0, exps[e]) != 0;
        exact_wrong += be->pow_unit(-0.5, exps[e]) != 0;
    }
    CHECK(exact_wrong == 0, "float x^s: x^1 = x, x^0 = 1, 1^s = 1, and 0 for x <= 0 (%ld wrong)", exact_wrong);

    /* s = 2^k, k = 2..6: k squarings, within 2^k 2^-24 relative (the
     * binary powers of every integer s <= 64, where they are fewest) */
    double worst_k = 0;
    int bad_k = 0;
    for (int k = 2; k <= 6; k++) {
        double s = (double)(1 << k), w = 0;
        for (uint32_t u = 0x33800000u; u < 0x3F800000u; u += 1021) {
            double x = float_of_bits(u), want = pow(x, s), got = be->pow_unit(x, s);
            if (want >= 0x1p-126 && fabs(got - want) / want > w)
                w = fabs(got - want) / want;
        }
        bad_k += w > s * 0x1p-24;
        worst_k = w / (s * 0x1p-24) > worst_k ? w / (s * 0x1p-24) : worst_k;
    }
    CHECK(bad_k == 0, "float x^(2^k), k = 2..6, by squarings: worst relative error %.2f of 2^k 2^-24", worst_k);
}

int main(void)
{
    printf("test_geometry: fixed vs double, %d random rays per primitive\n", N_RAYS);
    for (unsigned i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        test_shape(&shapes[i]);
    test_camera();
    test_pow_float();
    return tl_summary("test_geometry");
}
