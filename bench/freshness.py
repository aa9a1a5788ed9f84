#!/usr/bin/env python3
"""Freshness counts: what keeps a bench file's figures from going stale
silently.

Each result file of bench/ that the README or docs cite records, beside its
figures, the deterministic counts of a few small runs of the same code
(instructions inside the render under QEMU -icount shift=0, cycles under
rp2040js, code bytes of the ELF), measured by the same `make bench` that
wrote its figures. `make test` measures them again
(tests/boards/speed-tests.sh): a count that has moved more than 1%
from the file's means the code the figures were measured on is gone, and
the check names the file and the command that measures it again.

RUNS is the one list of small runs and FILES the one list of bench files
with the command that writes each and the runs its figures rest on (a run
as close to the file's own figures as a few seconds allow).

  bench/freshness.py --write FILE...   measure FILE's runs, write its section
  bench/freshness.py --check [--lines] [FILE...]
                                       measure every run the files name
                                       once, compare (the test); --lines:
                                       the check lines alone, no summary
                                       (tests/boards/speed-tests.sh relays them)
  bench/freshness.py --list            the files and their commands
"""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.join(ROOT, "tests", "lib"))
TOLERANCE = 0.01  # a count may move this much before its file is stale

CARD = "SCENE=scenes/bench/card.nff DEPTH=3 SIZE=80x60"
PICO_CARD = "SCENE=scenes/bench/card.nff DEPTH=3 SIZE=40x30"  # rp2040js runs 2.5 M cycles/s
# name: (make variables, the report's key, what it counts)
RUNS = {
    "m3-fixed-card": ("BOARD=mps2-an385 BACKEND=fixed " + CARD, "render_instructions",
                      "instructions, the card at 80x60, mps2-an385 fixed"),
    "m3-fixed-card-aa3": ("BOARD=mps2-an385 BACKEND=fixed AA=3 " + CARD, "render_instructions",
                          "instructions, the card at 80x60 with --aa 3, mps2-an385 fixed"),
    "m3-fixed-card-generic": ("BOARD=mps2-an385 BACKEND=fixed SPECIALISE=0 " + CARD, "render_instructions",
                              "instructions, the card at 80x60, mps2-an385 fixed, generic firmware"),
    "m3-fixed-balls2": ("BOARD=mps2-an385 BACKEND=fixed SCENE=scenes/spd/balls-2.nff DEPTH=5 SIZE=64x64",
                        "render_instructions", "instructions, balls-2 at 64x64, mps2-an385 fixed"),
    "m4f-float-card": ("BOARD=mps2-an386 BACKEND=float " + CARD, "render_instructions",
                       "instructions, the card at 80x60, mps2-an386 float"),
    "pico-card-1core": ("BOARD=pico BACKEND=fixed CORES=1 PROGRESSIVE=0 " + PICO_CARD, "render_cycles",
                        "rp2040js cycles, the card at 40x30, pico fixed, one core, scanline order"),
    # the pico's default build: both cores, progressive display
    "pico-card-2cores": ("BOARD=pico BACKEND=fixed " + CARD, "frame_cycles",
                         "rp2040js cycles of the frame (render start to the panel's last byte), the card at "
                         "80x60, pico fixed, both cores, progressive display"),
    "m3-fixed-card-code": ("BOARD=mps2-an385 BACKEND=fixed " + CARD, "code_bytes",
                           "code bytes of the firmware, the card, mps2-an385 fixed"),
}
# bench file: the runs its figures rest on (make bench-STEM writes bench/STEM.md)
FILES = {
    "bench/scenes.md": ["m3-fixed-card", "m4f-float-card", "pico-card-1core"],
    "bench/time.md": ["m3-fixed-card", "m3-fixed-card-aa3", "m4f-float-card", "pico-card-1core"],
    "bench/boards.md": ["m3-fixed-balls2", "m4f-float-card", "pico-card-1core"],
    "bench/cores.md": ["pico-card-2cores", "m3-fixed-card"],
    "bench/pico-frames.md": ["pico-card-1core", "pico-card-2cores"],
    "bench/aa.md": ["m3-fixed-card-aa3"],
    "bench/filter.md": ["m3-fixed-card", "m4f-float-card"],
    "bench/specialise.md": ["m3-fixed-card", "m3-fixed-card-generic"],
    "bench/profile.md": ["m3-fixed-balls2"],
    "bench/bvh.md": ["m3-fixed-balls2"],
    "bench/prims.md": ["m3-fixed-balls2"],
    "bench/lib-size.md": ["m3-fixed-card-code"],
    "bench/results.md": ["m3-fixed-balls2"],
    "bench/threads.md": ["m3-fixed-balls2"],
    "bench/pico-xip.md": ["pico-card-1core"],
}


def command(path):
    """the command that measures a file's figures again"""
    return "make bench-" + os.path.splitext(os.path.basename(path))[0]


HEADING = "## Freshness counts"
ROW = re.compile(r"^\| `([\w-]+)` \| ([\d,]+) \|", re.M)
FW = os.path.join("build", "freshness")


def run(cmd, env=None):
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, env=env)


def measure(name):
    """The count of one run (an int), or a string saying why there is none."""
    variables, key, _ = RUNS[name]
    args = variables.split() + ([] if "AA=" in variables else ["AA=0"])
    env = dict(os.environ)
    env.setdefault("FW_ROOT", os.path.join(ROOT, FW))
    r = run(["make", "-s", "-j2", "firmware"] + args, env=env)
    if r.returncode:
        return "firmware build failed: " + " ".join(r.stderr.split()[-12:])
    if key == "code_bytes":
        info = dict(t.split("=", 1) for t in run(["make", "-s", "board-info"] + args, env=env).stdout.split()
                    if "=" in t)
        sizes = run([info["cross"] + "size", "-A", info["elf"]]).stdout
        code = sum(int(m.group(2)) for m in re.finditer(r"^(\.vectors|\.text|\.ARM\.exidx)\s+(\d+)", sizes, re.M))
        return code or "no code sections in " + info["elf"]
    png = os.path.join(env["FW_ROOT"], name + ".png")
    r = run(["make", "-s", "board-run", "RUN_OUT=" + png] + args, env=env)
    m = re.findall(r"^%s (\d+)\b" % key, r.stdout, re.M)
    if r.returncode or not m:
        return "board run failed (status %d): %s" % (r.returncode, " ".join((r.stdout + r.stderr).split()[-12:]))
    return int(m[-1])


def recorded(path):
    """{run: count} of a file's freshness section"""
    with open(os.path.join(ROOT, path)) as f:
        text = f.read()
    at = text.find(HEADING)
    return {} if at < 0 else {m.group(1): int(m.group(2).replace(",", "")) for m in ROW.finditer(text[at:])}


def write(path, counts):
    with open(os.path.join(ROOT, path)) as f:
        text = f.read()
    at = text.find(HEADING)
    text = (text[:at] if at >= 0 else text).rstrip("\n") + "\n\n"
    text += HEADING + "\n\n"
    text += ("Measured with these figures; `make test` measures them again and fails when one moves\n"
             "more than %d%% (bench/freshness.py: then `%s` measures the figures again).\n\n"
             % (round(TOLERANCE * 100), command(path)))
    text += "| run | count | what |\n|---|---|---|\n"
    for name in FILES[path]:
        text += "| `%s` | %s | %s |\n" % (name, format(counts[name], ","), RUNS[name][2])
    with open(os.path.join(ROOT, path), "w") as f:
        f.write(text)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--write", action="store_true")
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--list", action="store_true")
    ap.add_argument("--lines", action="store_true")
    ap.add_argument("files", nargs="*")
    a = ap.parse_args()
    files = a.files or sorted(FILES)
    unknown = [f for f in files if f not in FILES]
    if unknown:
        sys.exit("bench/freshness.py: no freshness runs for %s (FILES lists %s)" % (
            ", ".join(unknown), ", ".join(sorted(FILES))))
    if a.list:
        for f in sorted(FILES):
            print("%-22s %s" % (f, command(f)))
        return 0
    names = sorted({n for f in files for n in FILES[f]})
    counts = {}
    for n in names:
        counts[n] = measure(n)
        if not a.lines:
            print("  %-22s %s" % (n, counts[n]), flush=True)
    if a.write:
        failed = [n for n in names if not isinstance(counts[n], int)]
        if failed:
            sys.exit("bench/freshness.py: no count for %s" % ", ".join(failed))
        for f in files:
            write(f, counts)
            print("wrote the freshness counts of " + f)
        return 0
    from check import check, summary
    for f in files:
        have = recorded(f)
        for n in FILES[f]:
            now = counts[n]
            if n not in have:
                check(False, "%s records no count of %s: `%s` writes it" % (f, n, command(f)))
            elif not isinstance(now, int):
                check(False, "%s: %s: %s" % (f, n, now))
            else:
                moved = abs(now - have[n]) / have[n]
                check(moved <= TOLERANCE, "%s: %s %s now, %s recorded (%+.2f%%)%s" % (
                    f, n, format(now, ","), format(have[n], ","), 100.0 * (now - have[n]) / have[n],
                    "" if moved <= TOLERANCE else ": its figures are stale; `%s` measures them again" % command(f)))
    return summary("freshness") if not a.lines else 1 if any(
        not isinstance(c, int) for c in counts.values()) else 0


if __name__ == "__main__":
    sys.exit(main())
