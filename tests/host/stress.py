#!/usr/bin/env python3
"""Numerical stress suite: the fixed build against the exact double
reference (tolerances from double precision) where fixed point is weakest (make stress; `--quick` runs inside make test).

Every image case renders a generated scene with the fixed and the double
build of `rt` built with FX_COUNT_SATURATIONS=1 and sanitisers, and checks
the tolerance stated in its row. Ends with a summary table (case, max
error, pixels over tolerance, saturation events) and "N passed, M failed".
"""
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from check import check, summary  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RT = os.path.join(ROOT, "build", "stress", "rt")
FUZZ = os.path.join(ROOT, "build", "stress", "test_rayfuzz")
OUT = os.path.join(ROOT, "build", "stress-out")
QUICK = "--quick" in sys.argv
SIZE = "64x64" if QUICK else "128x128"
rows = []


def spd(name):
    with open(os.path.join(ROOT, "scenes", "spd", name + ".nff")) as f:
        return f.read()


def fmt(v):
    return "%.9g" % v


def transform_positions(text, fn):
    """Applies fn to every position (and length) of an NFF text: from, at,
    light positions, sphere centres and radii, cone ends and radii, polygon
    and patch vertices. Colours, materials, normals and the up vector stay."""
    out, pending, kind = [], 0, None
    for line in text.splitlines():
        tok = line.split()
        if not tok:
            out.append(line)
            continue
        head = tok[0]
        if pending and re.match(r"^[-+.0-9]", head):
            nums = [float(t) for t in tok]
            if kind in ("p", "pp"):
                nums[0:3] = fn(nums[0:3])
                pending -= 1
                out.append(" ".join(fmt(v) for v in nums))
                continue
        if head in ("from", "at"):
            out.append(head + " " + " ".join(fmt(v) for v in fn([float(t) for t in tok[1:4]])))
        elif head == "l":
            nums = [float(t) for t in tok[1:]]
            nums[0:3] = fn(nums[0:3])
            out.append("l " + " ".join(fmt(v) for v in nums))
        elif head == "s":
            c = fn([float(t) for t in tok[1:4]])
            r = fn.scale_length(float(tok[4]))
            out.append("s " + " ".join(fmt(v) for v in c + [r]))
        elif head == "c" and len(tok) == 9:
            n = [float(t) for t in tok[1:]]
            out.append("c " + " ".join(fmt(v) for v in fn(n[0:3]) + [fn.scale_length(n[3])] + fn(n[4:7]) +
                                       [fn.scale_length(n[7])]))
        elif head in ("p", "pp"):
            pending, kind = int(tok[1]), head
            out.append(line)
        else:
            out.append(line)
    return "\n".join(out) + "\n"


class Scale:
    def __init__(self, f):
        self.f = f

    def __call__(self, v):
        return [x * self.f for x in v]

    def scale_length(self, r):
        return r * self.f


def write(name, text):
    path = os.path.join(OUT, re.sub(r"[^A-Za-z0-9.+-]+", "_", name) + ".nff")
    with open(path, "w") as f:
        f.write(text)
    return path


def render(path, backend, size=None, extra=()):
    png = path[:-4] + "-" + backend + ".png"
    r = subprocess.run([RT, path, "-o", png, "--" + backend, "--size", size or SIZE, "--stats", "--quiet"] +
                       list(extra), capture_output=True, text=True)
    if r.returncode != 0:
        raise RuntimeError(r.stderr.strip())
    stats = {}
    for line in r.stderr.splitlines():
        m = re.match(r"^([a-z0-9_]+)\s+(-?\d+)$", line)
        if m:
            stats[m.group(1).strip()] = int(m.group(2))
    return png, stats


def compare(a, b):
    line = subprocess.run([RT, "compare", a, b], capture_output=True, text=True).stdout
    m = re.search(r"psnr (\S+) dB\s+max-error (\d+)\s+over2 ([0-9.]+)%\s+over8 ([0-9.]+)%", line)
    psnr = math.inf if m.group(1) == "inf" else float(m.group(1))
    return psnr, int(m.group(2)), float(m.group(3)), float(m.group(4))


def image_case(name, text, psnr_min=40.0, over8_max=0.5, depth=None, check=None, warn=None):
    path = write(name, text)
    extra = ["--depth", str(depth)] if depth else []
    try:
        f, fs = render(path, "fixed", extra=extra)
        d, ds = render(path, "double", extra=extra)
    except RuntimeError as e:
        rows.append((name, False, "render failed: %s" % e, "-", "-", "-"))
        return None
    if warn is not None:
        def check(fp, dp, fs_, ds_, expect=warn):
            r = subprocess.run([RT, path, "-o", fp, "--fixed", "--size", SIZE, "--quiet"],
                               capture_output=True, text=True)
            return expect in r.stderr, "warns: %s" % (r.stderr.strip().split(": ", 1)[-1] or "(nothing)")
    psnr, maxe, o2, o8 = compare(f, d)
    sat = fs.get("saturations", -1)
    ok = psnr >= psnr_min and o8 <= over8_max and sat == 0
    note = "PSNR %s dB (>= %g), >8/255 %.3f%% (<= %g%%), no saturation" % (
        "inf" if psnr == math.inf else "%.1f" % psnr, psnr_min, o8, over8_max)
    if check:
        ok2, extra_note = check(f, d, fs, ds)
        ok = ok and ok2
        note += "; " + extra_note
    rows.append((name, ok, note, "%d/255" % maxe, "%.3f%%" % o8, str(sat)))
    return f, d, fs, ds


def error_case(name, text, expect):
    path = write(name, text)
    never = os.path.join(OUT, "never.png")
    if os.path.exists(never):
        os.remove(never)
    r = subprocess.run([RT, path, "-o", never], capture_output=True, text=True)
    msg = r.stderr.strip()
    ok = r.returncode == 2 and expect in msg and not os.path.exists(never)
    rows.append((name, ok, "rejected: %s" % msg.replace(OUT + "/", ""), "-", "-", "-"))


VIEW = "v\nfrom %s\nat %s\nup 0 0 1\nangle %s\nhither 1\nresolution 64 64\n"


def view(frm, at, angle=45):
    return VIEW % (" ".join(fmt(v) for v in frm), " ".join(fmt(v) for v in at), fmt(angle))


# ---- cases ----------------------------------------------------------------

def scale_sweep():
    exps = [-3, 0, 3] if QUICK else [-3, -2, -1, 0, 1, 2, 3]
    for base in ("balls-2", "teapot-1"):
        text = spd(base)
        for e in exps:
            image_case("scale %s x1e%+d" % (base, e), transform_positions(text, Scale(10.0 ** e)),
                       psnr_min=50, over8_max=0.25)
    # where the range ends: reported, not rendered
    error_case("scale balls-2 x1e+4 (too large)", transform_positions(spd("balls-2"), Scale(1e4)),
               "scene too large for the fixed range")
    error_case("scale balls-2 x1e-10 (too small)", transform_positions(spd("balls-2"), Scale(1e-10)),
               "scene too small for the fixed range")


def far_lights(text, dist):
    out = []
    for line in text.splitlines():
        tok = line.split()
        if tok and tok[0] == "l":
            p = [float(t) for t in tok[1:4]]
            n = math.sqrt(sum(x * x for x in p))
            out.append("l " + " ".join(fmt(x * dist / n) for x in p) + (" " + " ".join(tok[4:]) if len(tok) > 4 else ""))
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def far_camera(text, dist):
    lines = text.splitlines()
    frm = at = None
    for line in lines:
        tok = line.split()
        if tok and tok[0] == "from":
            frm = [float(t) for t in tok[1:4]]
        if tok and tok[0] == "at":
            at = [float(t) for t in tok[1:4]]
    d0 = math.sqrt(sum((a - b) ** 2 for a, b in zip(frm, at)))
    new = [a + (f - a) * dist / d0 for f, a in zip(frm, at)]
    out = []
    for line in lines:
        tok = line.split()
        if tok and tok[0] == "from":
            out.append("from " + " ".join(fmt(x) for x in new))
        elif tok and tok[0] == "angle":
            a = math.degrees(2 * math.atan(math.tan(math.radians(float(tok[1]) / 2)) * d0 / dist))
            out.append("angle " + fmt(a))
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def distant():
    # Far lights and cameras: they may lie up to 32 times farther out than
    # the geometry before it gives up bits (include/rt_config.h).
    for dist in (100, 1000):
        image_case("lights %d units away (balls-2)" % dist, far_lights(spd("balls-2"), dist), psnr_min=50.0,
                   over8_max=0.25)
    # Eye rays are built through a point near the scene and start at its
    # bounds (camera.c), so a far camera's rounded directions err only
    # across the scene: 100 units away meets the image tests' tolerance.
    image_case("camera 100 units away (balls-2)", far_camera(spd("balls-2"), 100), psnr_min=50.0,
               over8_max=0.25)
    # Wide lenses: up to 150 degrees eye rays go through a point at the
    # distance of `at`, beyond at unit distance (camera.c); both sides.
    for angle in (150, 170, 179):
        text = "\n".join(("angle %d" % angle) if l.startswith("angle") else l
                         for l in spd("balls-2").splitlines()) + "\n"
        image_case("lens of %d degrees (balls-2)" % angle, text, psnr_min=50.0, over8_max=0.25)
    image_case("camera 1000 units away (balls-2)", far_camera(spd("balls-2"), 1000), psnr_min=50.0,
               over8_max=0.25)
    # Where the range ends: the camera and lights may lie 32 times farther
    # out than the geometry (RT_FAR_EXTENT_LOG2); 10000 units from this
    # scene the geometry keeps 5 fewer bits: edges get noisy (not garbage)
    # and rt says so.
    image_case("camera 10000 units away (balls-2): range end", far_camera(spd("balls-2"), 10000),
               psnr_min=45, over8_max=0.5, warn="fewer bits")


def icosphere(levels):
    t = (1 + 5 ** 0.5) / 2
    v = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
         (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    v = [tuple(c / math.sqrt(sum(x * x for x in p)) for c in p) for p in v]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
         (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
         (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    for _ in range(levels):
        cache, nf = {}, []

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in cache:
                p = [(x + y) / 2 for x, y in zip(v[a], v[b])]
                n = math.sqrt(sum(c * c for c in p))
                v.append(tuple(c / n for c in p))
                cache[key] = len(v) - 1
            return cache[key]
        for a, b, c in f:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            nf += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        f = nf
    return v, f


def crack_count(fixed_png, double_png):
    """Pixels inside the mesh's outline (the double image shows the mesh
    there and at all 8 neighbours) where the fixed image shows the magenta
    background: rays slipping between two polygons. Outline pixels are
    silhouette decisions, not cracks."""
    a, b = ppm_pixels(fixed_png), ppm_pixels(double_png)
    n = int(len(b) ** 0.5)
    bg = (255, 0, 255)
    cracks = interior = 0
    for y in range(1, n - 1):
        for x in range(1, n - 1):
            if any(b[(y + dy) * n + x + dx] == bg for dy in (-1, 0, 1) for dx in (-1, 0, 1)):
                continue
            interior += 1
            cracks += a[y * n + x] == bg
    return cracks, interior


def ppm_pixels(png):
    """The pixels of the PPM twin of a rendered PNG (see grazing())."""
    with open(png[:-4] + ".ppm", "rb") as f:
        data = f.read()
    parts = data.split(b"\n", 3)
    w, h = map(int, parts[1].split())
    px = parts[3]
    return [tuple(px[3 * i:3 * i + 3]) for i in range(w * h)]


def grazing():
    # a floor seen edge-on, with a sphere and a cylinder lying on it
    text = ("b 0.2 0.3 0.5\n" + view([0, -20, 0.05], [0, 0, 0.05], 30) + "l 5 -10 0.6\nl -8 -4 3\n"
            "f 0.9 0.8 0.6 0.8 0.2 20 0 1\np 4\n-50 -50 0\n50 -50 0\n50 50 0\n-50 50 0\n"
            "f 0.3 0.6 0.9 0.7 0.3 50 0 1\ns -1 0 1 1\nc 1.5 -1 0.5 0.5 1.5 3 0.5 0.5\n")
    image_case("grazing: floor edge-on, tangent sphere/cylinder", text)
    # a closed mesh of 80 (quick) / 320 triangles against a magenta background
    v, f = icosphere(1 if QUICK else 2)
    mesh = "b 1 0 1\n" + view([0.3, -3.2, 1.1], [0, 0, 0], 45) + "l 4 -6 5\nf 0.8 0.8 0.8 0.9 0.1 10 0 1\n"
    for a, b, c in f:
        mesh += "p 3\n" + "\n".join(" ".join(fmt(x) for x in v[i]) for i in (a, b, c)) + "\n"
    path = write("closed mesh", mesh)

    def check(fp, dp, fs, ds):
        for png, be in ((fp, "fixed"), (dp, "double")):
            subprocess.run([RT, path, "-o", png[:-4] + ".ppm", "--" + be, "--size", SIZE, "--quiet"], check=True)
        cracks, covered = crack_count(fp, dp)
        return cracks == 0, "%d crack pixels of %d inside the mesh's outline (must be 0)" % (cracks, covered)
    image_case("closed mesh: %d triangles, cracks" % len(f), mesh, check=check)


def acne():
    for elev in (1.0, 5.0):
        h = math.tan(math.radians(elev)) * 30
        text = ("b 0 0 0\n" + view([0, -6, 3], [0, 0, 0.5], 45) + "l 30 0 %s\n" % fmt(h) +
                "f 0.9 0.9 0.9 1 0 1 0 1\np 4\n-10 -10 0\n10 -10 0\n10 10 0\n-10 10 0\n"
                "f 0.9 0.5 0.3 1 0 1 0 1\ns 0 0 1 1\ns -2 1 0.5 0.5\n")
        image_case("self-shadowing: light %g deg above the floor" % elev, text, over8_max=0.3)


def materials():
    text = "b 0.1 0.1 0.1\n" + view([0, -14, 6], [0, 0, 0], 40) + "l -6 -10 12\nl 8 -6 6\n"
    text += "f 0.5 0.5 0.5 0.8 0 1 0 1\np 4\n-20 -20 -1\n20 -20 -1\n20 20 -1\n-20 20 -1\n"
    shines = [1, 10, 100, 1000, 10000, 100000]
    for i, s in enumerate(shines):
        text += "f 0.9 0.3 0.2 0.6 1 %s 0 1\ns %s -3 0 0.8\n" % (fmt(s), fmt(-6.25 + 2.5 * i))
    for i, ior in enumerate([1.0, 1.33, 1.5, 2.0, 2.5]):
        text += "f 0.9 0.9 0.9 0 0 1 1 %s\ns %s 0 0 0.9\n" % (fmt(ior), fmt(-5 + 2.5 * i))
    text += "f 0.2 0.9 0.3 1 0 1 0 1\ns -3 3 0 0.8\nf 0.2 0.3 0.9 0 1 1 0 1\ns 0 3 0 0.8\n"
    text += "f 0.9 0.9 0.2 0 0 1 1 1.5\np 4\n1.5 2.5 -0.9\n5 2.5 -0.9\n5 4 2\n1.5 4 2\n"
    image_case("materials: Phong 1..1e5, Ks/T 0 and 1, ior 1.0..2.5", text)


def recursion():
    rays = {}

    def bounded(fp, dp, fs, ds):
        eye = fs.get("eye_rays", 0)
        sec = fs.get("reflect_rays", 0) + fs.get("refract_rays", 0)
        limit = eye * (2 ** 5 - 2)  # two children per ray, depth 5
        return sec <= limit, "secondary rays %d <= %d (depth 5 bound)" % (sec, limit)
    mirrors = ("b 0 0 0\n" + view([0.5, -1.5, 0.3], [0, 3, 0], 60) + "l 0 0 2.5\n"
               "f 1 1 1 0.05 1 50 0 1\np 4\n-3 -3 -1\n3 -3 -1\n3 3 -1\n-3 3 -1\n"
               "p 4\n-3 -3 1\n-3 3 1\n3 3 1\n3 -3 1\nf 0.9 0.2 0.2 0.8 0.2 10 0 1\ns 0 2 0 0.4\n")
    image_case("facing mirrors, depth 5", mirrors, check=bounded)
    glass = ("b 0.2 0.4 0.7\n" + view([0, -5, 1], [0, 0, 0], 40) + "l -3 -6 6\n"
             "f 0.9 0.9 0.9 0.8 0 1 0 1\np 4\n-10 -10 -1.5\n10 -10 -1.5\n10 10 -1.5\n-10 10 -1.5\n"
             "f 1 1 1 0 0.1 50 1 1.5\ns 0 0 0 1.4\nf 1 1 1 0 0.1 50 1 1.33\ns 0 0 0 0.8\n"
             "f 0.9 0.2 0.2 0.8 0.2 10 0 1\ns 0 0 0 0.3\n")
    image_case("glass sphere in glass sphere, depth 5", glass, check=bounded)


def degenerate():
    base = view([0, -5, 0], [0, 0, 0]) + "f 1 1 1 1 0 1 0 1\n"
    error_case("degenerate: zero radius", base + "s 0 0 0 0\n", "sphere radius is zero")
    error_case("degenerate: cone base = apex", base + "c 1 1 1 0.5 1 1 1 0.2\n", "cone base and apex are the same point")
    error_case("degenerate: collinear first vertices", base + "p 4\n0 0 0\n1 0 0\n2 0 0\n0 0 1\n",
               "polygon's first three vertices are collinear")
    v = "v\nfrom 0 -5 0\nat 0 0 0\nup %s\nangle %s\nhither 1\nresolution 8 8\n"
    error_case("degenerate: zero up vector", v % ("0 0 0", "45"), "'up' is zero or parallel")
    error_case("degenerate: up parallel to view", v % ("0 2 0", "45"), "'up' is zero or parallel")
    error_case("degenerate: angle 0", v % ("0 0 1", "0"), "angle must be between 0 and 180")
    error_case("degenerate: angle 180", v % ("0 0 1", "180"), "angle must be between 0 and 180")


def fuzz():
    n = 100000 if QUICK else 1000000
    r = subprocess.run([FUZZ, str(n)], capture_output=True, text=True)
    fails = [l for l in r.stdout.splitlines() if "FAIL" in l]
    sat = re.search(r"saturations during the fuzz: (\d+)", r.stdout)
    worst = max((float(x) for x in re.findall(r"worst t error ([0-9.]+) of", r.stdout)), default=-1)
    rows.append(("random-ray fuzz: %d rays, fixed vs double" % n, r.returncode == 0 and not fails,
                 "hit/miss, t and normal bounds of tests/unit/test_rayfuzz.c; worst t error %.2f of bound" % worst
                 + ("; " + "; ".join(fails) if fails else ""), "-", "-", sat.group(1) if sat else "?"))


def main():
    os.makedirs(OUT, exist_ok=True)
    for case in (scale_sweep, distant, grazing, acne, materials, recursion, degenerate, fuzz):
        case()
    w = max(len(r[0]) for r in rows)
    print("        %-*s  %-9s  %-12s  %-11s  %s" % (w, "case", "max err", ">8/255 px", "saturations", "detail"))
    for name, ok, note, maxe, over, sat in rows:
        check(ok, "%-*s  %-9s  %-12s  %-11s  %s" % (w, name, maxe, over, sat, note))
    return summary("stress-quick" if QUICK else "stress")


if __name__ == "__main__":
    sys.exit(main())
