#!/usr/bin/env python3
"""Every board and backend: instructions and estimated cycles per pixel, error.

For each board (platform/*/board.mk), each backend it offers and each
scene (the SPD size-1 and size-2 scenes and the default scene) it builds
the firmware at 64x64, depth 5, runs it under QEMU (-icount shift=0: exact
instruction counts) and records
  - instructions per pixel inside the render (the firmware's own count);
  - estimated cycles per pixel: the run's instruction mix priced with the
    core's documented timings (bench/cycles.py, which states the model),
    measured on a 32x32 render of the same scene and applied to the 64x64
    count as cycles per instruction (--cycles-scenes picks the scenes;
    others get none);
  - PSNR and max channel error against the exact double reference (the
    host's rt --double at the same size, in the board's pixel format);
  - code (text + vectors + exidx) and static RAM (data + bss) of the ELF.
A board with two cores renders on one here (CORES=1), like the others, and
a panel in scanline order (PROGRESSIVE=0: bench/pico-frames.md has the
other orders);
bench/cores_bench.py measures its split. It writes bench/boards.md and
bench/boards.csv.

  bench/boards_bench.py [--boards a,b] [--scenes a,b] [--cycles-scenes a,b] [--no-cycles] [--update]
  bench/boards_bench.py --from-csv
"""
import argparse
import csv
import json
import math
import os
import re
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "bench-boards")
SCENES = ["balls-1", "gears-1", "rings-1", "teapot-1", "tetra-1",
          "balls-2", "rings-2", "teapot-2", "tetra-2", "showpiece"]
CYCLE_SCENES = ["balls-2", "showpiece"]
SIZE = "64x64"
SINK_CALLBACKS = ["stream_begin", "stream_flush", "stream_end", "oled_begin", "oled_flush", "oled_end"]
CYCLE_SIZE = "32x32"


def run(cmd, check=True):
    return subprocess.run(cmd, cwd=ROOT, check=check, capture_output=True, text=True)


def scene_path(scene):
    p = os.path.join("scenes", "spd", scene + ".nff")
    return p if os.path.exists(os.path.join(ROOT, p)) else os.path.join("scenes", scene + ".nff")


def board_info(args):
    line = run(["make", "-s", "board-info"] + args).stdout
    return dict(t.split("=", 1) for t in shlex.split(line))


def boards():
    return sorted(d for d in os.listdir(os.path.join(ROOT, "platform"))
                  if os.path.exists(os.path.join(ROOT, "platform", d, "board.mk")))


def code_ram(cross, elf):
    """Code bytes, and RAM bytes: .data and .bss, and what reset copies
    from flash to run from RAM (the pico's code and scene tables)."""
    out = run([cross + "objdump", "-h", elf]).stdout
    sec = {m.group(1): (int(m.group(2), 16), m.group(3) != m.group(4))
           for m in re.finditer(r"^\s*\d+\s+(\.\S+)\s+([0-9a-f]+)\s+([0-9a-f]+)\s+([0-9a-f]+)", out, re.M)}
    code = sum(sec.get(s, (0, 0))[0] for s in (".vectors", ".text", ".ARM.exidx"))
    copied = sum(size for name, (size, moved) in sec.items() if moved and name in (".text", ".scene"))
    return code, sec.get(".data", (0, 0))[0] + sec.get(".bss", (0, 0))[0] + copied


def measure(board, backend, scene, size, path=None, depth=5, out=OUT, variant=""):
    """Build and run the firmware for scene (at path, default the SPD or demo
    scene of that name), with the board's build variant (make variables,
    board.mk's BOARD_BENCH_VARIANTS): its instructions per pixel (and cycles
    per pixel, where the port counts them), image (in out), facts."""
    # one core on every board (a two-core board's split: bench/cores_bench.py)
    args = ["BOARD=" + board, "BACKEND=" + backend, "SCENE=" + (path or scene_path(scene)), "SIZE=" + size,
            "DEPTH=%d" % depth, "CORES=1", "PROGRESSIVE=0", "AA=0", "DITHER=0"] + variant.split()
    r = run(["make", "-s", "-j2", "firmware"] + args, check=False)
    if r.returncode:
        return None
    info = board_info(args)
    png = os.path.join(out, "%s%s-%s-%s-%s.png" % (board, variant.replace(" ", "").replace("=", ""), backend, scene, size))
    r = run(["make", "-s", "board-run", "RUN_OUT=" + png] + args, check=False)
    m = re.search(r"^instructions_per_pixel (\d+)$", r.stdout, re.M)
    if r.returncode or not m:
        return None
    c = re.search(r"^cycles_per_pixel (\d+)$", r.stdout, re.M)
    return {"ipp": int(m.group(1)), "cpp": int(c.group(1)) if c else None, "png": png, "info": info, "args": args}


# rp2040js emulates 2.5 to 5 million cycles a second: a 320x240 card frame
# in the pico's soft float (6x its fixed build's cycles) is 10 to 20
# minutes of emulation, with --aa 3 more than an hour. The full frames
# (bench/scenes.md, bench/time.md) measure its fixed backend only;
# bench/boards.md has its soft float at 64x64.
FULL_FRAME_BACKENDS = {"pico": ["fixed"]}


def full_frame_backends(board, backends):
    """the backends of board the 320x240 benches measure"""
    return [b for b in backends if b in FULL_FRAME_BACKENDS.get(board, backends)]


def variants(board):
    """The board itself, then its build variants (BOARD_BENCH_VARIANTS), which
    are measured in the board's first backend only."""
    return [""] + [v.replace(",", " ") for v in board_info(["BOARD=" + board])["variants"].split()]


def cycles(m, estimate):
    """Cycles per instruction and per pixel: the port's count when it has one
    (its emulator's), else estimate() (bench/cycles.py's pricing)."""
    if m["cpp"]:
        return m["cpp"] / m["ipp"], m["cpp"], "counted"
    c = estimate()
    return (c, round(m["ipp"] * c), "estimated") if c else (None, "", "")


def error(scene, png, fmt, size):
    # cached per build of rt: a reference from an older build would be stale
    ref = os.path.join(OUT, "ref-%s-%s-%s-%d.png" % (scene, fmt, size, int(os.path.getmtime("build/host/rt"))))
    if not os.path.exists(ref):
        run(["build/host/rt", scene_path(scene), "-o", ref, "--double", "--size", size, "--depth", "5",
             "--format", fmt, "--quiet"])
    line = run(["build/host/rt", "compare", png, ref], check=False).stdout
    m = re.search(r"psnr (\S+) dB\s+max-error (\d+)", line)
    return (math.inf if m.group(1) == "inf" else float(m.group(1))), int(m.group(2))


def cpi(board, backend, scene):
    """Cycles per instruction inside rt_render (sink excluded) of a CYCLE_SIZE render."""
    m = measure(board, backend, scene, CYCLE_SIZE)
    return cpi_of(m, board, os.path.join(OUT, "cycles-%s-%s-%s.json" % (board, backend, scene))) if m else None


def cpi_of(m, board, js):
    """Cycles per instruction of the render measure() ran (its ELF), the figures to js."""
    elf = m["info"]["elf"]
    # the display sink's callbacks are counted apart, as the firmware does
    syms = run([m["info"]["cross"] + "nm", elf]).stdout.split()
    sink = [a for n in SINK_CALLBACKS if n in syms for a in ("--exclude-symbol", n)]
    r = run([sys.executable, "bench/cycles.py", elf, "--machine", board, "--from-symbol", "rt_render", "--top", "0",
             "--json", js] + sink, check=False)
    if r.returncode or not os.path.exists(js):
        return None
    with open(js) as f:
        d = json.load(f)
    return d["cycles"]["typ"] / d["instructions"]


def drop_unchanged(rows, label_keys=("board", "backend", "scene")):
    """rows without a build variant's rows that equal the board's own in
    every figure: there the variant does not change the code (the pico's
    PICO_DIVIDER=0 where the scene has no 64-bit division on its pixel
    path), so the row would measure nothing."""
    def key(r):
        return (r["board"].split(" ")[0],) + tuple(r.get(k) for k in label_keys[1:])
    own = {key(r): r for r in rows if " " not in r["board"]}
    return [r for r in rows if " " not in r["board"] or key(r) not in own or any(
        str(r.get(k, "")) != str(own[key(r)].get(k, "")) for k in r if k not in label_keys)]


def write_csv(path, keys, rows):
    """rows (dicts) to a CSV file with these columns, missing ones empty."""
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in keys})


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--boards", default="")
    ap.add_argument("--scenes", default="")
    ap.add_argument("--cycles-scenes", default=",".join(CYCLE_SCENES))
    ap.add_argument("--no-cycles", action="store_true")
    ap.add_argument("--update", action="store_true",
                    help="re-measure only the selected rows; keep the others of bench/boards.csv")
    ap.add_argument("--from-csv", action="store_true",
                    help="measure nothing: rewrite bench/boards.md (and the csv) from bench/boards.csv")
    a = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    if a.from_csv:
        a.update = True
    else:
        run(["make", "-s", "build/host/rt"])
    sel_boards = [] if a.from_csv else a.boards.split(",") if a.boards else boards()
    scenes = a.scenes.split(",") if a.scenes else SCENES
    cyc_scenes = [] if a.no_cycles else a.cycles_scenes.split(",")
    rows = []
    for b, v in [(b, v) for b in sel_boards for v in variants(b)]:
        backends = board_info(["BOARD=" + b])["backends"].split()
        label = b + (" " + v if v else "")
        for be in backends[:1] if v else backends:
            for s in scenes:
                m = measure(b, be, s, SIZE, variant=v)
                if not m:
                    print("%-12s %-7s %-10s failed" % (label, be, s), flush=True)
                    rows.append({"board": label, "backend": be, "scene": s})
                    continue
                psnr, maxerr = error(s, m["png"], m["info"]["format"], SIZE)
                code, ram = code_ram(m["info"]["cross"], m["info"]["elf"])
                c, cpp, _ = cycles(m, lambda: cpi(b, be, s) if s in cyc_scenes else None)
                row = {"board": label, "backend": be, "scene": s, "ipp": m["ipp"],
                       "cpi": "%.3f" % c if c else "", "cpp": cpp,
                       "psnr": "inf" if psnr == math.inf else "%.2f" % psnr, "max_error": maxerr,
                       "code": code, "ram": ram}
                rows.append(row)
                print("%-12s %-7s %-10s %8d instr/px %8s cycles/px %8s dB  code %6d  ram %7d" % (
                    label, be, s, m["ipp"], row["cpp"], row["psnr"], code, ram), flush=True)
    if a.update:
        # the rows measured now replace theirs; the others are kept, in order
        with open(os.path.join(ROOT, "bench", "boards.csv")) as f:
            kept = list(csv.DictReader(f))
        fresh = {(r["board"], r["backend"], r["scene"]): r for r in rows}
        merged = []
        for r in kept:
            k = (r["board"], r["backend"], r["scene"])
            if k in fresh:
                merged.append(fresh.pop(k))
            else:
                r["ipp"] = int(r["ipp"]) if r.get("ipp") else ""
                merged.append(r)
        rows = merged + list(fresh.values())
    keys = ["board", "backend", "scene", "ipp", "cpi", "cpp", "psnr", "max_error", "code", "ram"]
    rows = drop_unchanged(rows)
    write_csv(os.path.join(ROOT, "bench", "boards.csv"), keys, rows)
    with open(os.path.join(ROOT, "bench", "boards.md"), "w") as f:
        f.write("# Boards and backends (bench/boards_bench.py)\n\n")
        f.write("64x64, depth 5; instructions per pixel inside the render (QEMU -icount shift=0);\n"
                "cycles per pixel estimated from the instruction mix of a 32x32 render priced with\n"
                "the core's documented timings (bench/cycles.py), except on the pico, whose cycles\n"
                "are rp2040js's count of the whole render (no flash wait states or XIP cache\n"
                "modelled); PSNR and max error against the\n"
                "exact double reference in the board's pixel format; code and static RAM of the ELF.\n"
                "A build variant's row (board.mk's BOARD_BENCH_VARIANTS) is left out where it equals\n"
                "the board's own in every column: there the variant builds the same code.\n\n")
        f.write("| board | backend | scene | instr/px | CPI | est. cycles/px | PSNR (dB) | max error | code (B) | RAM (B) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s |\n" % " | ".join(str(r.get(k, "failed" if k == "ipp" else "")) for k in keys))
    print("wrote bench/boards.md and bench/boards.csv")


if __name__ == "__main__":
    main()
