#!/usr/bin/env python3
"""Boards with two cores: how the frame splits (app/firmware/bands.c).

For each board whose board.mk sets BOARD_CORES above 1 and each scene of
boards_bench.py (fixed point, 64x64, depth 5) it runs the firmware on one
core (CORES=1) and on all, under QEMU -icount (exact counts) or the
board's own runner (the pico: rp2040js stepping both cores, each counting
its own SysTick cycles), and records one core's count per pixel
(instructions, or cycles where the board counts those: the report's
unit), each core's render and waits on the parallel timeline, the
critical path and the speed-up, and whether the image is byte-identical
to the one-core run. A board that counts cycles (the pico) also renders
the benchmark scenes of bench/scenes.md (card, depth 3; picolib, depth
6) at 320x240 on one core and on all: each frame's cycles and time at the
board's clock. It writes bench/cores.md and bench/cores.csv (and
bench/cores-frames.csv).

  bench/cores_bench.py [--boards a,b] [--scenes a,b]
"""
import argparse
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boards_bench import ROOT, SCENES, board_info, boards, run, scene_path  # noqa: E402

OUT = os.path.join(ROOT, "build", "bench-cores")
SIZE = "64x64"
# whole frames on a board that counts cycles: bench/scenes.md's scenes
FRAME_SIZE = "320x240"
FRAME_SCENES = {"card": 3, "picolib": 6}  # scene: its ray-tree depth


def report(board, scene, cores, size=SIZE, depth=5, path=None):
    args = ["BOARD=" + board, "SCENE=" + (path or scene_path(scene)), "SIZE=" + size, "DEPTH=%d" % depth, "CORES=%d" % cores,
            "AA=0", "PROGRESSIVE=0"]  # (scanline order: the bands' split; bench/pico-frames.md has progressive display)
    if run(["make", "-s", "-j2", "firmware"] + args, check=False).returncode:
        return None, None
    png = os.path.join(OUT, "%s-%s-%s-%d.png" % (board, scene, size, cores))
    r = run(["make", "-s", "board-run", "RUN_OUT=" + png] + args, check=False)
    if r.returncode:
        return None, None
    return {k: int(v) for k, v in re.findall(r"^(\w+) (\d+)$", r.stdout, re.M)}, png


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--boards", default="")
    ap.add_argument("--scenes", default="")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    run(["make", "-s", "build/host/rt"])
    sel = a.boards.split(",") if a.boards else [b for b in boards() if int(board_info(["BOARD=" + b])["cores"]) > 1]
    scenes = a.scenes.split(",") if a.scenes else SCENES
    rows, frames, frame_hz = [], [], 0.0
    for b in sel:
        cores = int(board_info(["BOARD=" + b])["cores"])
        for s in scenes:
            one, png1 = report(b, s, 1)
            par, pngn = report(b, s, cores)
            if not one or not par:
                print("%-12s %-10s failed" % (b, s), flush=True)
                continue
            px = par["pixels"]
            unit = "instructions" if "critical_path_instructions" in par else "cycles"
            single = one["render_" + unit]
            work = sum(par["core%d_render_%s" % (c, unit)] for c in range(cores))
            same = run(["build/host/rt", "compare", png1, pngn, "--max-error", "0"], check=False).returncode == 0
            row = {"board": b, "scene": s, "unit": unit, "one_core_per_px": round(single / px),
                   "critical_path_per_px": round(par["critical_path_" + unit] / px),
                   "ratio": "%.4f" % (par["critical_path_" + unit] / single),
                   "speedup": "%.2f" % (single / par["critical_path_" + unit]),
                   "work": "%.4f" % (work / single),
                   "identical": "yes" if same else "NO"}
            for c in range(cores):
                row["core%d_per_px" % c] = round(par["core%d_render_%s" % (c, unit)] / px)
                row["core%d_wait_per_px" % c] = round(par["core%d_wait_%s" % (c, unit)] / px)
                row["core%d_bands" % c] = par["core%d_bands" % c]
            rows.append(row)
            print("%-12s %-10s one core %6d  critical path %6d  (%s, %sx)  image %s" % (
                b, s, row["one_core_per_px"], row["critical_path_per_px"], row["ratio"], row["speedup"],
                "same" if same else "DIFFERENT"), flush=True)
        if not rows or rows[-1]["board"] != b or rows[-1]["unit"] != "cycles" or a.scenes:
            continue
        hz = frame_hz = float(board_info(["BOARD=" + b])["clock_hz"])
        for s, depth in FRAME_SCENES.items():
            path = os.path.join("scenes", "bench", s + ".nff")
            one, png1 = report(b, s, 1, FRAME_SIZE, depth, path)
            par, pngn = report(b, s, cores, FRAME_SIZE, depth, path)
            if not one or not par:
                print("%-12s %-10s %s failed" % (b, s, FRAME_SIZE), flush=True)
                continue
            px = par["pixels"]
            same = run(["build/host/rt", "compare", png1, pngn, "--max-error", "0"], check=False).returncode == 0
            frame = {"board": b, "scene": s, "depth": depth, "size": FRAME_SIZE,
                     "one_core_cycles": one["render_cycles"], "cycles": par["render_cycles"],
                     "critical_path_cycles": par["critical_path_cycles"],
                     "share": "%.4f" % (par["render_cycles"] / one["render_cycles"]),
                     "critical_path_share": "%.4f" % (par["critical_path_cycles"] / one["render_cycles"]),
                     "one_core_s": "%.2f" % (one["render_cycles"] / hz), "s": "%.2f" % (par["render_cycles"] / hz),
                     "one_core_frame_ms": one["frame_ms"], "frame_ms": par["frame_ms"],
                     "per_px": round(par["render_cycles"] / px), "one_core_per_px": round(one["render_cycles"] / px),
                     "identical": "yes" if same else "NO"}
            frames.append(frame)
            print("%-12s %-10s %s one core %.2f s, %d cores %.2f s (%s; critical path %s)  image %s" % (
                b, s, FRAME_SIZE, one["render_cycles"] / hz, cores, par["render_cycles"] / hz, frame["share"],
                frame["critical_path_share"], "same" if same else "DIFFERENT"), flush=True)
    if not rows:
        print("no board with more than one core")
        return 0
    keys = list(rows[0].keys())
    with open(os.path.join(ROOT, "bench", "cores.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(ROOT, "bench", "cores.md"), "w") as f:
        f.write("# Two cores: the frame split between them\n\n")
        f.write("Generated by `make bench` (`bench/cores_bench.py`): fixed point, %s, depth 5; mps2-an521\n"
                "under QEMU `-icount` (exact instruction counts), the pico under rp2040js (both cores stepped\n"
                "by their cycles, each counting its own with SysTick). Per pixel, in the unit column's count:\n"
                "one core (`CORES=1`, the same firmware), each core's render and its waits on the parallel\n"
                "timeline, the critical path (the later core's render plus waits; docs/boards.md, \"Two\n"
                "cores\"), its share of one core's count, the speed-up, both cores' work over one core's, and\n"
                "the image against the one-core run.\n\n"
                % SIZE)
        f.write("| board | scene | unit | one core | core 0 (bands) | core 1 (bands) | waits | critical path | share | "
                "speed-up | work | image |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s | %s | %s | %d | %d (%d) | %d (%d) | %d / %d | %d | %s | %sx | %s | %s |\n" % (
                r["board"], r["scene"], r["unit"], r["one_core_per_px"], r["core0_per_px"], r["core0_bands"],
                r["core1_per_px"], r["core1_bands"], r["core0_wait_per_px"], r["core1_wait_per_px"],
                r["critical_path_per_px"], r["ratio"], r["speedup"], r["work"],
                "identical" if r["identical"] == "yes" else "DIFFERENT"))
        if frames:
            f.write("\nWhole frames on a board that counts cycles, the benchmark scenes of `bench/scenes.md` at %s,\n"
                    "one sample a pixel: the render's cycles (`render_cycles`: on two cores the frame on core 0 from\n"
                    "the render's start to its end, its own display output left out) a pixel and in seconds at the\n"
                    "board's clock (%g MHz), on one core and on both, the share of one core's (and the critical\n"
                    "path's share), and `frame_ms`, the board's own frame time with the panel's output. The\n"
                    "emulator has no SRAM bank contention between the cores; published two-core figures on the\n"
                    "RP2040 are 1.875x (the PicoLibSDK ray tracer demo, 15 s to 8 s) and 1.93x (CoreMark, its code\n"
                    "in SRAM), so expect about 1.85x to 1.95x on the chip.\n\n" % (FRAME_SIZE, frame_hz / 1e6))
            f.write("| board | scene | depth | one core: cycles/px | s | frame_ms | two cores: cycles/px | s | frame_ms | "
                    "share | critical path share | speed-up | image |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
            for r in frames:
                f.write("| %s | %s | %d | %d | %s | %d | %d | %s | %d | %s | %s | %.2fx | %s |\n" % (
                    r["board"], r["scene"], r["depth"], r["one_core_per_px"], r["one_core_s"], r["one_core_frame_ms"],
                    r["per_px"], r["s"], r["frame_ms"], r["share"], r["critical_path_share"],
                    r["one_core_cycles"] / r["cycles"], "identical" if r["identical"] == "yes" else "DIFFERENT"))
    if frames:
        with open(os.path.join(ROOT, "bench", "cores-frames.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(frames[0].keys()))
            w.writeheader()
            w.writerows(frames)
    print("wrote bench/cores.md and bench/cores.csv")
    return 0 if all(r["identical"] == "yes" for r in rows + frames) else 1


if __name__ == "__main__":
    sys.exit(main())
