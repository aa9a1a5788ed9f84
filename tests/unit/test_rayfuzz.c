/*
 * test_rayfuzz.c - random rays against random primitives, fixed against
 * double (part of the stress suite).
 *
 *   test_rayfuzz [RAYS]      (default 1000000)
 *
 * Each random scene holds one primitive (sphere, cylinder, cone, triangle,
 * quad, or smooth patch) of random size (0.01..4 units), place and
 * orientation; rays come from outside (3..8 sizes away, aimed at the
 * object's box) and, one in four, from inside. The view's `at` lies 8
 * sizes out, so the reader's range (which `at` belongs to, like all
 * geometry) holds every ray origin, as it holds render rays'. Asserted:
 *  - hit/miss agrees except where the double result itself flips when the
 *    ray is nudged by SILHOUETTE of the object's size (silhouettes, rims);
 *  - for hits at |D.N| >= 0.25: |t error| <= T_ABS extent + T_REL t, where
 *    extent is 6 sizes plus the object's distance from the origin, and
 *    each normal component within N_TOL; rays that start within 1e-3 of
 *    the object's size from its surface are left out (secondary rays skip
 *    their own surface);
 *  - no fixed-point saturation;
 *  - rays aimed exactly at the shared edges and corners of closed meshes
 *    all hit (no cracks).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "backend.h"
#include "probe_jump.h"
#include "testlib.h"

#define RAYS_PER_SCENE 10000
#define SILHOUETTE 1e-4
#define T_ABS 2e-5     /* times the object's size */
#define T_REL 2e-5
#define N_TOL 1e-3
#define MIN_COS 0.25

static void unit(double d[3])
{
    double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; k++)
        d[k] /= l;
}

static void rnd_dir(double d[3])
{
    do {
        for (int k = 0; k < 3; k++)
            d[k] = tl_uniform(-1, 1);
    } while (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 0.01);
    unit(d);
}

/* One random primitive as NFF; returns its size and fills its box centre. */
static double random_scene(char *buf, size_t cap, int kind, double c[3])
{
    double size = pow(10, tl_uniform(-2, 0.6)); /* 0.01 .. 4 */
    for (int k = 0; k < 3; k++)
        c[k] = tl_uniform(-2, 2);
    int n = snprintf(buf, cap,
                     "v\nfrom %.9g %.9g %.9g\nat %.9g %.9g %.9g\nup 0 0 1\nangle 45\nhither 1\n"
                     "resolution 8 8\nl 1 2 3\nf 1 1 1 0.8 0.2 10 0 1\n",
                     c[0], c[1] - 6 * size, c[2], c[0], c[1] + 8 * size, c[2]);
    double a[3], b[3], e[3];
    rnd_dir(a);
    rnd_dir(e);
    switch (kind) {
    case 0:
        snprintf(buf + n, cap - n, "s %.9g %.9g %.9g %.9g\n", c[0], c[1], c[2], size / 2);
        break;
    case 1:
    case 2: { /* cylinder or cone along a random axis */
        double r0 = size * tl_uniform(0.1, 0.5), r1 = kind == 1 ? r0 : size * tl_uniform(0, 0.5);
        snprintf(buf + n, cap - n, "c %.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", c[0] - a[0] * size / 2,
                 c[1] - a[1] * size / 2, c[2] - a[2] * size / 2, r0, c[0] + a[0] * size / 2,
                 c[1] + a[1] * size / 2, c[2] + a[2] * size / 2, r1);
        break;
    }
    case 3:
    case 4: { /* triangle or planar quad spanned by a and b = a x e */
        b[0] = a[1] * e[2] - a[2] * e[1], b[1] = a[2] * e[0] - a[0] * e[2], b[2] = a[0] * e[1] - a[1] * e[0];
        unit(b);
        double h = size / 2;
        if (kind == 3)
            snprintf(buf + n, cap - n, "p 3\n%.9g %.9g %.9g\n%.9g %.9g %.9g\n%.9g %.9g %.9g\n",
                     c[0] - h * a[0], c[1] - h * a[1], c[2] - h * a[2], c[0] + h * a[0], c[1] + h * a[1],
                     c[2] + h * a[2], c[0] + h * b[0], c[1] + h * b[1], c[2] + h * b[2]);
        else
            snprintf(buf + n, cap - n, "p 4\n%.9g %.9g %.9g\n%.9g %.9g %.9g\n%.9g %.9g %.9g\n%.9g %.9g %.9g\n",
                     c[0] - h * a[0] - h * b[0], c[1] - h * a[1] - h * b[1], c[2] - h * a[2] - h * b[2],
                     c[0] + h * a[0] - h * b[0], c[1] + h * a[1] - h * b[1], c[2] + h * a[2] - h * b[2],
                     c[0] + h * a[0] + h * b[0], c[1] + h * a[1] + h * b[1], c[2] + h * a[2] + h * b[2],
                     c[0] - h * a[0] + h * b[0], c[1] - h * a[1] + h * b[1], c[2] - h * a[2] + h * b[2]);
        break;
    }
    default: { /* smooth patch: a triangle with tilted vertex normals */
        b[0] = a[1] * e[2] - a[2] * e[1], b[1] = a[2] * e[0] - a[0] * e[2], b[2] = a[0] * e[1] - a[1] * e[0];
        unit(b);
        double nrm[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
        double h = size / 2;
        n += snprintf(buf + n, cap - n, "pp 3\n");
        for (int v = 0; v < 3; v++) {
            double p[3], m[3], t[3];
            rnd_dir(t);
            for (int k = 0; k < 3; k++) {
                p[k] = c[k] + (v == 0 ? -h * a[k] : v == 1 ? h * a[k] : h * b[k]);
                m[k] = nrm[k] + 0.4 * t[k];
            }
            n += snprintf(buf + n, cap - n, "%.9g %.9g %.9g %.9g %.9g %.9g\n", p[0], p[1], p[2], m[0], m[1], m[2]);
        }
        break;
    }
    }
    return size;
}

/* Rays aimed exactly at the shared edges and corners of closed meshes
 * (randomly rotated cubes of 12 triangles and octahedra of 8) from outside
 * must all hit: none may slip between two faces. */
static void edge_rays(long n)
{
    static const int cube_faces[12][3] = {
        { 0, 1, 3 }, { 0, 3, 2 }, { 4, 6, 7 }, { 4, 7, 5 }, { 0, 4, 5 }, { 0, 5, 1 },
        { 2, 3, 7 }, { 2, 7, 6 }, { 0, 2, 6 }, { 0, 6, 4 }, { 1, 5, 7 }, { 1, 7, 3 },
    };
    static const int octa_faces[8][3] = {
        { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 },
    };
    long misses_fixed = 0, misses_double = 0, rays = 0;
    for (int mesh = 0; mesh < 20; mesh++) {
        bool cube = mesh % 2 == 0;
        double v[8][3], ax[3], ay[3], az[3], size = pow(10, tl_uniform(-1, 0.5));
        rnd_dir(ax);
        rnd_dir(ay);
        az[0] = ax[1] * ay[2] - ax[2] * ay[1], az[1] = ax[2] * ay[0] - ax[0] * ay[2], az[2] = ax[0] * ay[1] - ax[1] * ay[0];
        unit(az);
        ay[0] = az[1] * ax[2] - az[2] * ax[1], ay[1] = az[2] * ax[0] - az[0] * ax[2], ay[2] = az[0] * ax[1] - az[1] * ax[0];
        int nv = cube ? 8 : 6;
        for (int i = 0; i < nv; i++) {
            double l[3];
            if (cube) {
                l[0] = i & 1 ? 1 : -1, l[1] = i & 2 ? 1 : -1, l[2] = i & 4 ? 1 : -1;
            } else {
                l[0] = l[1] = l[2] = 0;
                l[i / 2] = i % 2 ? -1.3 : 1.3;
            }
            for (int k = 0; k < 3; k++)
                v[i][k] = size * (l[0] * ax[k] + l[1] * ay[k] + l[2] * az[k]);
        }
        const int(*faces)[3] = cube ? cube_faces : octa_faces;
        int nf = cube ? 12 : 8;
        char text[4096];
        int len = snprintf(text, sizeof text,
                           "v\nfrom 0 %.9g 0\nat 0 %.9g 0\nup 0 0 1\nangle 45\nhither 1\nresolution 8 8\n"
                           "l 1 2 3\nf 1 1 1 0.8 0.2 10 0 1\n", -6 * size, 8 * size);
        for (int f = 0; f < nf; f++) {
            len += snprintf(text + len, sizeof text - len, "p 3\n");
            for (int k = 0; k < 3; k++)
                len += snprintf(text + len, sizeof text - len, "%.9g %.9g %.9g\n", v[faces[f][k]][0],
                                v[faces[f][k]][1], v[faces[f][k]][2]);
        }
        rt_error_t err;
        if (!rt_backend_fixed.load(text, strlen(text), &err) || !rt_backend_double.load(text, strlen(text), &err)) {
            printf("  mesh %d does not load: %s\n", mesh, err.msg);
            misses_fixed++;
            continue;
        }
        for (long i = 0; i < n / 20; i++) {
            const int *f = faces[tl_rand() % (unsigned)nf];
            int e = (int)(tl_rand() % 3);
            double u = i % 8 == 0 ? 0 : tl_uniform(0, 1); /* one in eight at a corner */
            double target[3], o[3], d[3], dir[3];
            for (int k = 0; k < 3; k++)
                target[k] = v[f[e]][k] + u * (v[f[(e + 1) % 3]][k] - v[f[e]][k]);
            /* from outside, heading inwards (a ray that only touches an
             * outer edge may rightly miss) */
            rnd_dir(dir);
            for (int k = 0; k < 3; k++) {
                o[k] = target[k] * tl_uniform(3, 6) + dir[k] * size;
                d[k] = target[k] - o[k];
            }
            unit(d);
            probe_hit_t h;
            rays++;
            misses_fixed += !rt_backend_fixed.probe(o, d, false, &h);
            misses_double += !rt_backend_double.probe(o, d, false, &h);
        }
    }
    CHECK(misses_fixed == 0, "closed meshes: %ld rays aimed at shared edges and corners, %ld slip through in the "
                             "fixed build (double: %ld)", rays, misses_fixed, misses_double);
}

int main(int argc, char **argv)
{
    long total = argc > 1 ? atol(argv[1]) : 1000000;
    static const char *const names[] = { "sphere", "cylinder", "cone", "triangle", "quad", "patch" };
    long rays[6] = { 0 }, hits[6] = { 0 }, mismatch[6] = { 0 }, unexcused[6] = { 0 };
    double worst_t[6] = { 0 }, worst_n[6] = { 0 };
    long scenes = total / RAYS_PER_SCENE;
    long saturations = 0;
    printf("test_rayfuzz: %ld random rays against %ld random primitives, fixed vs double\n", total, scenes);
    for (long sc = 0; sc < scenes; sc++) {
        int kind = (int)(sc % 6);
        char text[2048];
        double c[3];
        double size = random_scene(text, sizeof text, kind, c);
        rt_error_t err;
        if (!rt_backend_fixed.load(text, strlen(text), &err) || !rt_backend_double.load(text, strlen(text), &err)) {
            printf("  scene %ld does not load: %u: %s\n%s", sc, (unsigned)err.line, err.msg, text);
            unexcused[kind]++;
            continue;
        }
        rt_backend_fixed.saturations(true);
        for (int i = 0; i < RAYS_PER_SCENE; i++) {
            double o[3], d[3];
            if (i % 4 == 3) {
                for (int k = 0; k < 3; k++)
                    o[k] = c[k] + tl_uniform(-0.2, 0.2) * size;
                rnd_dir(d);
            } else {
                double u[3], target[3];
                rnd_dir(u);
                double dist = size * tl_uniform(3, 8);
                for (int k = 0; k < 3; k++) {
                    target[k] = c[k] + tl_uniform(-0.6, 0.6) * size;
                    o[k] = c[k] + u[k] * dist;
                    d[k] = target[k] - o[k];
                }
                unit(d);
            }
            probe_hit_t hf, hd;
            bool f = rt_backend_fixed.probe(o, d, false, &hf), g = rt_backend_double.probe(o, d, false, &hd);
            rays[kind]++;
            /* a ray starting within rounding distance of the surface may or
             * may not hit it at t ~ 0 (secondary rays avoid this with an
             * offset): not counted */
            if ((f && hf.t < 1e-3 * size) || (g && hd.t < 1e-3 * size))
                continue;
            bool apart = f && g && fabs(hf.t - hd.t) > 0.05 * size;
            for (int k = 0; f && g && k < 3; k++)
                apart |= fabs(hf.normal[k] - hd.normal[k]) > 0.1;
            if (f != g || apart) {
                mismatch[kind]++;
                if (!probe_double_jumps(o, d, SILHOUETTE * size, 0.05 * size)) {
                    unexcused[kind]++;
                    if (getenv("FUZZ_VERBOSE"))
                        printf("    %s size %.4g: fixed %d t %.6g n %.3f %.3f %.3f / double %d t %.6g n %.3f %.3f %.3f\n",
                               names[kind], size, f, f ? hf.t : 0, hf.normal[0], hf.normal[1], hf.normal[2], g,
                               g ? hd.t : 0, hd.normal[0], hd.normal[1], hd.normal[2]);
                }
                continue;
            }
            if (!f)
                continue;
            hits[kind]++;
            double cosine = fabs(hd.normal[0] * d[0] + hd.normal[1] * d[1] + hd.normal[2] * d[2]);
            if (cosine < MIN_COS)
                continue;
            /* precision is relative to the whole scene (camera included) */
            double extent = size * 6 + fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
            double et = fabs(hf.t - hd.t) / (extent * T_ABS + T_REL * hd.t);
            if (et > 1 && getenv("FUZZ_VERBOSE"))
                printf("    %s size %.4g t %.6g vs %.6g cos %.3f inside %d\n", names[kind], size, hf.t, hd.t, cosine, i % 4 == 3);
            worst_t[kind] = et > worst_t[kind] ? et : worst_t[kind];
            for (int k = 0; k < 3; k++)
                worst_n[kind] = fabs(hf.normal[k] - hd.normal[k]) > worst_n[kind] ? fabs(hf.normal[k] - hd.normal[k])
                                                                                 : worst_n[kind];
        }
        saturations += rt_backend_fixed.saturations(false);
    }
    for (int k = 0; k < 6; k++) {
        CHECK(unexcused[k] == 0 && hits[k] > rays[k] / 20,
              "%-8s %7ld rays, %6ld hits; hit/miss differs on %ld (%.4f%%), all within %.0e of a silhouette or rim "
              "(%ld not)",
              names[k], rays[k], hits[k], mismatch[k], rays[k] ? 100.0 * mismatch[k] / rays[k] : 0.0, SILHOUETTE,
              unexcused[k]);
        CHECK(worst_t[k] <= 1 && worst_n[k] <= N_TOL,
              "%-8s worst t error %.2f of (%.0e extent + %.0e t); worst normal component error %.1e (bound %.0e)",
              names[k], worst_t[k], T_ABS, T_REL, worst_n[k], N_TOL);
    }
    CHECK(saturations == 0, "fixed-point saturations during the fuzz: %ld", saturations);
    edge_rays(total / 10);
    return tl_summary("test_rayfuzz");
}
