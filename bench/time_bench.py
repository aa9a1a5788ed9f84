#!/usr/bin/env python3
"""Seconds a frame against error: every board at its clock, every backend,
one sample a pixel and adaptive anti-aliasing (--aa 3).

The card scene (scenes/bench/card.nff, depth 3: the business-card ray
tracer's, which the published microcontroller figures use) at 320x240, one
core. For each board, backend and sampling it records
  - cycles a pixel: counted where the port counts them (the pico: SysTick
    under rp2040js), else the instructions a pixel (QEMU -icount shift=0)
    times the cycles an instruction bench/cycles.py prices the run's mix at
    (the core's documented timings, no flash wait states), measured on a
    smaller frame of the same scene and sampling;
  - seconds a frame at the board's clock (board.mk's BOARD_CLOCK_HZ):
    cycles a pixel x 76,800 / clock;
  - the error against the pixel-area image (rt --double --spp 16
    --texture-filter off: what a viewer sees), PSNR and the share of pixels
    off by more than 8/255, and against the exact model at the same samples
    (the double build; with --aa 3 it replays the board's splits).
The one-sample rows are bench/scenes.csv's (bench/scenes_bench.py measures
them; this reads them), the anti-aliased ones are measured here. The
CPI column is the table make run prices a QEMU board's run with
(tools/firmware/summary.sh reads bench/time.csv).
It writes bench/time.md, bench/time.csv and bench/time.svg.

  bench/time_bench.py [--boards a,b] [--backends a,b] [--update] [--from-csv]
"""
import argparse
import csv
import math
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boards_bench import ROOT, board_info, boards, cpi_of, cycles, full_frame_backends, run, write_csv  # noqa: E402
import scenes_bench  # noqa: E402

SCENE = "card"
SIZE = "320x240"
PIXELS = 320 * 240
# the smaller frame whose instruction mix is priced (same framing)
CYCLE_SIZE = "40x30"
# (label, make variables, rt options) of each sampling measured here
SAMPLINGS = [("aa 3", "AA=3", ["--aa", "3"])]
CSV = os.path.join(ROOT, "bench", "time.csv")
KEYS = ["board", "clock_mhz", "backend", "sampling", "size", "ipp", "cpi", "cpp", "cycles", "seconds",
        "psnr", "max_error", "area_psnr", "area_over8", "note"]


def one_sample_rows():
    """bench/scenes.csv's card rows, one per board and backend (not its build variants)."""
    with open(os.path.join(ROOT, "bench", "scenes.csv")) as f:
        return [r for r in csv.DictReader(f) if r["scene"] == SCENE and " " not in r["board"] and r.get("ipp")]


def exact_ref(size, fmt, backend, opts):
    """The exact model at the board's samples: the double build, replaying the backend's splits."""
    same = [] if backend == "double" else ["--same-samples", backend]
    ref = os.path.join(scenes_bench.OUT, "exact-%s-%s-%s-%s-%s-%d.png" % (
        SCENE, size, fmt, backend, "".join(opts), int(os.path.getmtime("build/host/rt"))))
    if not os.path.exists(ref):
        run(["build/host/rt", scenes_bench.scene_path(SCENE), "-o", ref, "--double", "--size", size, "--depth",
             str(scenes_bench.SCENES[SCENE]), "--format", fmt, "--quiet"] + opts + same)
    return ref


def seconds(cpp, hz):
    return "%.3g" % (float(cpp) * PIXELS / hz) if cpp not in ("", None) else ""


def measure_sampling(board, backend, label, variables, opts, hz):
    size = scenes_bench.PANEL_SIZE.get(board, SIZE)
    row = {"board": board, "clock_mhz": "%g" % (hz / 1e6), "backend": backend, "sampling": label, "size": size}
    m = scenes_bench.measure(board, backend, SCENE, size, variant=variables)
    if not m:
        # why: the link's overflow, when that is it
        args = ["BOARD=" + board, "BACKEND=" + backend, "SCENE=" + scenes_bench.scene_path(SCENE), "SIZE=" + size,
                "DEPTH=%d" % scenes_bench.SCENES[SCENE], "CORES=1", "PROGRESSIVE=0", variables]
        err = run(["make", "-s", "firmware"] + args, check=False).stderr
        over = re.search(r"region .RAM' overflowed by (\d+) bytes", err)
        row["note"] = ("RAM overflows by %s bytes at %s" % (format(int(over.group(1)), ","), size) if over
                       else "fails at %s" % size)
        return row
    fmt = m["info"]["format"]

    def estimate():
        small = scenes_bench.measure(board, backend, SCENE, CYCLE_SIZE, variant=variables)
        js = os.path.join(scenes_bench.OUT, "cycles-%s-%s-%s-%s.json" % (board, backend, SCENE, variables))
        return cpi_of(small, board, js) if small else None

    c, cpp, how = cycles(m, estimate)
    psnr, maxerr, _ = scenes_bench.error(m["png"], exact_ref(size, fmt, backend, opts))
    apsnr, _, aover8 = scenes_bench.error(m["png"], scenes_bench.reference(SCENE, size, fmt, 16))
    row.update({"ipp": m["ipp"], "cpi": "%.3f" % c if c else "", "cpp": cpp, "cycles": how,
                "seconds": seconds(cpp, hz), "psnr": psnr, "max_error": maxerr, "area_psnr": apsnr,
                "area_over8": aover8})
    return row


# make run's default (Makefile: the showpiece, 128x128, depth 5, --aa 3 on
# mps2-an385, fixed): how far the table's card CPI is from the run's own
# mix, and what pricing the run itself would cost make run
CHECK = {"board": "mps2-an385", "backend": "fixed", "scene": "scenes/showpiece.nff", "size": "128x128", "depth": 5,
         "variables": "AA=3", "sampling": "make run's default: showpiece 128x128, depth 5, --aa 3"}


def check_row(table_rows):
    import time
    from boards_bench import measure as boards_measure
    c = CHECK
    hz = float(board_info(["BOARD=" + c["board"]])["clock_hz"])
    t0 = time.time()
    m = boards_measure(c["board"], c["backend"], "showpiece", c["size"], path=c["scene"], depth=c["depth"],
                       out=scenes_bench.OUT, variant=c["variables"])
    t1 = time.time()
    own = cpi_of(m, c["board"], os.path.join(scenes_bench.OUT, "cycles-make-run.json")) if m else None
    t2 = time.time()
    table = [r for r in table_rows if r["board"] == c["board"] and r["backend"] == c["backend"]
             and r["sampling"] == "aa 3" and r.get("cpi")]
    row = {"board": c["board"], "clock_mhz": "%g" % (hz / 1e6), "backend": c["backend"], "sampling": c["sampling"],
           "size": c["size"]}
    if not m or not own or not table:
        row["note"] = "not measured"
        return row
    tcpi = float(table[0]["cpi"])
    row.update({"ipp": m["ipp"], "cpi": "%.3f" % own, "cpp": round(m["ipp"] * own), "cycles": "estimated",
                "seconds": "%.3g" % (m["ipp"] * own * 128 * 128 / hz),
                "note": "table's card --aa 3 CPI %.3f: %.3g s (%+.1f%%); build and QEMU run %.0f s, "
                        "bench/cycles.py's pricing of it %.0f s" % (
                            tcpi, m["ipp"] * tcpi * 128 * 128 / hz, 100 * (tcpi - own) / own, t1 - t0, t2 - t1)})
    return row


def fnum(v):
    try:
        return format(int(v), ",")
    except (TypeError, ValueError):
        return v or ""


def compact(rows):
    """The table in short: a row per board and backend, seconds and PSNR
    (pixel area / exact) for each sampling."""
    out = ["| board, clock | backend | one sample: s, dB area / exact | --aa 3: s, dB area / exact |",
           "|---|---|---|---|"]
    cell = {(r["board"], r["backend"], r["sampling"]): r for r in rows}
    seen = []
    for r in rows:
        k = (r["board"], r["backend"])
        if r["sampling"] == CHECK["sampling"] or k in seen:
            continue
        seen.append(k)
        cells = []
        for samp in ("1 sample", "aa 3"):
            c = cell.get(k + (samp,))
            if not c:
                cells.append("")
            elif c.get("note"):
                cells.append("does not fit: %s" % c["note"])
            else:
                cells.append("%s s, %s / %s" % (c["seconds"], c["area_psnr"], c["psnr"]))
        out.append("| %s, %s MHz | %s | %s |" % (r["board"], r["clock_mhz"], r["backend"], " | ".join(cells)))
    return "\n".join(out) + "\n"


def write_md(rows):
    with open(os.path.join(ROOT, "bench", "time.md"), "w") as f:
        f.write("# Seconds a frame against error, every board (bench/time_bench.py)\n\n"
                "The card scene (`scenes/bench/card.nff`, depth 3), 320x240, one core, each board at\n"
                "the clock of its board.mk (`BOARD_CLOCK_HZ`): the pico 125 MHz (one of its two cores,\n"
                "scanline order; its fixed backend only, as in bench/scenes.md),\n"
                "the stm32f4 168 MHz (an F405/F407; a BlackPill's F411 runs at 100 MHz, its F401 and a\n"
                "Nucleo-64 at 84 MHz: 1.68 and twice the seconds),\n"
                "sifive_e 320 MHz, lm3s6965evb 50 MHz, microbit 16 MHz; the MPS2 boards are FPGA boards\n"
                "run here under QEMU only, at their 25 MHz (AN385, AN386) and 20 MHz (AN521).\n"
                "Seconds = cycles a pixel x 76,800 / clock. Cycles counted by SysTick under rp2040js on\n"
                "the pico (its Cortex-M0+ timing, code in SRAM); elsewhere estimated: instructions a\n"
                "pixel (QEMU -icount shift=0) x the cycles an instruction bench/cycles.py prices the\n"
                "run's mix at (the core's documented timings with no flash wait states: a real\n"
                "STM32F4 has 5 at 168 MHz behind its ART accelerator, and the HiFive1 runs its code\n"
                "from SPI flash through a 16 KiB cache; neither is in these estimates). One sample:\n"
                "bench/scenes.md's rows (CPI from an 80x60 render); --aa 3 measured here (CPI from\n"
                "a %s render). lm3s6965evb renders its 128x64 OLED's frame in 4-bit grey: its\n"
                "cycles a pixel are of that frame, scaled to 76,800 pixels. \"RAM overflows\": the\n"
                "build's link fails, the band buffers of a 320-wide anti-aliased frame do not fit.\n"
                "Error against the pixel-area image (`rt --double --spp 16 --texture-filter off`,\n"
                "what a viewer sees) and against the exact model at the same samples (the double\n"
                "build, replaying the board's anti-aliasing splits).\n\n" % CYCLE_SIZE)
        f.write("![seconds a frame against PSNR, one series per board](time.svg)\n\n")
        f.write(compact(rows) + "\n")
        f.write("| board | clock | backend | sampling | instr/px | CPI | cycles/px | cycles | s a frame | "
                "PSNR pixel area (dB) | > 8/255 vs area | PSNR exact (dB) | max error |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            if r["sampling"] == CHECK["sampling"]:
                continue
            if r.get("note"):
                f.write("| %s | %s MHz | %s | %s | %s |  |  |  |  |  |  |  |  |\n" % (
                    r["board"], r["clock_mhz"], r["backend"], r["sampling"], r["note"]))
                continue
            f.write("| %s |\n" % " | ".join([
                r["board"], r["clock_mhz"] + " MHz", r["backend"], r["sampling"], fnum(r["ipp"]), r["cpi"],
                fnum(r["cpp"]), r["cycles"], r["seconds"], r["area_psnr"], r["area_over8"] + "%",
                r["psnr"], str(r["max_error"])]))
        for r in rows:
            if r["sampling"] == CHECK["sampling"] and r.get("cpi"):
                f.write("\nThe table's CPI against a run's own: %s on %s (%s), its instruction mix priced by\n"
                        "bench/cycles.py: %s instructions a pixel x %s = %s cycles a pixel, %s s at %s MHz;\n"
                        "%s. make run prices a run with the table's CPI (tools/firmware/summary.sh).\n"
                        % (r["sampling"], r["board"], r["backend"], fnum(r["ipp"]), r["cpi"], fnum(r["cpp"]),
                           r["seconds"], r["clock_mhz"], r["note"]))


COLOURS = ["#1b6ca8", "#c0392b", "#27ae60", "#8e44ad", "#d68910", "#117a65", "#7f8c8d", "#a04000", "#2e4053"]


def marker(backend, cx, cy, colour, filled):
    """circle: fixed, square: float, triangle: double; filled: --aa 3, hollow: one sample"""
    paint = 'fill="%s"' % colour if filled else 'fill="white" stroke="%s" stroke-width="1.5"' % colour
    if backend == "float":
        return '<rect x="%.1f" y="%.1f" width="8" height="8" %s/>' % (cx - 4, cy - 4, paint)
    if backend == "double":
        return '<polygon points="%.1f,%.1f %.1f,%.1f %.1f,%.1f" %s/>' % (cx, cy - 5, cx - 5, cy + 4, cx + 5, cy + 4, paint)
    return '<circle cx="%.1f" cy="%.1f" r="4" %s/>' % (cx, cy, paint)


def write_svg(rows):
    """Seconds (x, log) against PSNR from the pixel-area image (y), one series
    (colour) per board: a segment from each backend's one-sample point to its
    --aa 3 point."""
    pts = [r for r in rows if r.get("seconds") and r["sampling"] != CHECK["sampling"]]
    W, H, L, B, R = 760, 480, 60, 50, 200
    smin = 10 ** math.floor(math.log10(min(float(r["seconds"]) for r in pts)))
    smax = 10 ** math.ceil(math.log10(max(float(r["seconds"]) for r in pts)))
    pmin = math.floor(min(float(r["area_psnr"]) for r in pts) - 1)
    pmax = math.ceil(max(float(r["area_psnr"]) for r in pts) + 1)
    x = lambda s: L + (W - L - R) * (math.log(s) - math.log(smin)) / (math.log(smax) - math.log(smin))
    y = lambda p: H - B - (H - B - 20) * (p - pmin) / (pmax - pmin)
    s = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="12">'
         % (W, H), '<rect width="100%" height="100%" fill="white"/>',
         '<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, H - B, W - R, H - B),
         '<line x1="%d" y1="20" x2="%d" y2="%d" stroke="black"/>' % (L, L, H - B)]
    for p in range(pmin, pmax + 1, 2):
        s.append('<text x="%d" y="%.1f" text-anchor="end">%d</text>' % (L - 6, y(p) + 4, p))
    d = smin
    while d <= smax:
        s.append('<line x1="%.1f" y1="20" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x(d), x(d), H - B))
        s.append('<text x="%.1f" y="%d" text-anchor="middle">%g</text>' % (x(d), H - B + 16, d))
        d *= 10
    s.append('<text x="%d" y="%d" text-anchor="middle">seconds a 320x240 frame of the card scene at the '
             'board\'s clock (log)</text>' % ((W - R + L) // 2, H - 12))
    s.append('<text x="14" y="%d" transform="rotate(-90 14 %d)" text-anchor="middle">PSNR against the '
             'pixel-area image, dB</text>' % (H // 2, H // 2))
    names = [b for b in boards() if any(r["board"] == b for r in pts)]
    for i, b in enumerate(names):
        colour = COLOURS[i % len(COLOURS)]
        mine = [r for r in pts if r["board"] == b]
        for be in sorted({r["backend"] for r in mine}):
            pair = sorted((r for r in mine if r["backend"] == be), key=lambda r: r["sampling"] != "1 sample")
            if len(pair) == 2:
                s.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="%s" stroke-opacity="0.5"/>' % (
                    x(float(pair[0]["seconds"])), y(float(pair[0]["area_psnr"])),
                    x(float(pair[1]["seconds"])), y(float(pair[1]["area_psnr"])), colour))
        for r in mine:
            s.append(marker(r["backend"], x(float(r["seconds"])), y(float(r["area_psnr"])), colour,
                            r["sampling"] != "1 sample"))
        yl = 30 + 18 * i
        s.append('<rect x="%d" y="%d" width="12" height="4" fill="%s"/>' % (W - R + 12, yl - 6, colour))
        s.append('<text x="%d" y="%d">%s, %s MHz</text>' % (W - R + 30, yl, b, mine[0]["clock_mhz"]))
    yl = 30 + 18 * len(names) + 14
    for j, (be, label) in enumerate([("fixed", "fixed"), ("float", "float"), ("double", "double")]):
        s.append(marker(be, W - R + 18, yl + 18 * j - 4, "black", True))
        s.append('<text x="%d" y="%d">%s</text>' % (W - R + 30, yl + 18 * j, label))
    yl += 18 * 3 + 8
    s.append('<text x="%d" y="%d">hollow: one sample a pixel</text>' % (W - R + 12, yl))
    s.append('<text x="%d" y="%d">filled: --aa 3</text>' % (W - R + 12, yl + 16))
    s.append("</svg>")
    open(os.path.join(ROOT, "bench", "time.svg"), "w").write("\n".join(s) + "\n")


def order(rows, board_names):
    rank = {"fixed": 0, "float": 1, "double": 2}
    samp = {"1 sample": 0}
    return sorted(rows, key=lambda r: (board_names.index(r["board"]) if r["board"] in board_names else 99,
                                       rank.get(r["backend"], 9), samp.get(r["sampling"], 1)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--boards", default="")
    ap.add_argument("--backends", default="")
    ap.add_argument("--update", action="store_true",
                    help="measure only the selected rows; keep the others of bench/time.csv")
    ap.add_argument("--check-only", action="store_true",
                    help="measure only make run's default against the table (CHECK); keep the other rows")
    ap.add_argument("--from-csv", action="store_true",
                    help="measure nothing: rewrite bench/time.md and bench/time.svg from bench/time.csv")
    a = ap.parse_args()
    names = boards()
    if a.check_only:
        with open(CSV) as f:
            rows = [r for r in csv.DictReader(f) if r["sampling"] != CHECK["sampling"]]
        rows.append(check_row(rows))
        print(rows[-1])
    elif a.from_csv:
        with open(CSV) as f:
            rows = list(csv.DictReader(f))
    else:
        os.makedirs(scenes_bench.OUT, exist_ok=True)
        run(["make", "-s", "build/host/rt"])
        rows = []
        clocks = {}
        for r in one_sample_rows():
            hz = clocks.setdefault(r["board"], float(board_info(["BOARD=" + r["board"]])["clock_hz"]))
            rows.append({"board": r["board"], "clock_mhz": "%g" % (hz / 1e6), "backend": r["backend"],
                         "sampling": "1 sample", "size": r["size"], "ipp": r["ipp"], "cpi": r["cpi"],
                         "cpp": r["cpp"], "cycles": r["cycles"], "seconds": seconds(r["cpp"], hz),
                         "psnr": r["psnr"], "max_error": r["max_error"], "area_psnr": r["area_psnr"],
                         "area_over8": r["area_over8"]})
        fresh = []
        for b in a.boards.split(",") if a.boards else names:
            info = board_info(["BOARD=" + b])
            hz = float(info["clock_hz"])
            for be in full_frame_backends(b, info["backends"].split()):
                if a.backends and be not in a.backends.split(","):
                    continue
                for label, variables, opts in SAMPLINGS:
                    r = measure_sampling(b, be, label, variables, opts, hz)
                    fresh.append(r)
                    print("%-12s %-7s %-6s %8s cycles/px %8s s  %6s dB area  %s" % (
                        b, be, label, r.get("cpp", ""), r.get("seconds", ""), r.get("area_psnr", ""),
                        r.get("note", "")), flush=True)
        # make run's default is measured again when its board and backend are
        check = ((not a.boards or CHECK["board"] in a.boards.split(","))
                 and (not a.backends or CHECK["backend"] in a.backends.split(",")))
        if a.update and os.path.exists(CSV):
            with open(CSV) as f:
                kept = [r for r in csv.DictReader(f) if r["sampling"] != "1 sample"]
            got = {(r["board"], r["backend"], r["sampling"]) for r in fresh}
            fresh += [r for r in kept if (r["board"], r["backend"], r["sampling"]) not in got
                      and (r["sampling"] != CHECK["sampling"] or not check)]
        rows += fresh
        if check:
            rows.append(check_row(rows))
    rows = order(rows, names)
    write_csv(CSV, KEYS, rows)
    write_md(rows)
    write_svg(rows)
    print("wrote bench/time.md, bench/time.csv and bench/time.svg")


if __name__ == "__main__":
    main()
