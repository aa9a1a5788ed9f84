/*
 * csg.c - CSG trees of shapes (layers: xform.h): the spans of each shape
 * (shape.c) combined by union, intersection and difference, and the
 * nearest boundary past tmin. Uses shape.h; nothing below calls back.
 */
#include "csg.h"

#include "scratch.h"
#include "shape.h"

uint32_t solid_max_spans(const scene_t *sc, uint16_t root)
{
    if (!(root & CSG_NODE_BIT))
        return sc->shapes[root].kind == SHAPE_BOX ? 1 : 2;
    const csg_node_t *n = &sc->csg_nodes[root & ~CSG_NODE_BIT];
    return solid_max_spans(sc, n->a) + solid_max_spans(sc, n->b);
}

uint32_t solid_depth(const scene_t *sc, uint16_t root)
{
    if (!(root & CSG_NODE_BIT))
        return 0;
    const csg_node_t *n = &sc->csg_nodes[root & ~CSG_NODE_BIT];
    uint32_t a = solid_depth(sc, n->a), b = solid_depth(sc, n->b);
    return 1 + (a > b ? a : b);
}

#if RT_USE_OBJECTS /* the tracer's half: the worker scratch has span lists only then */

/* ---- CSG: boolean operations on sorted span lists ----------------------- */

static void csg_union(const spans_t *a, const spans_t *b, spans_t *out)
{
    uint32_t i = 0, j = 0;
    out->n = 0;
    while (i < a->n || j < b->n) {
        span_t cur = (j >= b->n || (i < a->n && a->s[i].in.t <= b->s[j].in.t)) ? a->s[i++] : b->s[j++];
        /* swallow every span that starts before cur ends */
        for (;;) {
            const span_t *next = 0;
            if (i < a->n && a->s[i].in.t <= cur.out.t)
                next = &a->s[i++];
            else if (j < b->n && b->s[j].in.t <= cur.out.t)
                next = &b->s[j++];
            if (!next)
                break;
            if (next->out.t > cur.out.t)
                cur.out = next->out;
        }
        spans_push(out, cur.in, cur.out);
    }
}

static void csg_intersection(const spans_t *a, const spans_t *b, spans_t *out)
{
    out->n = 0;
    for (uint32_t i = 0; i < a->n; i++)
        for (uint32_t j = 0; j < b->n; j++) {
            bound_t in = a->s[i].in.t >= b->s[j].in.t ? a->s[i].in : b->s[j].in;
            bound_t ob = a->s[i].out.t <= b->s[j].out.t ? a->s[i].out : b->s[j].out;
            if (in.t <= ob.t)
                spans_push(out, in, ob);
        }
}

/* a minus b: b's surfaces bound the result from the other side (flip). */
static void csg_difference(const spans_t *a, const spans_t *b, spans_t *out)
{
    out->n = 0;
    for (uint32_t i = 0; i < a->n; i++) {
        bound_t in = a->s[i].in, end = a->s[i].out;
        bool open = true;
        for (uint32_t j = 0; j < b->n && open; j++) {
            const span_t *c = &b->s[j];
            if (c->out.t < in.t || c->in.t > end.t)
                continue;
            if (c->in.t > in.t) {
                bound_t cut = c->in;
                cut.flip ^= 1;
                spans_push(out, in, cut);
            }
            if (c->out.t < end.t) {
                in = c->out;
                in.flip ^= 1;
            } else {
                open = false;
            }
        }
        if (open)
            spans_push(out, in, end);
    }
}

/* The children's spans at each level of the tree go in the worker's
 * scratch (scratch.h), so CSG costs no stack. */
static void solid_spans(const scene_t *sc, uint16_t ref, const ray_t *r, const real_t win[2], spans_t *out,
                        ray_scratch_t *w, uint32_t level)
{
    if (!(ref & CSG_NODE_BIT) || level >= RT_CSG_MAX_DEPTH) {
        if (!(ref & CSG_NODE_BIT))
            shape_spans(sc, ref, r, win, out);
        else
            out->n = 0; /* deeper than the reader allows: cannot happen */
        return;
    }
    const csg_node_t *n = &sc->csg_nodes[ref & ~CSG_NODE_BIT];
    spans_t *a = &w->csg_spans[level][0], *b = &w->csg_spans[level][1];
    solid_spans(sc, n->a, r, win, a, w, level + 1);
    if (a->n == 0 && n->op != CSG_UNION) {
        out->n = 0; /* nothing to intersect with or subtract from */
        return;
    }
    solid_spans(sc, n->b, r, win, b, w, level + 1);
    switch (n->op) {
    case CSG_UNION: csg_union(a, b, out); break;
    case CSG_INTERSECTION: csg_intersection(a, b, out); break;
    default: csg_difference(a, b, out); break;
    }
}

bool ray_hit_object(const scene_t *sc, const object_t *obj, const ray_t *r, real_t tmin, real_t *t,
                    ray_scratch_t *w, uint16_t *shape, uint8_t *face, bool *flip)
{
    spans_t *spans = &w->object_spans;
    /* only boundaries in (tmin, *t) count, and the boolean operations act
     * point by point: shapes may leave out what lies outside */
    const real_t win[2] = { tmin, *t };
    solid_spans(sc, obj->root, r, win, spans, w, 0);
    for (uint32_t i = 0; i < spans->n; i++) {
        const bound_t *b = spans->s[i].in.t > tmin ? &spans->s[i].in : &spans->s[i].out;
        if (b->t <= tmin)
            continue;
        if (b->t >= *t)
            return false;
        *t = b->t;
        *shape = b->shape;
        *face = b->face;
        *flip = b->flip;
        return true;
    }
    return false;
}
#endif
