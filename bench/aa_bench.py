#!/usr/bin/env python3
"""Anti-aliasing: error against the pixel-area image against cost.

For every SPD size-1/2 scene and demo scene at 128x128, depth 5, the fixed
build with one sample a pixel, uniform 2x2 and 4x4 (rt --spp 2, 4) and
adaptive subdivision at several levels and thresholds (rt --aa L,T) is
measured against the pixel-area image (rt --double --spp 16 --texture-filter off,
docs/shading-model.md) for
  - PSNR and the share of pixels off by more than 8/255;
  - host time: median of 3 runs of rt --threads 1, seconds;
  - eye rays a pixel (rt --stats);
  - board instructions a pixel on mps2-an385 (QEMU -icount shift=0: exact
    and repeatable; make firmware AA=/SPP=), for the scenes of
    --board-scenes (all by default).
Then the number format's part: fixed against double with the same samples
(--aa 3; the double build replays the fixed build's splits, rt
--same-samples fixed). Then dithering: the showpiece and balls-2 with --aa 3 in rgb565,
l8 and l4, with and without --dither, against the pixel-area image in the
same colours (rgb888 for rgb565; its l8 luma for l8 and l4), both blurred
by a Gaussian of 1 pixel (rt compare --blur 1), and unblurred.
It writes bench/aa.md, bench/aa.csv and bench/aa-plot.svg.

  bench/aa_bench.py [--scenes a,b] [--board-scenes a,b] [--no-board]
"""
import argparse
import csv
import math
import os
import re
import statistics
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "bench-aa")
RT = os.environ.get("AA_BENCH_RT", os.path.join(ROOT, "build", "host", "rt"))
SIZE = "128x128"
SCENES = ["balls-1", "balls-2", "gears-1", "rings-1", "rings-2", "teapot-1", "teapot-2", "tetra-1", "tetra-2",
          "showpiece", "boxes", "csg", "quadrics", "torus", "transforms"]
# (label, rt options, make variables)
MODES = [("1 sample", [], []),
         ("uniform 2x2", ["--spp", "2"], ["SPP=2"]),
         ("uniform 4x4", ["--spp", "4"], ["SPP=4"]),
         ("aa 2,8", ["--aa", "2,8"], ["AA=2,8"]),
         ("aa 3,4", ["--aa", "3,4"], ["AA=3,4"]),
         ("aa 3,8", ["--aa", "3,8"], ["AA=3,8"]),
         ("aa 3,16", ["--aa", "3,16"], ["AA=3,16"])]


def run(cmd, **kw):
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=True, **kw)


def scene_path(s):
    p = "scenes/spd/%s.nff" % s
    return p if os.path.exists(os.path.join(ROOT, p)) else "scenes/%s.nff" % s


def render(scene, out, extra=(), stats=False):
    cmd = [RT, scene_path(scene), "-o", out, "--size", SIZE, "--quiet", "--threads", "1"] + list(extra)
    t0 = time.perf_counter()
    r = run(cmd + (["--stats"] if stats else []))
    dt = time.perf_counter() - t0
    counters = dict((m.group(1), int(m.group(2))) for m in re.finditer(r"^(\w+)\s+(\d+)$", r.stderr, re.M))
    return dt, counters


def compare(a, b, blur=None):
    cmd = [RT, "compare", a, b] + (["--blur", str(blur)] if blur else [])
    m = re.search(r"psnr (\S+) dB  max-error (\d+)  over2 \S+  over8 (\S+)%", run(cmd).stdout)
    return float(m.group(1)), int(m.group(2)), float(m.group(3))


def board_ipp(scene, variables):
    args = ["make", "-s", "SCENE=" + scene_path(scene), "SIZE=" + SIZE, "DEPTH=5", "AA=0"] + variables
    run(args + ["-j2", "firmware"])
    rep = run(args + ["board-run", "RUN_OUT=" + os.path.join(OUT, "board.png")]).stdout
    return int(re.search(r"^instructions_per_pixel (\d+)$", rep, re.M).group(1))


def pareto(points):
    """Indices of the points no other beats on both cost (lower) and PSNR (higher)."""
    return [i for i, (c, p) in enumerate(points)
            if not any(c2 <= c and p2 >= p and (c2, p2) != (c, p) for c2, p2 in points)]


def write_svg(path, agg):
    """Geometric-mean cost (x, log) against mean PSNR (y) per mode."""
    W, H, L, B = 640, 400, 60, 50
    pts = [(label, a["cost"], a["psnr"]) for label, a in agg.items()]
    cmin, cmax = min(p[1] for p in pts) / 1.3, max(p[1] for p in pts) * 1.3
    pmin, pmax = math.floor(min(p[2] for p in pts) - 2), math.ceil(max(p[2] for p in pts) + 2)
    x = lambda c: L + (W - L - 20) * (math.log(c) - math.log(cmin)) / (math.log(cmax) - math.log(cmin))
    y = lambda p: H - B - (H - B - 20) * (p - pmin) / (pmax - pmin)
    front = set(pareto([(p[1], p[2]) for p in pts]))
    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">'
         % (W, H), '<rect width="100%" height="100%" fill="white"/>',
         '<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, H - B, W - 20, H - B),
         '<line x1="%d" y1="20" x2="%d" y2="%d" stroke="black"/>' % (L, L, H - B)]
    for p in range(int(pmin), int(pmax) + 1, 2):
        s.append('<text x="%d" y="%.1f" text-anchor="end">%d</text>' % (L - 6, y(p) + 4, p))
    for c in (1, 2, 4, 8, 16, 32):
        if cmin <= c <= cmax:
            s.append('<text x="%.1f" y="%d" text-anchor="middle">%dx</text>' % (x(c), H - B + 16, c))
    s.append('<text x="%d" y="%d" text-anchor="middle">cost: board instructions a pixel over one sample '
             '(geometric mean)</text>' % ((W + L) // 2, H - 12))
    s.append('<text x="14" y="%d" transform="rotate(-90 14 %d)" text-anchor="middle">PSNR against the pixel-area '
             'image, dB (mean)</text>' % (H // 2, H // 2))
    order = sorted(front, key=lambda i: pts[i][1])
    s.append('<polyline fill="none" stroke="#c33" points="%s"/>'
             % " ".join("%.1f,%.1f" % (x(pts[i][1]), y(pts[i][2])) for i in order))
    for i, (label, c, p) in enumerate(pts):
        colour = "#c33" if i in front else "#36c"
        s.append('<circle cx="%.1f" cy="%.1f" r="4" fill="%s"/>' % (x(c), y(p), colour))
        s.append('<text x="%.1f" y="%.1f">%s</text>' % (x(c) + 6, y(p) - 6, label))
    s.append("</svg>")
    open(path, "w").write("\n".join(s) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", default=",".join(SCENES))
    ap.add_argument("--board-scenes", default=None, help="scenes measured on the board (default: all)")
    ap.add_argument("--no-board", action="store_true")
    a = ap.parse_args()
    scenes = a.scenes.split(",")
    board_scenes = [] if a.no_board else (a.board_scenes.split(",") if a.board_scenes else scenes)
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for s in scenes:
        ref = os.path.join(OUT, s + "-area.png")
        render(s, ref, ["--double", "--spp", "16", "--texture-filter", "off", "--threads", "2"])
        base = None
        for label, opts, variables in MODES:
            out = os.path.join(OUT, "%s-%s.png" % (s, label.replace(" ", "_").replace(",", "_")))
            times = []
            for _ in range(3):
                dt, counters = render(s, out, opts, stats=True)
                times.append(dt)
            psnr, maxerr, over8 = compare(out, ref)
            ipp = board_ipp(s, variables) if s in board_scenes else None
            row = {"scene": s, "mode": label, "psnr_db": psnr, "max_error": maxerr, "over8_pct": over8,
                   "host_s": statistics.median(times), "eye_rays_per_px": counters["eye_rays"] / 16384,
                   "board_ipp": ipp}
            if base is None:
                base = row
            row["cost_x"] = (ipp / base["board_ipp"]) if ipp else None
            row["host_x"] = row["host_s"] / base["host_s"]
            rows.append(row)
            print("%-10s %-12s %6.2f dB  over8 %6.3f%%  host %.3f s  eye %5.2f/px  board %s" % (
                s, label, psnr, over8, row["host_s"], row["eye_rays_per_px"], ipp if ipp else "-"), flush=True)
    # the number format's part at the same samples
    fmt_rows = []
    for s in scenes:
        f, d = os.path.join(OUT, s + "-fmt-fixed.png"), os.path.join(OUT, s + "-fmt-double.png")
        render(s, f, ["--aa", "3"])
        render(s, d, ["--aa", "3", "--double", "--same-samples", "fixed"])
        p, m, o = compare(f, d)
        fmt_rows.append((s, p, m, o))
    # dithering
    dither_rows = []
    for s in ["showpiece", "balls-2"]:
        for fmt in ("rgb888", "l8"):
            render(s, os.path.join(OUT, "%s-area-%s.png" % (s, fmt)), ["--double", "--spp", "16", "--texture-filter", "off", "--format", fmt,
                                                                       "--threads", "2"])
        for fmt, src in (("rgb565", "rgb888"), ("l8", "l8"), ("l4", "l8")):
            ref = os.path.join(OUT, "%s-area-%s.png" % (s, src))
            r = {}
            for d in (False, True):
                out = os.path.join(OUT, "%s-%s%s.png" % (s, fmt, "-dither" if d else ""))
                render(s, out, ["--aa", "3", "--format", fmt] + (["--dither"] if d else []))
                r[d] = (compare(out, ref, blur=1), compare(out, ref))
            dither_rows.append((s, fmt, src, r))

    # aggregate over the scenes measured on the board
    agg = {}
    for label, _, _ in MODES:
        rs = [r for r in rows if r["mode"] == label and r["cost_x"]]
        if rs:
            agg[label] = {"cost": math.exp(statistics.mean(math.log(r["cost_x"]) for r in rs)),
                          "psnr": statistics.mean(r["psnr_db"] for r in rs),
                          "over8": statistics.mean(r["over8_pct"] for r in rs)}
    with open(os.path.join(ROOT, "bench", "aa.csv"), "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0].keys()))
        w.writeheader()
        for r in rows:
            w.writerow(r)
    if agg:
        write_svg(os.path.join(ROOT, "bench", "aa-plot.svg"), agg)
    md = ["# Anti-aliasing: error against the pixel-area image, and cost", "",
          "From `bench/aa_bench.py` (`make bench`): %s, depth 5, fixed build; reference the pixel-area image "
          "(`rt --double --spp 16 --texture-filter off`). Cost: board instructions a pixel on mps2-an385 (QEMU `-icount shift=0`) "
          "and its ratio to one sample; host time is the median of 3 runs of `rt --threads 1` on this "
          "machine (noisy; the instruction counts are exact)." % SIZE, ""]
    if agg:
        md += ["![PSNR against cost](aa-plot.svg)", "",
               "| mode | cost (geo-mean over one sample) | mean PSNR | mean share > 8/255 |", "|---|---|---|---|"]
        for label, g in agg.items():
            md.append("| %s | %.2fx | %.2f dB | %.3f%% |" % (label, g["cost"], g["psnr"], g["over8"]))
        md.append("")
    md += ["| scene | mode | PSNR | max | > 8/255 | eye rays/px | board instr/px | cost | host s |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append("| %s | %s | %.2f dB | %d | %.3f%% | %.2f | %s | %s | %.3f |" % (
            r["scene"], r["mode"], r["psnr_db"], r["max_error"], r["over8_pct"], r["eye_rays_per_px"],
            "{:,}".format(r["board_ipp"]) if r["board_ipp"] else "-",
            "%.2fx" % r["cost_x"] if r["cost_x"] else "-", r["host_s"]))
    md += ["", "## The number format's part", "",
           "Fixed against double with the same samples (`--aa 3`; the double build replays the fixed build's "
           "splits, `rt --same-samples fixed`):", "",
           "| scene | PSNR | max | > 8/255 |", "|---|---|---|---|"]
    for s, p, m, o in fmt_rows:
        md.append("| %s | %.2f dB | %d | %.3f%% |" % (s, p, m, o))
    md += ["", "## Dithering", "",
           "`--aa 3`, 128x128, against the pixel-area image in the same colours (rgb888; its l8 luma for l8 and "
           "l4), both blurred by a Gaussian of 1 pixel (`rt compare --blur 1`: what an eye sees of a small "
           "panel), and unblurred:", "",
           "| scene | format | blurred, rounded | blurred, dithered | unblurred, rounded | unblurred, dithered |",
           "|---|---|---|---|---|---|"]
    for s, fmt, src, r in dither_rows:
        md.append("| %s | %s (vs %s) | %.2f dB | %.2f dB | %.2f dB | %.2f dB |" % (
            s, fmt, src, r[False][0][0], r[True][0][0], r[False][1][0], r[True][1][0]))
    open(os.path.join(ROOT, "bench", "aa.md"), "w").write("\n".join(md) + "\n")
    print("wrote bench/aa.md, bench/aa.csv, bench/aa-plot.svg")


if __name__ == "__main__":
    main()
