/*
 * solid.h - solids beyond NFF: quadrics, tori and boxes in their own
 * object space, placed by affine transforms, and combined by CSG. This
 * header gathers the three layers (see xform.h): xform.h, shape.h, csg.h.
 *
 * A ray meets a solid in "spans" (the stretches of t inside it); CSG
 * combines span lists by union, intersection and difference, and the
 * nearest hit is the first span boundary past tmin. Every boundary
 * remembers the shape whose surface it is, which face of it (the curved
 * surface, or one of the six faces of a box or clip box) and whether the
 * solid's outward normal is the shape's inward one (subtracted parts).
 */
#ifndef SOLID_H
#define SOLID_H

#include "csg.h"
#include "shape.h"
#include "xform.h"

#endif
