/* object.c - the surface at a hit on a solid (object.h). */
#include "object.h"

#include "solid.h"

void object_prim_surface(const scene_t *sc, const object_t *o, const hit_t *h, vec3_t p, prim_surface_t *out)
{
    const shape_t *s = &sc->shapes[h->shape];
    (void)o;
    out->ng = shape_normal(sc, h->shape, h->face, p);
    if (h->flip) /* a subtracted solid's surface faces the other way */
        out->ng = v3_neg(out->ng);
    out->n = out->ng;
    out->material = s->material;
    /* solids may be met again anywhere: offset by their error bound */
    out->leave = LEAVE_OFFSET;
    out->offset = s->kind == SHAPE_TORUS ? RT_TORUS_OFFSET : RT_SOLID_OFFSET;
    out->smooth = false;
}
