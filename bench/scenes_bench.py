#!/usr/bin/env python3
"""The community's benchmark scenes on every board and backend, beside the
published microcontroller figures.

The scenes of scenes/bench (card: the Arduino/RX business-card ray tracer's
scene, 3 levels; picolib: like the PicoLibSDK RP2040 demo, depth 6;
whitted: Whitted's 1980 picture, depth 5) are rendered one sample per pixel
by each board's firmware (one core) and each backend it offers, at
320x240 as the published figures are (--size changes it: a square frame
shows more of the scene and costs about 10% less a pixel), and this records
  - instructions per pixel inside the render (QEMU -icount shift=0);
  - estimated cycles per pixel: the run's instruction mix at 80x60 priced
    by bench/cycles.py (the core's documented timings; no wait states),
    as cycles per instruction times the instructions per pixel;
  - the error against the exact double build at the same samples (the
    number format's) and against the pixel-area image (rt --double
    --spp 16 --texture-filter off: what a viewer sees; one sample per
    pixel aliases).
It writes bench/scenes.md and bench/scenes.csv.

A build variant's rows (board.mk's BOARD_BENCH_VARIANTS) are left out
where they equal the board's own in every column (the variant builds the
same code for these scenes: the pico's PICO_DIVIDER=0, whose divider only
64-bit quotients use, which these scenes' pixel paths have none of).

  bench/scenes_bench.py [--boards a,b] [--scenes a,b] [--size WxH] [--no-cycles] [--update]
  bench/scenes_bench.py --from-csv
"""
import argparse
import csv
import math
import os
import re
import sys

sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from boards_bench import ROOT, board_info, boards, code_ram, cpi_of, cycles, drop_unchanged, full_frame_backends, run, variants, write_csv  # noqa: E402
from boards_bench import measure as boards_measure  # noqa: E402

OUT = os.path.join(ROOT, "build", "bench-scenes")
SCENES = {"card": 3, "picolib": 6, "whitted": 5}  # scene: its ray-tree depth
CYCLE_SIZE = "80x60"  # the same framing as 320x240
# boards whose display bounds the frame: their panel's size (its framing
# differs, so does the figure per pixel)
PANEL_SIZE = {"lm3s6965evb": "128x64"}

# Published times (the README of hirakuni45/RX, RAYTRACER_sample; the RX
# times include drawing to the panel) and the PicoLibSDK demo's stated 15 s
# on one RP2040 core at 125 MHz, as cycles per pixel at 320x240.
PUBLISHED = [
    ("Renesas RX72N", "single, fsqrt", "card", 240e6, 0.342),
    ("Renesas RX65N", "single, fsqrt", "card", 120e6, 0.733),
    ("Renesas RX64M", "single, fsqrt", "card", 120e6, 0.700),
    ("Renesas RX62N", "single, no fsqrt", "card", 96e6, 1.875),
    ("STM32F7 (second-hand)", "single", "card", 200e6, 0.620),
    ("Renesas RX220", "none (soft float)", "card", 32e6, 291.0),
    ("RP2040, PicoLibSDK", "none (soft float)", "picolib", 125e6, 15.0),
]


def scene_path(scene):
    return os.path.join("scenes", "bench", scene + ".nff")


def measure(board, backend, scene, size, variant=""):
    return boards_measure(board, backend, scene, size, path=scene_path(scene), depth=SCENES[scene], out=OUT,
                          variant=variant)


def reference(scene, size, fmt, spp):
    # cached per build of rt: a reference from an older build would be stale
    ref = os.path.join(OUT, "ref-%s-%s-%s-spp%d-%d.png" % (scene, size, fmt, spp,
                                                           int(os.path.getmtime("build/host/rt"))))
    if not os.path.exists(ref):
        run(["build/host/rt", scene_path(scene), "-o", ref, "--double", "--size", size, "--depth",
             str(SCENES[scene]), "--format", fmt, "--spp", str(spp), "--quiet"]
            + (["--texture-filter", "off"] if spp > 1 else []))  # the pixel-area image: point-sampled
    return ref


def error(png, ref):
    line = run(["build/host/rt", "compare", png, ref], check=False).stdout
    m = re.search(r"psnr (\S+) dB\s+max-error (\d+)\s+over2 \S+\s+over8 (\S+)%", line)
    return m.group(1), int(m.group(2)), m.group(3)


def cpi(board, backend, scene):
    m = measure(board, backend, scene, CYCLE_SIZE)
    return cpi_of(m, board, os.path.join(OUT, "cycles-%s-%s-%s.json" % (board, backend, scene))) if m else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--boards", default="")
    ap.add_argument("--scenes", default="")
    ap.add_argument("--size", default="320x240")
    ap.add_argument("--no-cycles", action="store_true")
    ap.add_argument("--update", action="store_true",
                    help="re-measure only the selected rows; keep the others of bench/scenes.csv")
    ap.add_argument("--from-csv", action="store_true",
                    help="measure nothing: rewrite bench/scenes.md (and the csv) from bench/scenes.csv")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    if a.from_csv:
        a.update = True
    else:
        run(["make", "-s", "build/host/rt"])
    rows = []
    sel = [] if a.from_csv else a.boards.split(",") if a.boards else boards()
    for b, v in [(b, v) for b in sel for v in variants(b)]:
        label = b + (" " + v if v else "")
        backends = full_frame_backends(b, board_info(["BOARD=" + b])["backends"].split())
        for be in backends[:1] if v else backends:
            for s in (a.scenes.split(",") if a.scenes else list(SCENES)):
                size = PANEL_SIZE.get(b, a.size)
                m = measure(b, be, s, size, variant=v)
                if not m:
                    print("%-12s %-7s %-8s failed" % (label, be, s), flush=True)
                    rows.append({"board": label, "backend": be, "scene": s})
                    continue
                fmt = m["info"]["format"]
                psnr, maxerr, _ = error(m["png"], reference(s, size, fmt, 1))
                apsnr, _, aover8 = error(m["png"], reference(s, size, fmt, 16))
                c, cpp, how = cycles(m, lambda: None if a.no_cycles else cpi(b, be, s))
                code, ram = code_ram(m["info"]["cross"], m["info"]["elf"])
                fpu = "hard" if be == "float" and "float-abi=hard" in m["info"]["fpu"] else "-"
                row = {"board": label, "backend": be, "fpu": fpu, "scene": s,
                       "depth": SCENES[s], "size": size, "ipp": m["ipp"],
                       "cpi": "%.3f" % c if c else "", "cpp": cpp, "cycles": how,
                       "psnr": psnr, "max_error": maxerr, "area_psnr": apsnr, "area_over8": aover8,
                       "code": code, "ram": ram}
                rows.append(row)
                print("%-12s %-7s %-8s %7d instr/px %7s cycles/px  %6s dB exact  %6s dB area" % (
                    label, be, s, m["ipp"], row["cpp"], psnr, apsnr), flush=True)
    if a.update:
        with open(os.path.join(ROOT, "bench", "scenes.csv")) as f:
            kept = list(csv.DictReader(f))
        fresh = {(r["board"], r["backend"], r["scene"]): r for r in rows}
        rows = [fresh.pop((r["board"], r["backend"], r["scene"]), r) for r in kept] + list(fresh.values())
        for r in rows:  # rows written before the column existed: estimated
            if not r.get("cycles") and r.get("cpp"):
                r["cycles"] = "estimated"
    keys = ["board", "backend", "fpu", "scene", "depth", "size", "ipp", "cpi", "cpp", "cycles", "psnr", "max_error",
            "area_psnr", "area_over8", "code", "ram"]
    rows = drop_unchanged(rows)
    write_csv(os.path.join(ROOT, "bench", "scenes.csv"), keys, rows)
    with open(os.path.join(ROOT, "bench", "scenes.md"), "w") as f:
        f.write("# The benchmark scenes on every board (bench/scenes_bench.py)\n\n")
        f.write("One sample per pixel, %s, one core; instructions per pixel inside the render\n"
                "(QEMU -icount shift=0; the pico's rp2040js); cycles estimated from the\n"
                "instruction mix of an 80x60 render priced with the core's documented timings\n"
                "(bench/cycles.py: no flash wait states, so not the stm32f4's 5 behind its ART\n"
                "accelerator either; QEMU's STM32F405 has no cycle counter), except the pico's, counted by rp2040js\n"
                "over the whole render (its Cortex-M0+ timing: no flash wait states or XIP\n"
                "cache; its SIO divider charged 16 cycles a division, the silicon's 8; one core in\n"
                "scanline order: bench/cores.md and bench/pico-frames.md have both); the pico's fixed\n"
                "backend only (its soft float at 320x240 is 10 to 20 minutes of emulation a frame:\n"
                "bench/boards.md has it at 64x64); PSNR against the exact double build at the same samples and\n"
                "against the pixel-area image (rt --double --spp 16 --texture-filter off).\n"
                "A build variant's rows (board.mk's BOARD_BENCH_VARIANTS) are left out where they\n"
                "equal the board's own in every column: the pico's PICO_DIVIDER=0 builds the same\n"
                "code for these scenes (its divider serves only 64-bit quotients, which they do not\n"
                "compute).\n\n" % a.size)
        f.write("Published figures, cycles per pixel at 320x240 (time x clock / 76,800):\n\n")
        f.write("| chip | FPU | scene | clock | time | cycles/px |\n|---|---|---|---|---|---|\n")
        for chip, fpu, s, hz, t in PUBLISHED:
            f.write("| %s | %s | %s | %g MHz | %g s | %s |\n" % (chip, fpu, s, hz / 1e6, t,
                                                                  format(round(t * hz / 76800), ",")))
        f.write("\n| board | backend | float in hardware | scene | depth | size | instr/px | CPI | cycles/px | cycles | "
                "PSNR exact (dB) | max error | PSNR pixel area (dB) | > 8/255 vs area | code (B) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s |\n" % " | ".join(str(r.get(k, "failed" if k == "ipp" else "")) for k in
                                          ["board", "backend", "fpu", "scene", "depth", "size", "ipp", "cpi", "cpp", "cycles", "psnr",
                                           "max_error", "area_psnr", "area_over8", "code"]))
    print("wrote bench/scenes.md and bench/scenes.csv")


if __name__ == "__main__":
    main()
