/* probe_jump.h - the excuse shared by the geometry tests: where the double
 * result itself jumps under a tiny nudge, fixed and double may disagree. */
#ifndef PROBE_JUMP_H
#define PROBE_JUMP_H

#include <math.h>
#include <stdbool.h>

#include "backend.h"

/* Whether nudging the ray's origin by `eps` along any axis makes the double
 * result jump (hit to miss, t by more than `dt`, or the normal turning):
 * the ray passes a silhouette, a rim or the tip of a cone. */
static inline bool probe_double_jumps(const double o[3], const double dir[3], double eps, double dt)
{
    probe_hit_t h0, h;
    bool base = rt_backend_double.probe(o, dir, false, &h0);
    for (int k = 0; k < 3; k++) {
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double o2[3] = { o[0], o[1], o[2] };
            o2[k] += sgn * eps;
            bool hit = rt_backend_double.probe(o2, dir, false, &h);
            if (hit != base || (hit && fabs(h.t - h0.t) > dt))
                return true;
            for (int m = 0; hit && m < 3; m++)
                if (fabs(h.normal[m] - h0.normal[m]) > 0.1)
                    return true;
        }
    }
    return false;
}

#endif
