/*
 * bench_prims.c - firmware that measures the cost of intersection tests:
 * 32x32 eye rays of the built-in scene (one primitive) go to
 * scene_nearest, and the instructions per ray, minus those of making the
 * ray, are reported per test. Built as prims.elf by firmware.mk.
 */
#include "board_scene.h"
#include "port.h"
#include "geometry/camera.h"
#include "sink.h"
#include "geometry/scene_hit.h"
#include "tracer/trace.h"

#define GRID 32

int main(void)
{
    static rt_error_t err;
    static ray_scratch_t st;
    static camera_t cam;
    port_init();
    port_icount_start();
    const scene_t *sc = board_scene(&err);
    if (!sc || camera_init(&cam, &sc->view, GRID, GRID)) {
        report_text("scene or camera failed");
        return 2;
    }
    volatile real_t sink = 0;
    uint64_t t0 = port_icount_read();
    for (int j = 0; j < GRID; j++)
        for (int i = 0; i < GRID; i++)
            sink += camera_ray(&cam, i, j).dir.x;
    uint64_t rays_only = port_icount_read() - t0;
    uint32_t hits = 0;
    t0 = port_icount_read();
    for (int j = 0; j < GRID; j++)
        for (int i = 0; i < GRID; i++) {
            ray_t r = camera_ray(&cam, i, j);
            hit_t h;
            h.t = RT_T_FAR;
            hits += scene_nearest(sc, &r, RT_T_MIN, &h, &st);
        }
    uint64_t total = port_icount_read() - t0 - rays_only;
    scene_fold_stats(&st); /* the flat search counts a loop's tests apart */
    uint64_t tests = rt_stats_tests(&st.stats);
    report_value("rays", (uint64_t)GRID * GRID);
    report_value("hits", hits);
    report_value("tests", tests);
    report_value("instructions_per_test", tests ? (total + tests / 2) / tests : 0);
    (void)sink;
    return 0;
}
