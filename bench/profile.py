#!/usr/bin/env python3
"""Where a render's instructions go on a board: per function, group and ray kind.

    bench/profile.py FIRMWARE.elf [--machine mps2-an385] [--sink stream_begin,stream_flush,stream_end]
                     [--top N] [--json OUT.json] [--check]
    bench/profile.py --log QEMU.log --stream UART.out FIRMWARE.elf ...   (a saved log)
    make profile SCENE=.. [BOARD=..] [SIZE=..] [BACKEND=..] [DEPTH=..]     (builds, then runs this)

It runs the firmware under QEMU as bench/cycles.py does (-d in_asm,exec,nochain
through a pipe, -icount shift=0) with cycles.py's parser, and counts every
instruction executed inside rt_render, the display sink's callbacks (--sink)
apart as the firmware's own count has them: the same total as cycles.py
--from-symbol rt_render, which the firmware's render_instructions confirms.

Ray kinds. A shadow stack of the frames of rt_render, rt_trace_ray (a
pixel's ray tree, walked without recursion), trace_segment (one ray of it),
rt_scene_occluded and the sink callbacks (cycles.Extents: a frame is pushed
when a call reaches the function's entry and popped when a return reaches the
call's fall-through) says which ray each instruction works for:
  eye         inside the first trace_segment of a trace_ray called by rt_render;
  reflection  inside a trace_segment after trace_ray called count_reflect_ray()
              (the counter of the mirror rays it goes on with);
  refraction  inside a trace_segment after count_refract_ray();
  shadow      inside scene_occluded (called by trace_segment for each light
              above the surface): the occlusion test only;
  frame       inside rt_render but outside any ray: frame set-up, the pixel
              loop, camera rays, packing pixels, handing bands to the sink.
The innermost such frame wins: the shading of a reflection ray's hit point
(its direct light, the mirror direction of its own children) is reflection
work, its shadow rays' occlusion tests are shadow work. trace_ray's own
instructions between segments (the walk, adding a child's colour to its
parent's) go to the kind of the segment it called last. Which ray a
trace_segment call traces is told by which counter the trace_ray frame called
last (also under GCC's clone names such as count_reflect_ray.constprop.0), so
code layout does not matter.

Checks (printed; --check makes a failure the exit status):
  - the total is within 0.1% of the firmware's render_instructions;
  - trace_segment entries per kind equal the firmware's counters eye_rays,
    reflect_rays and refract_rays, and scene_occluded entries equal
    shadow_rays (shadow_rays also counts lights a patch hides from itself,
    which trace no ray: with patches, entries <= shadow_rays);
  - every trace_segment entry was classified.

Groups: GROUPS below maps function names (without the rt_ prefix and GCC's
.isra/.part/.constprop suffixes; shell patterns, first match wins) to groups;
a function in none is listed under "other" so the table can be extended.
Estimated cycles are bench/cycles.py's model (typ), for comparison only.
"""
import argparse
import collections
import fnmatch
import os
import re
import sys
import time

sys.dont_write_bytecode = True  # no bench/__pycache__ in the work tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cycles  # noqa: E402

# group, what it holds, name patterns (first match over the list wins)
GROUPS = [
    ("traversal", "BVH traversal, box tests, the dispatch to primitives",
     ["scene_nearest*", "scene_occluded", "slab_*", "enter_root", "hit_prim", "bvh_*", "unbounded_*"]),
    ("flat", "a one-leaf scene searched kind by kind, the primitives' tests inline in it",
     ["flat_nearest*", "flat_occluded*", "scene_fold_stats", "eye_row_setup"]),
    ("sphere", "ray-sphere intersection", ["ray_hit_sphere", "sphere_prim_hit"]),
    ("plane", "ray-plane intersection", ["ray_hit_plane", "plane_hit_inside"]),
    ("polygon", "ray-polygon and patch intersection, inside tests",
     ["ray_hit_polygon", "even_odd_axis", "inside_*", "edge_fn", "edge_side", "fan_triangle", "project_axis",
      "vertex_before", "is_zero"]),
    ("cone", "ray-cone/cylinder intersection", ["ray_hit_cone", "cylinder_missed", "quotient_below", "refine_root"]),
    ("shading", "the tracer, hit surface and normals, lights, secondary rays",
     ["trace_ray", "trace_segment", "count_re*_ray", "colour_*", "find_surface", "surface_at", "direct_light", "add_light", "mirror_dir", "reflected", "refracted", "leave", "snell",
      "worth_tracing", "prim_surface", "object_prim_surface", "sphere_normal", "cone_normal",
      "polygon_shading_normal", "shape_normal", "xform_normal"]),
    ("solids", "quadrics, tori, boxes, CSG, object-space rays and transforms",
     ["ray_hit_object", "solid_spans", "csg_*", "object_ray", "box_*", "quadric_*", "torus_*", "safe_div",
      "polish", "bnd", "to_world", "shape_*", "spans_*", "xform_*", "row_dot", "mat_mul", "mat_vec", "first_root",
      "corner_radius"]),
    ("texture", "textures and the sky", ["texture_colour*", "checker_at_point", "sky_colour", "checker", "marble", "noise",
                                         "lattice_hash", "gradient_dot", "fade", "lerp", "background"]),
    ("maths", "fixed-point and real operations, vectors, libgcc and soft-float helpers, libm",
     ["fx_*", "unit3_*", "isqrt*", "rsqrt*", "recip*", "clz*", "smul64", "sdiv64", "udiv64", "div_*", "wsqrt_*", "abs_u32", "sign_mask", "normalise_even", "log2_*", "exp2_*", "cos_q30",
      "sin_q30", "v3_*", "r_*", "two_*", "split12", "from_bits", "to_bits", "__*", ".udivsi3*",
      "pow", "powf", "sqrt", "sqrtf", "fabs", "fabsf", "finite", "finitef", "nan", "nanf", "rint", "rintf",
      "scalbn", "scalbnf", "copysign*"]),
    ("libc", "memcpy, memset (structure copies GCC emits)", ["memcpy", "memset", "memmove", "memcmp"]),
    ("output", "frame set-up and pixel loop, camera rays, pixel packing, band hand-over",
     ["render*", "camera_*", "scene_eye_setup", "wait_flushed", "corner_row", "spd_line", "plain_line", "put_pixel", "flush_band", "add_stats", "stats_add",
      "fb_*",
      # the sink's end of frame (and the output window sink_io_* opens
      # for it): rt_render tail-calls it, so it is no call counted apart
      # (cycles.py warns), and the firmware's count has it too
      "stream_*", "oled_*", "sink_io_*", "port_*", "report_*"]),
]
GROUP_ORDER = [g for g, _, _ in GROUPS] + ["other"]
GROUP_DOC = {g: d for g, d, _ in GROUPS}
GROUP_DOC["other"] = "in no group of GROUPS (bench/profile.py)"

KINDS = ["eye", "reflection", "refraction", "shadow", "frame"]
KIND_DOC = {
    "eye": "first trace_segment of a trace_ray",
    "reflection": "trace_segment after count_reflect_ray()",
    "refraction": "trace_segment after count_refract_ray()",
    "shadow": "scene_occluded (occlusion tests)",
    "frame": "rt_render outside any ray",
    "unclassified": "a later trace_segment with no counter call before it",
}
# firmware counter of each ray kind (include/rt_stats.h)
KIND_COUNTER = {"eye": "eye_rays", "reflection": "reflect_rays", "refraction": "refract_rays", "shadow": "shadow_rays"}
SINK_CALLBACKS = ["stream_begin", "stream_flush", "stream_end", "oled_begin", "oled_flush", "oled_end"]
CLONE_SUFFIX = re.compile(r"\.(isra|part|constprop|cold|lto_priv|clone|localalias)(\.\d+)*")
MAX_DIFF = 0.1  # percent


def base_name(sym):
    """rt_fx_div.part.0 -> fx_div: the source's name."""
    b = sym
    while True:
        s = CLONE_SUFFIX.sub("", b)
        if s == b:
            break
        b = s
    return b[3:] if b.startswith("rt_") else b


def group_of(sym):
    b = base_name(sym)
    for g, _, pats in GROUPS:
        for p in pats:
            if fnmatch.fnmatchcase(b, p):
                return g
    return "other"


class RayKinds(cycles.Extents):
    """cycles.Extents with the ray kinds as buckets (see the module docstring):
    frames of rt_render ("frame"), trace_ray and trace_segment (its kind),
    scene_occluded ("shadow") and the sink ("excluded"); entries of the ray
    counters only mark the trace_ray frame that calls them."""

    def __init__(self, root, trace, segments, occluded, sinks, marks, names):
        self.trace, self.occluded = trace, occluded
        self.segments = frozenset(segments)
        self.sinks = frozenset(sinks)
        self.marks = marks                     # entry PC -> "reflection" / "refraction"
        self.names = names                     # PC -> symbol, for warnings
        self.rays = collections.Counter()      # kind -> rays (trace_segment / scene_occluded entries)
        self.inner = [p for p in [trace, occluded] if p is not None] + sorted(self.segments) + sorted(self.sinks)
        super().__init__(root, self.sinks)

    def enterable(self):
        if not self.stack:
            return (self.root,)
        top = self.stack[-1]
        if top.kind in ("excluded", "shadow"):
            return ()
        if top.pc == self.trace:
            return tuple(self.inner) + tuple(self.marks)
        return tuple(self.inner)

    def enter(self, f):
        top = self.stack[-1] if self.stack else None
        if f.pc in self.marks:
            top.note = self.marks[f.pc]
            return False
        if f.pc == self.root:
            f.kind = "frame"
        elif f.pc in self.sinks:
            f.kind = "excluded"
        elif f.pc == self.occluded:
            f.kind = "shadow"
            self.rays["shadow"] += 1
        elif f.pc == self.trace:
            f.kind = "eye"  # until its first segment: the eye ray's
            f.note = "eye"
        elif f.pc in self.segments and top.pc == self.trace:
            f.kind = top.note or "unclassified"
            top.note = None
            top.kind = f.kind  # trace_ray's walk after it: this ray's
            self.rays[f.kind] += 1
        else:
            f.kind = top.kind
        return True

    def label(self):
        return self.stack[-1].kind if self.stack else "outside"

    def not_a_call(self, pc):
        return "entered %s not by a call: ignored" % self.names.get(pc, hex(pc))


def report_records(stream):
    """Every 'key value' report record ('T', length u16, text) of the board's output."""
    rec = {}
    for m in re.finditer(rb"T(..)([a-z][a-z0-9_]*) ([0-9]+)", stream, re.S):
        n = m.group(1)[0] | (m.group(1)[1] << 8)
        if n == len(m.group(2)) + 1 + len(m.group(3)):
            rec[m.group(2).decode()] = int(m.group(3))
    return rec


def scene_uses_patches(elf):
    """SCENE_USES_PATCHES of the scene_data.h beside the ELF (None: not found)."""
    try:
        with open(os.path.join(os.path.dirname(elf), "scene_data.h")) as f:
            m = re.search(r"#define SCENE_USES_PATCHES (\d)", f.read())
    except OSError:
        return None
    return int(m.group(1)) if m else None


def find(syms, pred):
    return sorted({a for a, n in syms if pred(n)})


def one(syms, name):
    pcs = find(syms, lambda n: n == name)
    return pcs[0] if pcs else None


def fmt(n):
    return "{:,}".format(n)


def profile(args, parser, model, syms, rk, extra):
    """Tally the buckets; return (text, data, failed checks)."""
    fw = extra.get("firmware", {})
    pixels = args.pixels or fw.get("pixels") or 1
    kinds = KINDS + (["unclassified"] if rk.rays.get("unclassified") else [])
    per = {}
    for k in kinds + ["excluded"]:
        per[k] = cycles.tally(parser, model, k, syms)
    total = sum(per[k]["instructions"] for k in kinds)
    cyc_total = sum(per[k]["cycles"]["typ"] for k in kinds)

    funcs = collections.defaultdict(lambda: {"instructions": 0, "cycles_typ": 0, "kinds": collections.Counter()})
    for k in kinds:
        for f, n in per[k]["func_insns"].items():
            funcs[f]["instructions"] += n
            funcs[f]["kinds"][k] += n
        for f, c in per[k]["funcs"].items():
            funcs[f]["cycles_typ"] += c
    for f, d in funcs.items():
        d["group"] = group_of(f)
    groups = collections.OrderedDict((g, {"instructions": 0, "cycles_typ": 0, "functions": []}) for g in GROUP_ORDER)
    matrix = collections.OrderedDict((g, collections.Counter()) for g in GROUP_ORDER)
    for f, d in sorted(funcs.items(), key=lambda kv: -kv[1]["instructions"]):
        g = groups[d["group"]]
        g["instructions"] += d["instructions"]
        g["cycles_typ"] += d["cycles_typ"]
        g["functions"].append(f)
        matrix[d["group"]].update(d["kinds"])

    # -- checks
    checks = []

    def check(ok, name, text):
        checks.append({"name": name, "ok": bool(ok), "text": text})

    ri = fw.get("render_instructions")
    if ri:
        diff = 100.0 * (total - ri) / ri
        check(abs(diff) <= MAX_DIFF, "total", "%s counted, the firmware's render_instructions %s: %+.4f%% (limit %g%%)"
              % (fmt(total), fmt(ri), diff, MAX_DIFF))
    else:
        check(False, "total", "the firmware reported no render_instructions")
    patches = scene_uses_patches(args.elf)
    for k in ("eye", "reflection", "refraction", "shadow"):
        key = KIND_COUNTER[k]
        got = rk.rays.get(k, 0)
        what = "scene_occluded entries" if k == "shadow" else "trace_segment entries"
        if key not in fw:
            check(False, k + " rays", "the firmware reported no %s" % key)
        elif k == "shadow" and patches != 0 and got <= fw[key]:
            check(True, k + " rays", "%s %s <= %s %s (%s: a light a patch hides from itself is "
                  "counted, no ray traced)" % (fmt(got), what, key, fmt(fw[key]),
                                               "the scene has patches" if patches else "scene_data.h not found"))
        else:
            check(got == fw[key], k + " rays", "%s %s, firmware's %s %s" % (fmt(got), what, key, fmt(fw[key])))
    unc = rk.rays.get("unclassified", 0)
    check(unc == 0, "classified", "%d later trace_segment entries without a ray counter call before"
          % unc if unc else "every trace_segment entry has its kind")
    failed = [c for c in checks if not c["ok"]]

    # -- text
    out = []
    sink = ", ".join(n for n in args.sink if one(syms, n) is not None) or "none"
    out.append("profile of %s (%s, core %s): inside rt_render, display sink (%s) apart" % (
        args.elf, args.machine, model.core, sink))
    out.append("%s pixels, %s instructions, %.1f per pixel; est. cycles (typ) %.1f per pixel" % (
        fmt(pixels), fmt(total), total / pixels, cyc_total / pixels))
    out.append("")
    out.append("checks")
    for c in checks:
        out.append("  %-5s %-16s %s" % ("ok" if c["ok"] else "FAIL", c["name"], c["text"]))
    out.append("")
    hdr = "%-12s %9s %8s %15s %10s %7s %10s %12s  %s"
    out.append(hdr % ("ray kind", "rays", "rays/px", "instructions", "instr/px", "share", "instr/ray",
                      "est.cyc/px", "what"))
    for k in kinds:
        n = per[k]["instructions"]
        r = rk.rays.get(k, 0) if k != "frame" else None
        out.append(hdr % (k, fmt(r) if r is not None else "-", "%.2f" % (r / pixels) if r is not None else "-",
                          fmt(n), "%.1f" % (n / pixels), "%.2f%%" % (100.0 * n / max(1, total)),
                          "%.1f" % (n / r) if r else "-", "%.1f" % (per[k]["cycles"]["typ"] / pixels), KIND_DOC[k]))
    out.append(hdr % ("total", "", "", fmt(total), "%.1f" % (total / pixels), "100.00%", "",
                      "%.1f" % (cyc_total / pixels), ""))
    out.append("")
    hdr = "%-12s %15s %10s %7s %12s  %s"
    out.append(hdr % ("group", "instructions", "instr/px", "share", "est.cyc/px", "what"))
    for g, d in groups.items():
        if not d["instructions"]:
            continue
        out.append(hdr % (g, fmt(d["instructions"]), "%.1f" % (d["instructions"] / pixels),
                          "%.2f%%" % (100.0 * d["instructions"] / max(1, total)),
                          "%.1f" % (d["cycles_typ"] / pixels), GROUP_DOC[g]))
    out.append(hdr % ("total", fmt(total), "%.1f" % (total / pixels), "100.00%", "%.1f" % (cyc_total / pixels), ""))
    out.append("")
    out.append("instructions per pixel by group and ray kind")
    cols = [k for k in kinds if per[k]["instructions"] or k in ("eye", "shadow")]
    hdr = "%-12s" + " %11s" * (len(cols) + 1)
    out.append(hdr % tuple(["group"] + cols + ["total"]))
    for g, row in matrix.items():
        if not groups[g]["instructions"]:
            continue
        out.append(hdr % tuple([g] + ["%.1f" % (row[k] / pixels) for k in cols]
                               + ["%.1f" % (groups[g]["instructions"] / pixels)]))
    out.append(hdr % tuple(["total"] + ["%.1f" % (per[k]["instructions"] / pixels) for k in cols]
                           + ["%.1f" % (total / pixels)]))
    out.append("")
    hdr = "%-30s %-10s %15s %10s %7s"
    out.append(hdr % ("function", "group", "instructions", "instr/px", "share"))
    listed = sorted(funcs.items(), key=lambda kv: -kv[1]["instructions"])
    if args.top:
        listed = listed[:args.top]
    for f, d in listed:
        out.append(hdr % (f[:30], d["group"], fmt(d["instructions"]), "%.1f" % (d["instructions"] / pixels),
                          "%.2f%%" % (100.0 * d["instructions"] / max(1, total))))
    if groups["other"]["functions"]:
        out.append("")
        out.append("in no group (add them to GROUPS in bench/profile.py): " + ", ".join(groups["other"]["functions"]))
    out.append("")
    out.append("display sink, apart: %s instructions" % fmt(per["excluded"]["instructions"]))
    out.append("log: %s lines, %d translations, %d rewinds (I/O), %d stopped blocks" % (
        fmt(parser.lines), parser.translations, parser.rewinds, parser.stops))
    unknown = sum(per[k]["unknown_blocks"] for k in kinds)
    if unknown:
        out.append("warning: %d executions of blocks without a translation listing" % unknown)
    for w, n in parser.warnings.most_common():
        out.append("warning: %s (%d)" % (w, n))
    if "qemu_seconds" in extra:
        out.append("QEMU + parsing %.1f s wall, tool total %.1f s" % (extra["qemu_seconds"], time.time() - extra["t0"]))

    data = {
        "elf": args.elf, "machine": args.machine, "core": model.core, "pixels": pixels,
        "instructions": total, "cycles_typ": cyc_total, "firmware": fw,
        "difference_percent": (100.0 * (total - ri) / ri) if ri else None,
        "excluded_instructions": per["excluded"]["instructions"], "sink": args.sink,
        "kinds": {k: {"rays": rk.rays.get(k, 0) if k != "frame" else None,
                      "instructions": per[k]["instructions"], "cycles_typ": per[k]["cycles"]["typ"]} for k in kinds},
        "groups": {g: {"instructions": d["instructions"], "cycles_typ": d["cycles_typ"], "functions": d["functions"]}
                   for g, d in groups.items()},
        "matrix": {g: {k: row[k] for k in kinds} for g, row in matrix.items()},
        "functions": {f: {"group": d["group"], "instructions": d["instructions"], "cycles_typ": d["cycles_typ"],
                          "kinds": dict(d["kinds"])} for f, d in funcs.items()},
        "checks": checks,
        "log": {"lines": parser.lines, "translations": parser.translations, "rewinds": parser.rewinds,
                "stops": parser.stops, "warnings": dict(parser.warnings), "unknown_block_executions": unknown},
    }
    return "\n".join(out), data, failed


def main():
    t0 = time.time()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="How kinds and groups are decided: see the docstring (the file head).")
    ap.add_argument("elf", help="firmware ELF")
    ap.add_argument("--machine", default="mps2-an385", help="QEMU machine, the board's name (default mps2-an385)")
    ap.add_argument("--qemu", help="QEMU binary (default: the machine's)")
    ap.add_argument("--qemu-arg", action="append", default=[], help="extra QEMU argument (repeatable)")
    ap.add_argument("--sink", default=",".join(SINK_CALLBACKS),
                    help="the display sink's callbacks, counted apart (comma-separated; default: %(default)s)")
    ap.add_argument("--pixels", type=int, help="pixels rendered (default: the firmware's 'pixels' record)")
    ap.add_argument("--top", type=int, default=0, help="functions to list (default 0: all)")
    ap.add_argument("--log", help="parse this saved QEMU log (-d in_asm,exec,nochain) instead of running QEMU")
    ap.add_argument("--stream", help="keep the board's output in this file (with --log: read it)")
    ap.add_argument("--json", help="also write the figures as JSON to this file")
    ap.add_argument("--check", action="store_true", help="exit 1 when a check fails")
    ap.add_argument("--nm", help="nm for the ELF's symbols (default: the target's binutils)")
    ap.add_argument("--timeout", type=float, default=1800, help="seconds before QEMU is killed (default 1800)")
    args = ap.parse_args()
    args.sink = [s for s in args.sink.split(",") if s]
    if args.machine not in cycles.MACHINES:
        ap.error("unknown machine %s (known: %s)" % (args.machine, ", ".join(sorted(cycles.MACHINES))))
    core, qemu = cycles.MACHINES[args.machine]
    args.qemu = args.qemu or qemu
    model = cycles.Model(core)
    syms = cycles.read_symbols(args.elf, model.isa, args.nm)
    names = {a: n for a, n in syms}

    root = one(syms, "rt_render")
    trace = one(syms, "rt_trace_ray")
    occluded = one(syms, "rt_scene_occluded")
    segments = find(syms, lambda n: base_name(n) == "trace_segment")
    if root is None or trace is None or not segments:
        sys.exit("profile: %s has no rt_render, rt_trace_ray or trace_segment" % args.elf)
    marks = {}
    for kind, fn in (("reflection", "count_reflect_ray"), ("refraction", "count_refract_ray")):
        for pc in find(syms, lambda n, fn=fn: base_name(n) == fn):
            marks[pc] = kind
    sinks = [a for a in (one(syms, s) for s in args.sink) if a is not None]
    rk = RayKinds(root, trace, segments, occluded, sinks, marks, names)
    parser = cycles.Parser(model, extents=rk)
    extra = {"t0": t0}
    if cycles.run_firmware(args, parser, report_records, "profile", extra) != 0:
        sys.exit(1)
    if rk.entries[root] == 0:
        sys.exit("profile: rt_render was never entered by a call")
    text, data, failed = profile(args, parser, model, syms, rk, extra)
    print(text)
    if args.json:
        cycles.write_json(args.json, data, t0)
    if failed and args.check:
        sys.exit(1)


if __name__ == "__main__":
    main()
