/*
 * test_eye_box.c - the samples a sphere's eye rays may meet
 * (camera_sphere_box, src/geometry/camera.c), by which a flat scene's eye
 * rays skip spheres: for random views, sample grids (pixels and the cells
 * of anti-aliasing) and spheres, every sample whose eye ray meets the
 * sphere (the fixed build's exact test) must lie in the box. Also how
 * many samples the boxes leave out, so boxes that hold everything fail.
 */
#include <math.h>

#include "geometry/camera.h"
#include "geometry/sphere.h"
#include "testlib.h"

static fx_t q(double v) { return (fx_t)llround(v * FX_ONE); }

int main(void)
{
    printf("test_eye_box: eye rays outside a sphere's sample box miss it\n");
    long rays = 0, hits = 0, outside = 0, wrong = 0;
    for (int n = 0; n < 150; n++) {
        view_t view;
        view.from = v3(q(tl_uniform(-16, 16)), q(tl_uniform(-16, 16)), q(tl_uniform(-16, 16)));
        view.at = v3(q(tl_uniform(-4, 4)), q(tl_uniform(-4, 4)), q(tl_uniform(-4, 4)));
        view.up = v3(q(tl_uniform(-1, 1)), q(tl_uniform(-1, 1)), FX_ONE);
        view.angle = q(tl_uniform(10, 150));
        view.tan_half = fx_wtan_deg(view.angle / 2);
        int32_t w = 8 + (int32_t)(tl_rand() % 90), h = 8 + (int32_t)(tl_rand() % 70);
        int32_t sub = 1 << (tl_rand() % 3);
        camera_t cam;
        if ((sub == 1 ? camera_init(&cam, &view, w, h) : camera_init_cells(&cam, &view, w, h, sub)) != 0)
            continue;
        int32_t ni = sub == 1 ? w - 1 : sub * w, nj = sub == 1 ? h - 1 : sub * h;
        for (int k = 0; k < 8; k++) {
            sphere_t s;
            double rad = pow(2.0, tl_uniform(-5, 3));
            if (sphere_init(&s, v3(q(tl_uniform(-8, 8)), q(tl_uniform(-8, 8)), q(tl_uniform(-8, 8))), q(rad), 0))
                continue;
            int32_t box[4];
            camera_sphere_box(&cam, s.centre, s.radius, box);
            for (int32_t j = 0; j <= nj; j++)
                for (int32_t i = 0; i <= ni; i++) {
                    ray_t r = camera_ray(&cam, i, j);
                    fx_t t = FX_MAX;
                    int32_t kk = 2 * i - cam.cx, mm = 2 * j - cam.cy;
                    bool out = kk < box[0] || kk > box[1] || mm < box[2] || mm > box[3];
                    bool hit = sphere_hit_inline(&s, &r, 1, &t, false);
                    rays++;
                    hits += hit;
                    outside += out;
                    wrong += hit && out;
                }
        }
    }
    CHECK(wrong == 0, "sample boxes: %ld of %ld eye rays (%ld hits) meet a sphere outside its box", wrong, rays, hits);
    CHECK(outside > rays / 2, "sample boxes: leave out %ld of %ld eye rays (%.1f%%; more than half)", outside, rays,
          100.0 * outside / rays);
    return tl_summary("test_eye_box");
}
