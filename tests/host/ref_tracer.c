/* ref_tracer: a deliberately simple, brute-force, double-precision Whitted
 * ray tracer, written from docs/shading-model.md alone. It is a second,
 * independent reference that the project's double build must match, so it
 * shares no code with src/ and favours obviousness over speed: no
 * acceleration structure, every ray tests every primitive.
 *
 *   ref_tracer SCENE.nff -o OUT.ppm [--size WxH] [--depth N] [--spp N] [--far F] [--texture-filter on|off]
 *
 * --far F: the half side of the far cube that ends planes; --far rule:
 * the model's, F = 2^(9 - k) with k the scene scale found here by the
 * page's rule (and printed to stderr, "far cube F"); without it planes go
 * on for ever.
 *
 * Exit status: 0 success, 1 output failure, 2 bad scene or usage.
 * Scene errors read "file:line: message". The environment variable
 * REF_TRACER_EPS_SCALE multiplies the surface offset of secondary rays,
 * to check that images do not depend on it.
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- vectors ---------------------------------------------------------- */

typedef struct { double x, y, z; } Vec;

static Vec vec(double x, double y, double z) { Vec v = {x, y, z}; return v; }
static Vec add(Vec a, Vec b) { return vec(a.x + b.x, a.y + b.y, a.z + b.z); }
static Vec sub(Vec a, Vec b) { return vec(a.x - b.x, a.y - b.y, a.z - b.z); }
static Vec mul(Vec a, double s) { return vec(a.x * s, a.y * s, a.z * s); }
static Vec vmul(Vec a, Vec b) { return vec(a.x * b.x, a.y * b.y, a.z * b.z); }
static double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static Vec cross(Vec a, Vec b)
{
    return vec(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static double len(Vec a) { return sqrt(dot(a, a)); }
static Vec norm(Vec a) { double l = len(a); return l > 0 ? mul(a, 1 / l) : a; }
static double comp(Vec a, int i) { return i == 0 ? a.x : i == 1 ? a.y : a.z; }

/* ---- scene ------------------------------------------------------------ */

enum { TEX_NONE, TEX_CHECKER, TEX_MARBLE };

typedef struct {
    Vec c;
    double kd, ks, shine, t, ior;
    int tex;           /* TEX_*: then C depends on the hit point */
    double size, amount;
    Vec ca, cb;        /* the texture's two colours */
    int axes;          /* checker: bit i, axis i counts */
} Material;

enum { SPHERE, CONE, POLYGON, PLANE };

typedef struct {
    int kind;
    Material m;
    Vec a;           /* sphere centre; cone base */
    double r;        /* sphere radius; cone base radius */
    Vec axis;        /* cone: unit axis base -> apex */
    double h, k;     /* cone: height, radius change per unit height */
    Vec ng;          /* polygon, plane: unit normal (a polygon's from its first three vertices) */
    double d;        /* polygon, plane: the plane ng . x = d */
    int ax0, ax1;    /* polygon: the two axes it is projected onto */
    size_t first, n; /* polygon: verts[first .. first+n) */
    int patch;       /* polygon: unit vertex normals in norms[] */
} Prim;

typedef struct { Vec pos, col; } Light;

/* Globals, so that everything stays reachable when exit() is called from
 * deep in the parser (no leak reports under the sanitizers). */
static Prim *prims;
static size_t nprims, capprims;
static Vec *verts, *norms; /* norms[i] belongs to verts[i] (zero for `p`) */
static size_t nverts, capverts, capnorms;
static Light *lights;
static size_t nlights, caplights;
static char *text;

static Vec bg, from, at, up;
static double angle;
static int resx, resy, have_view;
static double extent;             /* largest absolute coordinate */
static double eps_offset, eps_t;  /* derived from extent, see main() */
static int max_depth = 5;
static double far_cube = INFINITY;  /* --far */
static int far_rule;                /* --far rule */
static int sky_on;
static Vec sky_horizon, sky_zenith, sky_up;
static double sky_exp;

static void *grow(void *p, size_t *cap, size_t need, size_t size)
{
    size_t c = *cap ? *cap : 16;
    if (need <= *cap)
        return p;
    while (c < need) {
        if (c > (size_t)-1 / 2 / size) {
            fputs("ref_tracer: out of memory\n", stderr);
            exit(1);
        }
        c *= 2;
    }
    p = realloc(p, c * size);
    if (!p) {
        fputs("ref_tracer: out of memory\n", stderr);
        exit(1);
    }
    *cap = c;
    return p;
}

/* The scene scale (docs/shading-model.md, "The scene scale"): the least
 * p with |x| < 2^p over the geometry numbers and over the camera and
 * light numbers, each number on its own (INT_MIN: none yet). */
static int scale_p[2] = { INT_MIN, INT_MIN };
static void scale_number(double x, int far)
{
    int e;
    if (x == 0)
        return;
    (void)frexp(fabs(x), &e); /* |x| = m 2^e, 1/2 <= m < 1: |x| < 2^e */
    if (e > scale_p[far])
        scale_p[far] = e;
}
static void scale_vec(Vec v, int far)
{
    scale_number(v.x, far), scale_number(v.y, far), scale_number(v.z, far);
}
/* 2^(9 - k), k the largest with the geometry below 2^4 and the camera and
 * lights below 2^9 */
static double rule_far_cube(void)
{
    int k = INT_MAX;
    if (scale_p[0] != INT_MIN)
        k = 4 - scale_p[0];
    if (scale_p[1] != INT_MIN && 9 - scale_p[1] < k)
        k = 9 - scale_p[1];
    return ldexp(1, 9 - (k == INT_MAX ? 0 : k));
}

static void see(Vec p, double r) /* widen the extent by a position (+ radius) */
{
    double m = fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))) + r;
    if (m > extent)
        extent = m;
}

/* ---- NFF reader ------------------------------------------------------- */

typedef struct { const char *s; size_t len; int line; } Tok;

typedef struct {
    const char *name;
    const char *p;   /* next unread character */
    int line;        /* line of *p */
    int last_line;   /* line of the last token read, for errors at EOF */
} Reader;

static void fail(const Reader *r, int line, const char *msg)
{
    fprintf(stderr, "%s:%d: %s\n", r->name, line, msg);
    exit(2);
}

static Tok next(Reader *r)
{
    Tok t;
    for (;;) {
        while (*r->p == ' ' || *r->p == '\t' || *r->p == '\r' || *r->p == '\n' ||
               *r->p == '\f' || *r->p == '\v')
            if (*r->p++ == '\n')
                r->line++;
        if (*r->p != '#')
            break;
        while (*r->p && *r->p != '\n') /* comment to end of line */
            r->p++;
    }
    t.s = r->p;
    t.line = r->line;
    while (*r->p && !strchr(" \t\r\n\f\v", *r->p))
        r->p++;
    t.len = (size_t)(r->p - t.s);
    if (t.len)
        r->last_line = t.line;
    return t;
}

static Tok peek(const Reader *r) { Reader copy = *r; return next(&copy); }

static int is(Tok t, const char *word) { return t.len == strlen(word) && !memcmp(t.s, word, t.len); }

/* The NFF number syntax, [+-]digits[.digits][e[+-]digits]: strtod alone
 * would also take "inf", "nan" and hex. */
static int numeric(Tok t)
{
    size_t i = 0, digits = 0;
    if (i < t.len && (t.s[i] == '+' || t.s[i] == '-'))
        i++;
    for (; i < t.len && t.s[i] >= '0' && t.s[i] <= '9'; i++)
        digits++;
    if (i < t.len && t.s[i] == '.')
        for (i++; i < t.len && t.s[i] >= '0' && t.s[i] <= '9'; i++)
            digits++;
    if (!digits)
        return 0;
    if (i < t.len && (t.s[i] == 'e' || t.s[i] == 'E')) {
        size_t e = 0;
        if (++i < t.len && (t.s[i] == '+' || t.s[i] == '-'))
            i++;
        for (; i < t.len && t.s[i] >= '0' && t.s[i] <= '9'; i++)
            e++;
        if (!e)
            return 0;
    }
    return i == t.len && t.len < 64;
}

static double number(Reader *r, const char *what)
{
    char buf[160], num[64];
    Tok t = next(r);
    double x;
    if (!t.len) {
        snprintf(buf, sizeof buf, "%s: expected a number (end of file)", what);
        fail(r, r->last_line, buf);
    }
    if (!numeric(t)) {
        snprintf(buf, sizeof buf, "%s: expected a number, found '%.*s'", what,
                 (int)(t.len < 40 ? t.len : 40), t.s);
        fail(r, t.line, buf);
    }
    memcpy(num, t.s, t.len);
    num[t.len] = 0;
    x = strtod(num, NULL);
    if (!isfinite(x)) {
        snprintf(buf, sizeof buf, "%s: number out of range", what);
        fail(r, t.line, buf);
    }
    return x;
}

static Vec vector(Reader *r, const char *what)
{
    double x = number(r, what), y = number(r, what);
    return vec(x, y, number(r, what));
}

static int count(Reader *r, const char *what, int lo, int hi)
{
    double x = number(r, what);
    if (x != floor(x) || x < lo || x > hi) {
        char buf[160];
        snprintf(buf, sizeof buf, "%s: expected a whole number from %d to %d", what, lo, hi);
        fail(r, r->last_line, buf);
    }
    return (int)x;
}

static void keyword(Reader *r, const char *word)
{
    Tok t = next(r);
    if (!is(t, word)) {
        char buf[160];
        snprintf(buf, sizeof buf, "v: expected '%s'", word);
        fail(r, t.len ? t.line : r->last_line, buf);
    }
}

/* |a x b| negligible against |a| |b|: parallel, or one of them zero */
static int parallel(Vec a, Vec b) { return len(cross(a, b)) <= 1e-12 * len(a) * len(b); }

static void read_view(Reader *r, int line)
{
    Vec w;
    keyword(r, "from");
    from = vector(r, "from");
    keyword(r, "at");
    at = vector(r, "at");
    keyword(r, "up");
    up = vector(r, "up");
    keyword(r, "angle");
    angle = number(r, "angle");
    keyword(r, "hither");
    (void)number(r, "hither"); /* read and ignored: eye rays start at from */
    keyword(r, "resolution");
    resx = count(r, "resolution", 1, 16384);
    resy = count(r, "resolution", 1, 16384);
    w = sub(at, from);
    if (len(w) == 0)
        fail(r, line, "v: from and at are the same point");
    if (parallel(w, up))
        fail(r, line, "v: up is zero or parallel to the view direction");
    if (!(angle > 0 && angle < 180))
        fail(r, line, "v: angle must be between 0 and 180 degrees");
    see(from, 0);
    see(at, 0);
    scale_vec(from, 1);
    scale_vec(at, 0);
    have_view = 1;
}

static Prim *new_prim(int kind, const Material *m)
{
    Prim *p;
    prims = grow(prims, &capprims, nprims + 1, sizeof *prims);
    p = &prims[nprims++];
    memset(p, 0, sizeof *p);
    p->kind = kind;
    p->m = *m;
    return p;
}

static void read_polygon(Reader *r, int line, int patch, const Material *m)
{
    const char *what = patch ? "pp" : "p";
    int n = count(r, what, 3, 1 << 24), i, far = 0;
    size_t first = nverts;
    Vec v0, e1, e2, ng;
    Prim *p;
    for (i = 0; i < n; i++) {
        Vec nv = vec(0, 0, 0);
        verts = grow(verts, &capverts, nverts + 1, sizeof *verts);
        norms = grow(norms, &capnorms, nverts + 1, sizeof *norms);
        verts[nverts] = vector(r, what);
        scale_vec(verts[nverts], 0); /* a polygon skipped as flat counts too */
        if (patch) {
            nv = vector(r, what);
            if (len(nv) == 0)
                fail(r, r->last_line, "pp: vertex normal is zero");
            nv = norm(nv);
        }
        norms[nverts++] = nv;
    }
    /* All vertices on one line (or one point): no area, nothing to hit. */
    v0 = verts[first];
    for (i = 1; i < n; i++)
        if (len(sub(verts[first + i], v0)) > len(sub(verts[first + far], v0)))
            far = i;
    for (i = 1; i < n; i++)
        if (!parallel(sub(verts[first + i], v0), sub(verts[first + far], v0)))
            break;
    if (i == n) {
        nverts = first;
        return;
    }
    e1 = sub(verts[first + 1], v0);
    e2 = sub(verts[first + 2], verts[first + 1]);
    if (parallel(e1, e2)) /* the model takes Ng from these three */
        fail(r, line, "polygon's first three vertices are collinear");
    ng = norm(cross(e1, e2));
    for (i = 0; i < n; i++)
        see(verts[first + i], 0);
    p = new_prim(POLYGON, m);
    p->ng = ng;
    p->d = dot(ng, v0);
    /* project onto the plane of the two axes where ng is smallest */
    if (fabs(ng.x) >= fabs(ng.y) && fabs(ng.x) >= fabs(ng.z))
        p->ax0 = 1, p->ax1 = 2;
    else if (fabs(ng.y) >= fabs(ng.z))
        p->ax0 = 0, p->ax1 = 2;
    else
        p->ax0 = 0, p->ax1 = 1;
    p->first = first;
    p->n = (size_t)n;
    p->patch = patch;
}

static void read_scene(const char *name)
{
    Reader r;
    Material m;
    int have_material = 0;
    FILE *f = fopen(name, "rb");
    size_t n = 0, cap = 0, got;
    memset(&m, 0, sizeof m);
    if (!f) {
        fprintf(stderr, "%s: cannot open\n", name);
        exit(2);
    }
    do { /* whole file into memory, NUL-terminated */
        text = grow(text, &cap, n + 4097, 1);
        got = fread(text + n, 1, 4096, f);
        n += got;
    } while (got == 4096);
    fclose(f);
    text[n] = 0;
    r.name = name;
    r.p = text;
    r.line = 1;
    r.last_line = 1;
    if (strlen(text) != n) { /* a NUL byte: not text */
        size_t i;
        int line = 1;
        for (i = 0; text[i]; i++)
            line += text[i] == '\n';
        fail(&r, line, "not a text file");
    }
    for (;;) {
        Tok t = next(&r);
        if (!t.len)
            break;
        if (is(t, "v")) {
            read_view(&r, t.line);
        } else if (is(t, "b")) {
            bg = vector(&r, "b");
        } else if (is(t, "l")) {
            Light l;
            Tok c;
            l.pos = vector(&r, "l");
            l.col = vec(1, 1, 1);
            /* The colour is optional: present when numbers follow on the
             * line where the position ends. */
            c = peek(&r);
            if (c.len && c.line == r.last_line && numeric(c)) {
                int line = r.last_line;
                l.col = vector(&r, "l");
                if (r.last_line != line)
                    fail(&r, line, "l: a light colour needs three numbers on the line");
            }
            see(l.pos, 0);
            scale_vec(l.pos, 1);
            lights = grow(lights, &caplights, nlights + 1, sizeof *lights);
            lights[nlights++] = l;
        } else if (is(t, "f")) {
            m.c = vector(&r, "f");
            m.kd = number(&r, "f");
            m.ks = number(&r, "f");
            m.shine = number(&r, "f");
            m.t = number(&r, "f");
            m.ior = number(&r, "f");
            m.tex = TEX_NONE;
            if (m.t > 0 && m.ior <= 0)
                fail(&r, t.line, "f: index of refraction must be positive");
            have_material = 1;
        } else if (is(t, "checker") || is(t, "marble")) {
            if (!have_material)
                fail(&r, t.line, is(t, "checker") ? "checker before any 'f' material line"
                                                  : "marble before any 'f' material line");
            m.tex = is(t, "checker") ? TEX_CHECKER : TEX_MARBLE;
            m.size = number(&r, "texture");
            scale_number(m.size, 0);
            m.ca = vector(&r, "texture");
            m.cb = vector(&r, "texture");
            if (!(m.size > 0))
                fail(&r, t.line, "texture: size must be positive");
            if (m.tex == TEX_MARBLE) {
                m.amount = number(&r, "marble");
            } else {
                Tok a = peek(&r);
                static const char *names[] = { "x", "y", "xy", "z", "xz", "yz", "xyz" };
                int k;
                m.axes = 7;
                if (a.len && a.line == r.last_line && !numeric(a)) {
                    next(&r);
                    for (k = 0; k < 7 && !is(a, names[k]); k++)
                        ;
                    if (k == 7)
                        fail(&r, a.line, "checker: bad axes");
                    m.axes = k + 1;
                }
            }
        } else if (is(t, "sky")) {
            sky_horizon = vector(&r, "sky");
            sky_zenith = vector(&r, "sky");
            sky_up = norm(vector(&r, "sky"));
            sky_exp = number(&r, "sky");
            sky_on = 1;
        } else if (is(t, "plane")) {
            Prim *p;
            Vec pt, nv;
            if (!have_material)
                fail(&r, t.line, "plane before any 'f' material line");
            pt = vector(&r, "plane");
            nv = vector(&r, "plane");
            if (len(nv) == 0)
                fail(&r, t.line, "plane normal is zero");
            p = new_prim(PLANE, &m);
            p->ng = norm(nv);
            p->d = dot(p->ng, pt);
            see(pt, 0);
            scale_vec(pt, 0);
        } else if (is(t, "s") || is(t, "c") || is(t, "p") || is(t, "pp")) {
            if (!have_material) {
                char buf[80];
                snprintf(buf, sizeof buf, "%.*s before any 'f' material line", (int)t.len, t.s);
                fail(&r, t.line, buf);
            }
            if (is(t, "s")) {
                Vec c = vector(&r, "s");
                double rad = fabs(number(&r, "s"));
                Prim *p;
                if (rad == 0)
                    fail(&r, t.line, "sphere radius is zero");
                p = new_prim(SPHERE, &m);
                p->a = c;
                p->r = rad;
                see(c, rad);
                scale_vec(c, 0);
                scale_number(rad, 0);
            } else if (is(t, "c")) {
                Vec base = vector(&r, "c");
                double rb = fabs(number(&r, "c"));
                Vec apex = vector(&r, "c");
                double ra = fabs(number(&r, "c"));
                Prim *p;
                if (len(sub(apex, base)) == 0)
                    fail(&r, t.line, "cone base and apex are the same point");
                if (rb == 0 && ra == 0)
                    fail(&r, t.line, "cone radii are both zero");
                p = new_prim(CONE, &m);
                p->a = base;
                p->r = rb;
                p->h = len(sub(apex, base));
                p->axis = mul(sub(apex, base), 1 / p->h);
                p->k = (ra - rb) / p->h;
                see(base, rb);
                see(apex, ra);
                scale_vec(base, 0), scale_vec(apex, 0);
                scale_number(rb, 0), scale_number(ra, 0);
            } else {
                read_polygon(&r, t.line, is(t, "pp"), &m);
            }
        } else {
            char buf[80];
            snprintf(buf, sizeof buf, "unsupported entity '%.*s'", (int)(t.len < 40 ? t.len : 40), t.s);
            fail(&r, t.line, buf);
        }
    }
    if (!have_view)
        fail(&r, r.last_line, "no 'v' viewpoint in the file");
}

/* ---- intersection ----------------------------------------------------- */

/* Roots of a t^2 + 2 b t + c = 0, in the cancellation-free form. */
static int roots(double a, double b, double c, double t[2])
{
    double disc = b * b - a * c, q;
    int n = 0;
    if (disc < 0)
        return 0;
    q = -(b + copysign(sqrt(disc), b));
    if (a != 0)
        t[n++] = q / a;
    if (q != 0)
        t[n++] = c / q;
    return n;
}

/* Nearest t in (eps_t, tmax) where the ray o + t d (d unit) meets p, or
 * tmax when it does not. */
static double hit(const Prim *p, Vec o, Vec d, double tmax)
{
    double t[2], best = tmax;
    int i, n;
    if (p->kind == SPHERE) {
        Vec oc = sub(o, p->a);
        n = roots(1, dot(oc, d), dot(oc, oc) - p->r * p->r, t);
        for (i = 0; i < n; i++)
            if (t[i] > eps_t && t[i] < best)
                best = t[i];
    } else if (p->kind == CONE) {
        /* |Q - (Q.axis) axis| = r + k (Q.axis), Q = o + t d - base, with
         * 0 <= Q.axis <= h; both sides squared. */
        Vec q0 = sub(o, p->a);
        double dy = dot(d, p->axis), qy = dot(q0, p->axis);
        Vec dp = sub(d, mul(p->axis, dy)), qp = sub(q0, mul(p->axis, qy));
        double rq = p->r + p->k * qy;
        n = roots(dot(dp, dp) - p->k * p->k * dy * dy, dot(dp, qp) - p->k * dy * rq,
                  dot(qp, qp) - rq * rq, t);
        for (i = 0; i < n; i++) {
            double y = qy + t[i] * dy;
            if (t[i] > eps_t && t[i] < best && y >= 0 && y <= p->h)
                best = t[i];
        }
    } else if (p->kind == PLANE) {
        double dn = dot(p->ng, d), th;
        Vec P;
        if (dn == 0)
            return tmax;
        th = (p->d - dot(p->ng, o)) / dn;
        P = add(o, mul(d, th));
        if (th > eps_t && th < tmax && fabs(P.x) < far_cube && fabs(P.y) < far_cube && fabs(P.z) < far_cube)
            best = th;
    } else {
        double dn = dot(p->ng, d), th, px, py;
        size_t j;
        int inside = 0;
        Vec P;
        if (dn == 0)
            return tmax;
        th = (p->d - dot(p->ng, o)) / dn;
        if (!(th > eps_t && th < tmax))
            return tmax;
        P = add(o, mul(d, th));
        px = comp(P, p->ax0);
        py = comp(P, p->ax1);
        /* even-odd rule: count edges crossed by a ray from P along +x */
        for (j = 0; j < p->n; j++) {
            Vec a = verts[p->first + j], b = verts[p->first + (j + 1) % p->n];
            double ax = comp(a, p->ax0), ay = comp(a, p->ax1);
            double bx = comp(b, p->ax0), by = comp(b, p->ax1);
            if ((ay > py) != (by > py) && px < ax + (py - ay) * (bx - ax) / (by - ay))
                inside = !inside;
        }
        if (inside)
            best = th;
    }
    return best;
}

/* Index of the nearest primitive before tmax (-1: none), its t in *t.
 * With any set, the first hit will do (shadow rays). */
static long nearest(Vec o, Vec d, double tmax, int any, double *t)
{
    long found = -1;
    size_t i;
    for (i = 0; i < nprims; i++) {
        double th = hit(&prims[i], o, d, tmax);
        if (th < tmax) {
            tmax = th;
            found = (long)i;
            if (any)
                break;
        }
    }
    *t = tmax;
    return found;
}

/* Geometric normal *ng and shading normal (returned) at P on p. */
static Vec normal_at(const Prim *p, Vec P, Vec *ng)
{
    if (p->kind == SPHERE) {
        *ng = norm(sub(P, p->a));
    } else if (p->kind == CONE) {
        /* gradient of |Qperp|^2 - r(y)^2: outward */
        Vec q = sub(P, p->a);
        double y = dot(q, p->axis);
        Vec qp = sub(q, mul(p->axis, y));
        *ng = norm(sub(qp, mul(p->axis, p->k * (p->r + p->k * y))));
        if (len(*ng) == 0) /* the tip of a pointed cone */
            *ng = p->axis;
    } else {
        *ng = p->ng;
        if (p->patch) {
            /* the fan triangle (0, i, i+1) that holds P: the one whose
             * smallest barycentric coordinate is largest */
            const Vec *v = verts + p->first, *nv = norms + p->first;
            double px = comp(P, p->ax0), py = comp(P, p->ax1), best = -INFINITY;
            Vec n = *ng;
            size_t i;
            for (i = 1; i + 1 < p->n; i++) {
                double ax = comp(v[0], p->ax0), ay = comp(v[0], p->ax1);
                double bx = comp(v[i], p->ax0) - ax, by = comp(v[i], p->ax1) - ay;
                double cx = comp(v[i + 1], p->ax0) - ax, cy = comp(v[i + 1], p->ax1) - ay;
                double den = bx * cy - by * cx, b1, b2, b0, lo;
                if (den == 0)
                    continue;
                b1 = ((px - ax) * cy - (py - ay) * cx) / den;
                b2 = (bx * (py - ay) - by * (px - ax)) / den;
                b0 = 1 - b1 - b2;
                lo = fmin(b0, fmin(b1, b2));
                if (lo > best) {
                    best = lo;
                    n = add(add(mul(nv[0], b0), mul(nv[i], b1)), mul(nv[i + 1], b2));
                }
            }
            return len(n) > 0 ? norm(n) : *ng;
        }
    }
    return *ng;
}

/* ---- textures and the sky --------------------------------------------- */

static unsigned lattice(long i, long j, long k)
{
    uint32_t n = (uint32_t)i * 0x8da6b343u + (uint32_t)j * 0xd8163841u + (uint32_t)k * 0xcb1ab31fu;
    n ^= n >> 15;
    n *= 0x2c1b3c6du;
    n ^= n >> 12;
    return n >> 28;
}

static double smooth(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

static double noise(Vec q)
{
    double c[3] = { floor(q.x), floor(q.y), floor(q.z) };
    double u[3] = { q.x - c[0], q.y - c[1], q.z - c[2] }, sum = 0;
    int e;
    for (e = 0; e < 8; e++) {
        int ex = e & 1, ey = (e >> 1) & 1, ez = e >> 2;
        unsigned h = lattice((long)c[0] + ex, (long)c[1] + ey, (long)c[2] + ez);
        double x = u[0] - ex, y = u[1] - ey, z = u[2] - ez;
        double a = h < 8 ? x : y, b = h < 4 ? y : (h == 12 || h == 14) ? x : z;
        double g = ((h & 1) ? -a : a) + ((h & 2) ? -b : b);
        double wx = ex ? smooth(u[0]) : 1 - smooth(u[0]);
        double wy = ey ? smooth(u[1]) : 1 - smooth(u[1]);
        double wz = ez ? smooth(u[2]) : 1 - smooth(u[2]);
        sum += wx * wy * wz * g;
    }
    return sum;
}

/* ---- filtered textures (docs/shading-model.md, "Filtered textures") ---- */

static int texture_filter = 1; /* --texture-filter off: 0, point samples */

static double triangle(double y) /* the integral of the square wave: 1 - |(y mod 2) - 1| */
{
    double m = y - 2 * floor(y / 2);
    return 1 - fabs(m - 1);
}

/* the mean of the square wave (+1 on even cells) over [x - h, x + h] */
static double square_mean(double x, double h)
{
    if (floor(x - h) == floor(x + h))
        return fmod(floor(x), 2) != 0 ? -1 : 1;
    return (triangle(x + h) - triangle(x - h)) / (2 * h);
}

/* the integral of |2 frac(y) - 1| from 0 */
static double stripes_integral(double y)
{
    double n = floor(y), f = y - n;
    return n / 2 + (f <= 0.5 ? f - f * f : 0.25 + (f - 0.5) * (f - 0.5));
}

/* the mean of |2 frac(y) - 1| over [y - h, y + h] */
static double stripes_mean(double y, double h)
{
    double lo = y - h, hi = y + h;
    if (floor(2 * lo) == floor(2 * hi)) /* one straight piece */
        return fabs(2 * (y - floor(y)) - 1);
    return (stripes_integral(hi) - stripes_integral(lo)) / (2 * h);
}

static double fade_octave(double x) { return fmin(1, fmax(0, 2 - 2 * x)); }

/* Half-extents along the axes, in cells of `size`, of the ellipse where a
 * cone of width w along d meets the surface of normal n (facing d). */
static void extents(double size, Vec d, Vec n, double w, double h[3])
{
    double rho = fmin(fabs(w) / (2 * size), 1024), cs = -dot(d, n), c = fmax(cs, 1.0 / 256);
    Vec T = add(d, mul(n, cs));
    int a;
    for (a = 0; a < 3; a++) {
        double na = comp(n, a), ta = comp(T, a);
        h[a] = fmin(rho * sqrt(c * c * (1 - na * na) + ta * ta) / c, 1024);
    }
}

/* C at P, seen along d on the surface of normal n by a cone of width w */
static Vec colour_at(const Material *m, Vec P, Vec d, Vec n, double w)
{
    double h[3] = { 0, 0, 0 };
    if (m->tex != TEX_NONE && w != 0)
        extents(m->size, d, n, w, h);
    if (m->tex == TEX_CHECKER) {
        double prod = 1;
        int i;
        for (i = 0; i < 3; i++)
            if (m->axes >> i & 1)
                prod *= square_mean(comp(P, i) / m->size, h[i]);
        return add(m->ca, mul(sub(m->cb, m->ca), (1 - prod) / 2));
    }
    if (m->tex == TEX_MARBLE) {
        Vec q = mul(P, 1 / m->size);
        double rho = fmax(h[0], fmax(h[1], h[2]));
        double o1 = fade_octave(2 * rho), o2 = fade_octave(4 * rho);
        double nz = (o1 > 0 ? o1 * noise(q) : 0) + (o2 > 0 ? o2 * noise(mul(q, 2)) / 2 : 0);
        double y = q.x + m->amount * nz;
        double k = stripes_mean(y, h[0] + m->amount * rho * (o1 + o2));
        return add(m->ca, mul(sub(m->cb, m->ca), k));
    }
    return m->c;
}

static Vec missed(Vec d)
{
    if (!sky_on)
        return bg;
    return add(sky_zenith, mul(sub(sky_horizon, sky_zenith), pow(1 - fmax(0, dot(d, sky_up)), sky_exp)));
}

/* ---- shading ---------------------------------------------------------- */

/* Snell's law about n (n . d < 0); 0 on total internal reflection. */
static int refract(Vec d, Vec n, double eta, Vec *out)
{
    double ci = -dot(d, n), k = 1 - eta * eta * (1 - ci * ci);
    if (k < 0)
        return 0;
    *out = norm(add(mul(d, eta), mul(n, eta * ci - sqrt(k))));
    return 1;
}

/* The colour along o + t d; the ray's cone has width w0 at o and grows
 * by spread a unit of t. */
static Vec trace(Vec o, Vec d, int depth, double w0, double spread)
{
    double t, I = nlights ? sqrt((double)nlights) / (2.0 * (double)nlights) : 0;
    long h = nearest(o, d, INFINITY, 0, &t);
    const Prim *p;
    const Material *m;
    Vec P, ng, ngo, n, col, out, C;
    size_t i;
    int entering;
    double w, bend;
    if (h < 0)
        return missed(d);
    p = &prims[h];
    m = &p->m;
    P = add(o, mul(d, t));
    n = normal_at(p, P, &ng);
    entering = dot(d, ng) < 0;
    ngo = entering ? ng : mul(ng, -1); /* geometric normal facing the ray */
    if (dot(n, d) > 0)
        n = mul(n, -1);
    /* secondary rays on the side they leave, clear of the surface */
    out = add(P, mul(ngo, eps_offset));
    w = w0 + spread * t; /* the cone's width at P */
    /* its bend: w times the curvature, +-1/r on a sphere (+ from outside) */
    bend = p->kind == SPHERE ? (entering ? w / p->r : -w / p->r) : 0;
    C = colour_at(m, P, d, n, w);
    col = mul(C, I * m->kd);
    for (i = 0; i < nlights; i++) {
        Vec L = norm(sub(lights[i].pos, P)), toward = sub(lights[i].pos, out), R;
        double nl = dot(n, L), dist = len(toward), rv, spec = 0, dummy;
        /* patch policy: the light must be above both the shading and the
         * geometric surface (for s, c, p they are the same) */
        if (nl <= 0 || dot(ngo, L) <= 0)
            continue;
        if (dist > 0 && nearest(out, mul(toward, 1 / dist), dist, 1, &dummy) >= 0)
            continue;
        R = sub(mul(n, 2 * nl), L);
        rv = -dot(R, d);
        if (m->ks != 0 && rv > 0)
            spec = m->ks * pow(rv, m->shine);
        col = add(col, mul(vmul(lights[i].col, add(mul(C, m->kd * nl), vec(spec, spec, spec))), I));
    }
    if (depth < max_depth) {
        if (m->ks > 0) {
            Vec r = sub(d, mul(n, 2 * dot(d, n)));
            /* patch policy: a mirror ray that would enter the geometric
             * surface is mirrored about the geometric normal instead */
            if (dot(r, ngo) <= 0)
                r = sub(d, mul(ngo, 2 * dot(d, ngo)));
            col = add(col, mul(trace(out, norm(r), depth + 1, w, spread + 2 * bend), m->ks));
        }
        if (m->t > 0) {
            double eta = entering ? 1 / m->ior : m->ior;
            Vec dir;
            /* patch policy: a refracted ray must cross the geometric
             * surface; if it would not, refract about Ng instead */
            int ok = refract(d, n, eta, &dir);
            if (ok && dot(dir, ngo) >= 0)
                ok = refract(d, ngo, eta, &dir);
            if (ok) { /* else total internal reflection: no ray */
                Vec in = sub(P, mul(ngo, eps_offset));
                double ci = -dot(d, n), ct = -dot(dir, n);
                col = add(col, mul(trace(in, dir, depth + 1, w, eta * spread + (eta * ci - ct) * bend), m->t));
            }
        }
    }
    return col;
}

static double clamp01(double c)
{
    return c > 0 ? (c < 1 ? c : 1) : 0; /* a NaN would become 0 */
}

static unsigned char byte(double c)
{
    return (unsigned char)floor(255 * clamp01(c) + 0.5);
}

/* ---- main ------------------------------------------------------------- */

static void usage(void)
{
    fputs("usage: ref_tracer SCENE.nff -o OUT.ppm [--size WxH] [--depth N] [--spp N] [--far F|rule] [--texture-filter on|off]\n", stderr);
    exit(2);
}

static long whole(const char *s, char **end, long lo, long hi)
{
    long x;
    if (*s < '0' || *s > '9')
        usage();
    x = strtol(s, end, 10);
    if (x < lo || x > hi)
        usage();
    return x;
}

int main(int argc, char **argv)
{
    const char *scene = NULL, *outname = NULL;
    long sx = 0, sy = 0, spp = 1;
    int i, j, X, Y, big;
    double s, pi = acos(-1.0);
    Vec w, u, v;
    unsigned char *row;
    FILE *f;
    for (i = 1; i < argc; i++) {
        char *end;
        if (!strcmp(argv[i], "-o") && i + 1 < argc) {
            outname = argv[++i];
        } else if (!strcmp(argv[i], "--size") && i + 1 < argc) {
            sx = whole(argv[++i], &end, 1, 16384);
            if (*end != 'x')
                usage();
            sy = whole(end + 1, &end, 1, 16384);
            if (*end)
                usage();
        } else if (!strcmp(argv[i], "--depth") && i + 1 < argc) {
            max_depth = (int)whole(argv[++i], &end, 1, 100);
            if (*end)
                usage();
        } else if (!strcmp(argv[i], "--far") && i + 1 < argc) {
            if (!strcmp(argv[++i], "rule")) {
                far_rule = 1;
                continue;
            }
            far_cube = strtod(argv[i], &end);
            if (*end || !(far_cube > 0))
                usage();
        } else if (!strcmp(argv[i], "--spp") && i + 1 < argc) {
            spp = whole(argv[++i], &end, 1, 64);
            if (*end)
                usage();
        } else if (!strcmp(argv[i], "--texture-filter") && i + 1 < argc) {
            i++;
            if (strcmp(argv[i], "on") && strcmp(argv[i], "off"))
                usage();
            texture_filter = !strcmp(argv[i], "on");
        } else if (argv[i][0] != '-' && !scene) {
            scene = argv[i];
        } else {
            usage();
        }
    }
    if (!scene || !outname)
        usage();
    read_scene(scene);
    if (far_rule) {
        far_cube = rule_far_cube();
        fprintf(stderr, "far cube %g\n", far_cube);
    }
    X = sx ? (int)sx : resx;
    Y = sx ? (int)sy : resy;

    /* Tolerances from double precision only, relative to the scene's
     * extent E. A computed hit point is off its surface by rounding error
     * of order 1e-15 E. Secondary rays start 1e-9 E off the surface, on
     * the side they leave: a million times that error, so they never hit
     * their own surface again by rounding, yet far below any feature of a
     * scene or a pixel's footprint (only things within 1e-9 E of the hit
     * point are treated as the same surface). Hits count from t > 1e-12 E,
     * below the offset (so nothing beyond it is lost) but above the error
     * of a computed t near zero. Changing the offset 10x either way leaves
     * the SPD images within 1/255. */
    if (extent == 0)
        extent = 1;
    eps_offset = 1e-9 * extent;
    eps_t = 1e-12 * extent;
    if (getenv("REF_TRACER_EPS_SCALE")) /* for self-consistency checks */
        eps_offset *= atof(getenv("REF_TRACER_EPS_SCALE"));

    w = norm(sub(at, from));
    u = norm(cross(w, up));
    v = cross(u, w);
    big = X > Y ? X : Y;
    s = big > 1 ? 2 * tan(angle * pi / 360) / (big - 1) : 0;

    f = fopen(outname, "wb");
    if (!f) {
        fprintf(stderr, "%s: cannot write\n", outname);
        return 1;
    }
    row = malloc((size_t)X * 3);
    if (!row) {
        fputs("ref_tracer: out of memory\n", stderr);
        fclose(f);
        return 1;
    }
    fprintf(f, "P6\n%d %d\n255\n", X, Y);
    for (j = 0; j < Y; j++) {
        for (i = 0; i < X; i++) {
            /* the pixel-area image: the mean of spp x spp samples at the
             * centres of equal cells of the pixel's square, each clamped
             * (--spp 1: the pixel's centre alone) */
            Vec sum = vec(0, 0, 0);
            int a, b;
            for (b = 0; b < spp; b++) {
                for (a = 0; a < spp; a++) {
                    double x = i - 0.5 + (a + 0.5) / spp, y = j - 0.5 + (b + 0.5) / spp;
                    Vec dir = norm(add(w, add(mul(u, (x - (X - 1) / 2.0) * s), mul(v, -(y - (Y - 1) / 2.0) * s))));
                    Vec c = trace(from, dir, 1, 0, texture_filter ? s / spp : 0);
                    sum = add(sum, vec(clamp01(c.x), clamp01(c.y), clamp01(c.z)));
                }
            }
            sum = mul(sum, 1.0 / (double)(spp * spp));
            row[3 * i] = byte(sum.x);
            row[3 * i + 1] = byte(sum.y);
            row[3 * i + 2] = byte(sum.z);
        }
        fwrite(row, 3, (size_t)X, f);
    }
    free(row);
    if (ferror(f) | fclose(f)) {
        fprintf(stderr, "%s: write failed\n", outname);
        return 1;
    }
    free(prims);
    free(verts);
    free(norms);
    free(lights);
    free(text);
    return 0;
}
