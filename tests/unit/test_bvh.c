/*
 * test_bvh.c - the BVH never misses: for random rays against every SPD
 * size-1 and size-2 scene, traversal must return exactly what testing
 * every primitive returns (same primitive, same t to the last bit) in the
 * fixed build. Rays come from the camera, from random points in and around
 * the scene, and from surface points (like shadow and secondary rays).
 * Secondary rays carry the BVH leaf of their surface as a hint (ray.h):
 * with the right leaf and with a random one, the hit must not change. Any-
 * hit rays (shadow rays, scene_occluded) must say "blocked" exactly when
 * brute force finds a hit before their end, whatever the blocker they try
 * first. And a flat scene's shadow rays to its light, which skip spheres
 * outside the light's cones, are blocked exactly as without the cones (in
 * every backend).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "backend.h"
#include "testlib.h"

#define RAYS_PER_KIND 4000

static const char *const scenes[] = {
    "balls-1", "gears-1", "rings-1", "teapot-1", "tetra-1",
    "balls-2", "rings-2", "teapot-2", "tetra-2",
    "../textures", /* a plane beside the tree, and textured materials */
};

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    char *buf = malloc(1 << 20);
    *len = fread(buf, 1, 1 << 20, f);
    fclose(f);
    return buf;
}

static void unit(double d[3])
{
    double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; k++)
        d[k] /= l;
}

/* The light cones of a flat scene's shadow rays (scene_hit.c,
 * light_setup): for random scenes of a few spheres (and a floor), shadow
 * rays from random points and from points of the spheres to the light
 * must be blocked exactly as without the cones. */
static void light_cones(const rt_backend_t *be, const char *name)
{
    int scenes_flat = 0, rays = 0, blocked_n = 0, differ = 0;
    for (int n = 0; n < 60; n++) {
        char text[1024];
        int len = 0, spheres = 1 + (int)(tl_rand() % 4);
        double light[3], c[4][4];
        for (int k = 0; k < 3; k++)
            light[k] = tl_uniform(-12, 12);
        len += snprintf(text + len, sizeof text - (size_t)len,
                        "v\nfrom 0 -30 4\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0.01\nresolution 16 16\n"
                        "l %.4f %.4f %.4f\nf 1 1 1 0.8 0.2 8 0 1\n", light[0], light[1], light[2]);
        if (n & 1)
            len += snprintf(text + len, sizeof text - (size_t)len, "plane 0 0 -8  0 0 1\n");
        for (int i = 0; i < spheres; i++) {
            for (int k = 0; k < 3; k++)
                c[i][k] = tl_uniform(-6, 6);
            c[i][3] = pow(2.0, tl_uniform(-3, 1.5));
            len += snprintf(text + len, sizeof text - (size_t)len, "s %.4f %.4f %.4f %.4f\n", c[i][0], c[i][1],
                            c[i][2], c[i][3]);
        }
        rt_error_t err;
        bvh_stats_t bs;
        if (!be->load(text, (size_t)len, &err))
            continue;
        be->bvh_stats(&bs);
        scenes_flat += bs.nodes <= 1;
        for (int i = 0; i < 400; i++) {
            double o[3], d[3], tmax = 0;
            if (i & 1) { /* on a sphere, or just off it */
                int j = (int)(tl_rand() % (unsigned)spheres);
                double u[3] = { tl_uniform(-1, 1), tl_uniform(-1, 1), tl_uniform(-1, 1) };
                unit(u);
                for (int k = 0; k < 3; k++)
                    o[k] = c[j][k] + (c[j][3] + tl_uniform(-1e-4, 1e-4)) * u[k];
            } else {
                for (int k = 0; k < 3; k++)
                    o[k] = tl_uniform(-10, 10);
            }
            for (int k = 0; k < 3; k++) {
                d[k] = light[k] - o[k];
                tmax += d[k] * d[k];
            }
            tmax = sqrt(tmax);
            unit(d);
            uint32_t lb_a = UINT32_MAX, lb_b = UINT32_MAX;
            bool a = be->occluded_light(0, o, d, tmax, &lb_a), b = be->occluded(o, d, tmax, UINT32_MAX, &lb_b);
            rays++;
            blocked_n += b;
            if (a != b) {
                if (differ < 3)
                    printf("    %s: scene %d: o %.6f %.6f %.6f to the light: %d with the cones, %d without\n", name,
                           n, o[0], o[1], o[2], a, b);
                differ++;
            }
        }
    }
    CHECK(differ == 0 && scenes_flat > 20 && blocked_n > rays / 20,
          "%s light cones: %d shadow rays in %d flat scenes (%d blocked): %d differ from the search without them",
          name, rays, scenes_flat, blocked_n, differ);
}

int main(void)
{
    const rt_backend_t *be = &rt_backend_fixed;
    printf("test_bvh: BVH traversal against brute force, fixed build, %d rays x 3 kinds per scene\n",
           RAYS_PER_KIND);
    for (unsigned s = 0; s < sizeof scenes / sizeof scenes[0]; s++) {
        char path[128];
        size_t len;
        snprintf(path, sizeof path, "scenes/spd/%s.nff", scenes[s]);
        char *text = slurp(path, &len);
        rt_error_t err;
        if (!text || !be->load(text, len, &err)) {
            CHECK(0, "%s loads", scenes[s]);
            free(text);
            continue;
        }
        free(text);
        double mn[3], mx[3];
        be->bounds(mn, mx);
        int rays = 0, hits = 0, differ = 0, hint_differ = 0, occl_differ = 0, occluded_n = 0;
        uint32_t last_blocker = UINT32_MAX, leaf = UINT32_MAX;
        bvh_stats_t bs;
        be->bvh_stats(&bs);
        for (int kind = 0; kind < 3; kind++) {
            for (int i = 0; i < RAYS_PER_KIND; i++) {
                double o[3], d[3];
                if (kind == 0) { /* eye rays through random pixels */
                    double e[3];
                    be->eye_dir(256, 256, (int)(tl_rand() % 256), (int)(tl_rand() % 256), e);
                    probe_hit_t h0;
                    /* the eye position: back along the ray from any hit */
                    (void)h0;
                    for (int k = 0; k < 3; k++)
                        d[k] = e[k];
                    /* origin: a random point in the box, looking along d */
                    for (int k = 0; k < 3; k++)
                        o[k] = tl_uniform(mn[k], mx[k]) - 2 * (mx[k] - mn[k]) * d[k];
                } else if (kind == 1) { /* anywhere in and around the scene */
                    for (int k = 0; k < 3; k++) {
                        double pad = 0.2 * (mx[k] - mn[k]);
                        o[k] = tl_uniform(mn[k] - pad, mx[k] + pad);
                        d[k] = tl_uniform(-1, 1);
                    }
                    unit(d);
                } else { /* from a surface point, in a random direction */
                    double o0[3], d0[3];
                    for (int k = 0; k < 3; k++) {
                        o0[k] = tl_uniform(mn[k], mx[k]);
                        d0[k] = tl_uniform(-1, 1);
                    }
                    unit(d0);
                    probe_hit_t h;
                    if (!be->probe(o0, d0, false, &h)) {
                        i--;
                        continue;
                    }
                    leaf = h.leaf;
                    for (int k = 0; k < 3; k++) {
                        d[k] = tl_uniform(-1, 1);
                        o[k] = o0[k] + h.t * d0[k] + 1e-3 * h.normal[k] * ((d[k] * h.normal[k] >= 0) ? 1 : -1);
                    }
                    unit(d);
                }
                probe_hit_t a, b;
                bool ha = be->probe(o, d, false, &a), hb = be->probe(o, d, true, &b);
                rays++;
                hits += hb;
                if (ha != hb || (ha && (a.t_raw != b.t_raw || a.kind != b.kind || a.index != b.index))) {
                    if (differ < 3)
                        printf("    %s: o %.6f %.6f %.6f d %.6f %.6f %.6f: bvh %d t %.6f #%d/%u, brute %d t %.6f #%d/%u\n",
                               scenes[s], o[0], o[1], o[2], d[0], d[1], d[2], ha, ha ? a.t : 0, a.kind,
                               a.index, hb, hb ? b.t : 0, b.kind, b.index);
                    differ++;
                }
                /* the surface's own leaf for secondary rays, else any node */
                uint32_t hint = kind == 2 && (i & 1) ? leaf : (uint32_t)(tl_rand() % (bs.nodes + 2));
                probe_hit_t c;
                bool hc = be->probe_leaf(o, d, hint, &c);
                if (hc != hb || (hc && (c.t_raw != b.t_raw || c.kind != b.kind || c.index != b.index))) {
                    if (hint_differ < 3)
                        printf("    %s: leaf hint %u: bvh %d t %.6f, brute %d t %.6f\n", scenes[s], hint, hc,
                               hc ? c.t : 0, hb, hb ? b.t : 0);
                    hint_differ++;
                }
                /* a shadow ray ending before, at or after the nearest hit */
                double tmax = hb ? b.t * (0.5 + (tl_rand() % 3) * 0.5) : tl_uniform(0.1, 100);
                bool expect = hb && b.t < tmax;
                if ((tl_rand() & 3) == 0)
                    last_blocker = hb ? ((uint32_t)b.kind << 24 | b.index) : UINT32_MAX;
                bool blocked = be->occluded(o, d, tmax, hint, &last_blocker);
                occluded_n += blocked;
                if (blocked != expect && !(hb && b.t == tmax)) {
                    if (occl_differ < 3)
                        printf("    %s: occluded %d to t %.6f, brute nearest %d t %.6f\n", scenes[s], blocked,
                               tmax, hb, hb ? b.t : 0);
                    occl_differ++;
                }
            }
        }
        CHECK(hint_differ == 0, "%s: leaf hints change no hit (%d differ)", scenes[s], hint_differ);
        CHECK(occl_differ == 0 && occluded_n > 0, "%s: shadow rays blocked exactly when brute force hits before "
              "their end (%d blocked, %d differ)", scenes[s], occluded_n, occl_differ);
        CHECK(differ == 0, "%s: %d rays (%d hits): BVH and brute force differ on %d", scenes[s], rays, hits,
              differ);
    }
    light_cones(&rt_backend_fixed, "fixed");
    light_cones(&rt_backend_float, "float");
    light_cones(&rt_backend_double, "double");
    return tl_summary("test_bvh");
}
