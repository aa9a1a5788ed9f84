#!/usr/bin/env python3
"""Run time against error: every numeric configuration on every bench scene.

For each (configuration, scene) cell it measures
  - error against the exact double reference at 128x128 (PSNR, max channel error,
    share of pixels off by more than 2/255 and 8/255), from `rt compare`;
  - board cost: instructions per pixel on the emulated Cortex-M3 at 64x64
    (QEMU -icount shift=0, exact);
  - host cost: render time at 128x128, median of 5 runs after a warm-up,
    one thread, and callgrind's instruction count of a 64x64 render.
It writes bench/results.md, bench/results.csv and bench/plot.svg.
The fixed-point configurations are the Makefile's (make -s print-configs),
described by docs/accuracy.md's table.

  bench/run_bench.py [--quick] [--scenes A,B] [--size WxH --out DIR]
"""
import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "bench")



def fixed_configs():
    """The Makefile's configurations, each with docs/accuracy.md's words for it."""
    names = subprocess.run(["make", "-s", "print-configs"], cwd=ROOT, check=True, capture_output=True,
                           text=True).stdout.split()
    with open(os.path.join(ROOT, "docs", "accuracy.md")) as f:
        what = dict(re.findall(r"^\| `(\w+)` \| ([^|]+?) \|", f.read(), re.M))
    missing = [n for n in names if n not in what]
    if missing:
        sys.exit("bench: docs/accuracy.md's table of configurations has no row for %s" % ", ".join(missing))
    return {n: ("fixed", n, "fixed " + what[n]) for n in names}


# name -> (kind, board CONFIG, description)
CONFIGS = dict(fixed_configs(), **{
    "float": ("float", "q20", "single-precision soft-float"),
    "double": ("double", "q20", "double-precision soft-float (reference)"),
})
DEFAULT = "q20"
SPD = ["balls-1", "gears-1", "rings-1", "teapot-1", "tetra-1",
       "balls-2", "rings-2", "teapot-2", "tetra-2"]
QUICK_SCENES = ["balls-1", "rings-1", "tetra-2"]
QUICK_CONFIGS = ["q20", "q16", "float", "double"]
ERR_SIZE = "128x128"
BOARD_SIZE = "64x64"
CALLGRIND_SIZE = "64x64"


def run(cmd, **kw):
    return subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True, text=True, **kw)


def host_rt(cfg):
    kind = CONFIGS[cfg][0]
    return ("build/host/rt", "--" + kind) if kind != "fixed" else ("build/cfg-%s/rt" % cfg, "--fixed")


def scene_path(scene):
    for d in (("scenes", "spd"), ("scenes",), ("scenes", "bench")):
        p = os.path.join(*d, scene + ".nff")
        if os.path.exists(os.path.join(ROOT, p)):
            return p
    sys.exit("bench: no scene %s in scenes/spd, scenes or scenes/bench" % scene)


def render(cfg, scene, size, out, extra=()):
    rt, flag = host_rt(cfg)
    r = run([rt, scene_path(scene), "-o", out, "--size", size, flag, "--threads", "1", "--quiet", "--stats"] + list(extra))
    m = re.search(r"^render_seconds\s+([0-9.]+)$", r.stderr, re.M)
    return float(m.group(1))


def compare(a, b):
    line = run(["build/host/rt", "compare", a, b]).stdout
    m = re.search(r"psnr (\S+) dB\s+max-error (\d+)\s+over2 ([0-9.]+)%\s+over8 ([0-9.]+)%", line)
    psnr = math.inf if m.group(1) == "inf" else float(m.group(1))
    return psnr, int(m.group(2)), float(m.group(3)), float(m.group(4))


def board_ipp(cfg, scene, board, size):
    kind, board_cfg, _ = CONFIGS[cfg]
    args = ["BOARD=" + board, "BACKEND=" + kind, "SCENE=" + scene_path(scene), "SIZE=" + size,
            "DEPTH=5", "CONFIG=" + board_cfg, "AA=0"]
    run(["make", "-s", "-j2", "firmware"] + args)
    report = run(["make", "-s", "board-run", "RUN_OUT=" + os.path.join(OUT, "board-%s-%s.png" % (cfg, scene))]
                 + args).stdout
    m = re.search(r"^instructions_per_pixel (\d+)$", report, re.M)
    return int(m.group(1))


def callgrind(cfg, scene):
    rt, flag = host_rt(cfg)
    out = os.path.join(OUT, "cg.out")
    r = run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + out, rt, scene_path(scene),
             "-o", os.path.join(OUT, "cg.png"), "--size", CALLGRIND_SIZE, flag, "--threads", "1", "--quiet"])
    m = re.search(r"Collected : (\d+)", r.stderr)
    return int(m.group(1)) if m else None


def pareto(points):
    """Indices of points not dominated (lower cost and higher PSNR)."""
    front = []
    for i, (c, p) in enumerate(points):
        if not any((c2 <= c and p2 >= p) and (c2 < c or p2 > p) for c2, p2 in points):
            front.append(i)
    return front


def fmt_psnr(p):
    return "inf" if p == math.inf else "%.2f" % p


def write_svg(path, cells, cfgs, agg, front, board_size):
    W, H, L, R, T, B = 760, 460, 70, 200, 30, 50
    costs = [c["board_ipp"] for c in cells] + [a[0] for a in agg.values()]
    lo, hi = math.log10(min(costs)) - 0.1, math.log10(max(costs)) + 0.1
    cap = 100.0
    ps = [min(c["psnr"], cap) for c in cells]
    plo, phi = max(0.0, math.floor(min(ps) / 10) * 10), cap

    def x(v):
        return L + (math.log10(v) - lo) / (hi - lo) * (W - L - R)

    def y(p):
        return T + (1 - (min(p, cap) - plo) / (phi - plo)) * (H - T - B)

    palette = {"q20": "#1b7837", "q20fast": "#7fbf7b", "q16": "#2166ac", "q16fast": "#92c5de",
               "q12": "#762a83", "float": "#e08214", "double": "#555555"}
    col = {c: palette.get(c, "#999999") for c in cfgs}
    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">' % (W, H),
         '<rect width="100%" height="100%" fill="white"/>',
         '<text x="%d" y="18" font-size="14">PSNR against the exact double vs board instructions per pixel (Cortex-M3, %s)</text>' % (L, board_size)]
    for e in range(int(math.floor(lo)), int(math.ceil(hi)) + 1):
        for m in (1, 2, 5):
            v = m * 10 ** e
            if lo <= math.log10(v) <= hi:
                s.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x(v), T, x(v), H - B))
                s.append('<text x="%.1f" y="%d" text-anchor="middle">%s</text>' % (x(v), H - B + 16, "{:,}".format(v)))
    for p in range(int(plo), int(phi) + 1, 10):
        s.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (L, y(p), W - R, y(p)))
        s.append('<text x="%d" y="%.1f" text-anchor="end">%s</text>' % (L - 6, y(p) + 4, "%d%s" % (p, "+" if p == cap else "")))
    s.append('<text x="%d" y="%d" text-anchor="middle">instructions per pixel (log scale)</text>' % ((L + W - R) / 2, H - 12))
    s.append('<text x="16" y="%d" transform="rotate(-90 16 %d)" text-anchor="middle">PSNR (dB)</text>' % ((T + H - B) / 2, (T + H - B) / 2))
    for c in cells:
        s.append('<circle cx="%.1f" cy="%.1f" r="3" fill="%s" fill-opacity="0.45"><title>%s %s: %s dB, %d instr/px</title></circle>'
                 % (x(c["board_ipp"]), y(c["psnr"]), col[c["config"]], c["config"], c["scene"], fmt_psnr(c["psnr"]), c["board_ipp"]))
    pts = sorted((agg[c][0], agg[c][1], c) for c in front)
    s.append('<polyline fill="none" stroke="black" stroke-dasharray="4 3" points="%s"/>'
             % " ".join("%.1f,%.1f" % (x(a), y(b)) for a, b, _ in pts))
    for i, c in enumerate(cfgs):
        a, b = agg[c]
        s.append('<rect x="%.1f" y="%.1f" width="10" height="10" fill="%s" stroke="black"%s/>'
                 % (x(a) - 5, y(b) - 5, col[c], ' stroke-width="2.5"' if c in front else ""))
        ly = T + 16 + i * 18
        s.append('<rect x="%d" y="%d" width="10" height="10" fill="%s" stroke="black"/>' % (W - R + 14, ly - 9, col[c]))
        s.append('<text x="%d" y="%d">%s%s</text>' % (W - R + 30, ly, c, " (Pareto)" if c in front else ""))
    s.append('<text x="%d" y="%d" font-size="11">dots: one per scene;</text>' % (W - R + 14, T + 36 + len(cfgs) * 18))
    s.append('<text x="%d" y="%d" font-size="11">squares: worst-scene PSNR</text>' % (W - R + 14, T + 50 + len(cfgs) * 18))
    s.append('<text x="%d" y="%d" font-size="11">at geometric-mean cost;</text>' % (W - R + 14, T + 64 + len(cfgs) * 18))
    s.append('<text x="%d" y="%d" font-size="11">dashed: Pareto front</text>' % (W - R + 14, T + 78 + len(cfgs) * 18))
    s.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(s) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true", help="a subset (make bench-quick; its duration: docs/performance.md)")
    ap.add_argument("--board", default="mps2-an385", help="the board of the instructions-per-pixel column")
    ap.add_argument("--scenes", help="these scenes (comma-separated names) instead")
    ap.add_argument("--size", help="errors and board cost at WxH, one timed run, results in --out "
                                   "(the test of make test: tests/boards/configs-tests.sh)")
    ap.add_argument("--out", help="the folder of the results (default bench/)")
    ap.add_argument("--from-csv", action="store_true",
                    help="measure nothing: rewrite the results from results.csv's cells "
                         "(after a configuration or scene is dropped from it)")
    args = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    extra_scenes = sorted(f[:-4] for f in os.listdir(os.path.join(ROOT, "scenes")) if f.endswith(".nff"))
    scenes = QUICK_SCENES if args.quick else SPD + extra_scenes
    if args.scenes:
        scenes = args.scenes.split(",")
    cfgs = QUICK_CONFIGS if args.quick else list(CONFIGS)
    runs = 3 if args.quick else 5
    err_size, board_size = ERR_SIZE, BOARD_SIZE
    if args.size:
        if not args.out:
            sys.exit("bench: --size writes its results to --out DIR, not bench/")
        err_size = board_size = args.size
        runs = 1
    dest = args.out or os.path.join(ROOT, "bench")
    os.makedirs(dest, exist_ok=True)

    if args.from_csv:
        cells = read_csv(os.path.join(dest, "results%s.csv" % ("-quick" if args.quick else "")))
        scenes = list(dict.fromkeys(c["scene"] for c in cells))
        cfgs = [c for c in CONFIGS if any(x["config"] == c for x in cells)]
        write_results(cells, scenes, cfgs, args.quick, runs, dest, err_size, board_size)
        return
    cells = []
    for scene in scenes:
        ref = os.path.join(OUT, "ref-%s.png" % scene)
        render("double", scene, err_size, ref)
        for cfg in cfgs:
            img = os.path.join(OUT, "%s-%s.png" % (cfg, scene))
            render(cfg, scene, err_size, img)  # also the warm-up
            times = [render(cfg, scene, err_size, img) for _ in range(runs)]
            psnr, maxe, o2, o8 = compare(img, ref)
            cell = {"config": cfg, "scene": scene, "psnr": psnr, "max_err": maxe, "over2_pct": o2,
                    "over8_pct": o8, "board_ipp": board_ipp(cfg, scene, args.board, board_size),
                    "host_ms": 1000 * statistics.median(times),
                    "host_instr": None if args.quick or args.size else callgrind(cfg, scene)}
            cells.append(cell)
            print("%-8s %-9s psnr %7s  max %3d  board %9d instr/px  host %7.2f ms" %
                  (cfg, scene, fmt_psnr(psnr), maxe, cell["board_ipp"], cell["host_ms"]), flush=True)
    write_results(cells, scenes, cfgs, args.quick, runs, dest, err_size, board_size)


def read_csv(path):
    """The cells of a results.csv, as the measurement loop makes them."""
    cells = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            cells.append({"config": r["config"], "scene": r["scene"],
                          "psnr": math.inf if r["psnr_db"] == "inf" else float(r["psnr_db"]),
                          "max_err": int(r["max_err"]), "over2_pct": float(r["over2_pct"]),
                          "over8_pct": float(r["over8_pct"]), "board_ipp": int(r["board_instr_per_px"]),
                          "host_ms": float(r["host_ms_128"]),
                          "host_instr": int(r["host_callgrind_instr_64"]) if r["host_callgrind_instr_64"] else None})
    return cells


def write_results(cells, scenes, cfgs, quick, runs, dest, err_size, board_size):
    """results.csv, plot.svg and results.md in dest from the measured cells."""

    # per-scene Pareto membership, and the configurations' aggregate points
    for scene in scenes:
        sc = [c for c in cells if c["scene"] == scene]
        for i in pareto([(c["board_ipp"], c["psnr"]) for c in sc]):
            sc[i]["pareto"] = True
    agg = {}
    for cfg in cfgs:
        cc = [c for c in cells if c["config"] == cfg]
        gmean = math.exp(sum(math.log(c["board_ipp"]) for c in cc) / len(cc))
        agg[cfg] = (gmean, min(min(c["psnr"] for c in cc), 100.0))
    front = [cfgs[i] for i in pareto([agg[c] for c in cfgs])]

    suffix = "-quick" if quick else ""
    with open(os.path.join(dest, "results%s.csv" % suffix), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["config", "scene", "psnr_db", "max_err", "over2_pct", "over8_pct", "board_instr_per_px",
                    "host_ms_128", "host_callgrind_instr_64", "pareto_in_scene"])
        for c in cells:
            w.writerow([c["config"], c["scene"], fmt_psnr(c["psnr"]), c["max_err"], c["over2_pct"], c["over8_pct"],
                        c["board_ipp"], "%.3f" % c["host_ms"], c["host_instr"] or "", int(c.get("pareto", False))])
    write_svg(os.path.join(dest, "plot%s.svg" % suffix), cells, cfgs, agg, front, board_size)

    dbl = {c["scene"]: c["board_ipp"] for c in cells if c["config"] == "double"}
    flt = {c["scene"]: c["board_ipp"] for c in cells if c["config"] == "float"}
    md = ["# Run time against error%s" % (" (quick subset)" if quick else ""), "",
          "Generated by `bench/run_bench.py%s` (`make bench%s`). Error: each configuration's "
          "image against the exact double reference (its tolerances from double precision, src/numeric/tolerance.h) at %s, depth 5. Board: instructions per pixel on the emulated "
          "Cortex-M3 at %s (QEMU `-icount shift=0`, exact); soft-float configurations use libgcc's "
          "`__aeabi_f*`/`__aeabi_d*`. Host: render time at %s, median of %d runs after a warm-up, "
          "one thread%s." % (" --quick" if quick else "", "-quick" if quick else "", err_size,
                             board_size, err_size, runs,
                             "" if quick else ", and callgrind's instruction count at " + CALLGRIND_SIZE), "",
          "![PSNR against board instructions per pixel](plot%s.svg)" % suffix, "",
          "## Configurations", "",
          "| config | what | worst PSNR | geo-mean board instr/px | vs float | vs double | Pareto front |",
          "|---|---|---|---|---|---|---|"]
    for cfg in cfgs:
        g, p = agg[cfg]
        vf = ("%.1fx" % (math.exp(sum(math.log(flt[s] / c["board_ipp"]) for s, c in
                                      ((c["scene"], c) for c in cells if c["config"] == cfg)) / len(scenes)))
              if flt else "-")
        vd = ("%.1fx" % (math.exp(sum(math.log(dbl[s] / c["board_ipp"]) for s, c in
                                      ((c["scene"], c) for c in cells if c["config"] == cfg)) / len(scenes)))
              if dbl else "-")
        md.append("| %s%s | %s | %s dB | %d | %s | %s | %s |" % (
            cfg, " (default)" if cfg == DEFAULT else "", CONFIGS[cfg][2], fmt_psnr(p) if p < 100 else "100+",
            g, vf, vd, "yes" if cfg in front else "no"))
    md += ["", "\"vs float\" / \"vs double\": how many times fewer board instructions than the soft-float "
           "build, geometric mean over the scenes.", "",
           "## Every cell", "",
           "| config | scene | PSNR | max err | >2/255 | >8/255 | board instr/px | vs float | vs double | host ms | host instr (callgrind) |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for c in cells:
        md.append("| %s | %s | %s | %d | %.3f%% | %.3f%% | %d | %s | %s | %.2f | %s |" % (
            c["config"], c["scene"], fmt_psnr(c["psnr"]), c["max_err"], c["over2_pct"], c["over8_pct"],
            c["board_ipp"], "%.1fx" % (flt[c["scene"]] / c["board_ipp"]) if c["scene"] in flt else "-",
            "%.1fx" % (dbl[c["scene"]] / c["board_ipp"]) if c["scene"] in dbl else "-", c["host_ms"],
            "{:,}".format(c["host_instr"]) if c["host_instr"] else "-"))
    with open(os.path.join(dest, "results%s.md" % suffix), "w") as f:
        f.write("\n".join(md) + "\n")
    where = os.path.relpath(dest, ROOT)
    print("wrote %s/results%s.md, results%s.csv, plot%s.svg; Pareto front: %s"
          % (where, suffix, suffix, suffix, ", ".join(front)))
    if DEFAULT in cfgs and DEFAULT not in front:
        print("note: the default configuration %s is not on the Pareto front" % DEFAULT)


if __name__ == "__main__":
    try:
        main()
    except subprocess.CalledProcessError as e:
        sys.exit("bench: %s failed:\n%s%s" % (" ".join(e.cmd), e.stdout, e.stderr))
