#!/usr/bin/env python3
"""Self-test of bench/cycles.py: exact instruction counts on hand-written loops.

Builds bench/cycles-tests/*.S for every board whose toolchain and QEMU are
installed (Cortex-M3 mps2-an385 and lm3s6965evb, Cortex-M4F mps2-an386,
Cortex-M0 microbit, SiFive E31 sifive_e), runs cycles.py with --from-symbol
on each hand-counted function and checks the instruction count and mix
exactly, a few cycle figures against the model worked by hand, and that the
log's special cases (blocks re-translated around I/O, blocks stopped by the
icount budget) were met. Prints 'cycles-selftest: N passed, M failed'
(tests/lib/check.py); exits 1 on a failure.

    bench/cycles_selftest.py [--n N]
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SRC = os.path.join(ROOT, "bench", "cycles-tests")
OUT = os.path.join(ROOT, "build", "cycles-selftest")
CYCLES = os.path.join(ROOT, "bench", "cycles.py")
sys.path.insert(0, os.path.join(ROOT, "tests", "lib"))
from check import check, summary  # noqa: E402  (the tests' harness)

# name -> (machine, compiler flags, defines)
ARM = ["arm-none-eabi-gcc", "-mthumb", "-nostdlib", "-T", os.path.join(SRC, "arm.ld"), "-DRAM_TOP=0x20004000"]
BOARDS = {
    "m3-an385": ("mps2-an385", ARM + ["-mcpu=cortex-m3", "-DHAVE_V7M", "-DMMIO_ADDR=0x40000004"], "arm_loops.S"),
    "m3-lm3s": ("lm3s6965evb", ARM + ["-mcpu=cortex-m3", "-DHAVE_V7M", "-DMMIO_ADDR=0x400FE000"], "arm_loops.S"),
    "m4-an386": ("mps2-an386", ARM + ["-mcpu=cortex-m4", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16", "-DHAVE_V7M",
                                      "-DHAVE_FPU", "-DMMIO_ADDR=0x40000004"], "arm_loops.S"),
    "m0-microbit": ("microbit", ARM + ["-mcpu=cortex-m0", "-DMMIO_ADDR=0x50000504"], "arm_loops.S"),
    "e31-sifive_e": ("sifive_e", ["riscv64-unknown-elf-gcc", "-march=rv32imac", "-mabi=ilp32", "-nostdlib",
                                  "-T", os.path.join(SRC, "rv.ld")], "rv_loops.S"),
}


def expected(board, n):
    """function -> (instructions, {class: count}, {"typ cycles": ..., cond taken/not})"""
    if board.startswith("e31"):
        return {
            "loop2": (2 * n + 1, {"alu": n, "branch": n + 1},
                      # addi, bnez (backward, taken: predicted); last one not taken:
                      # mispredicted (3); ret predicted by the RAS
                      {"typ": 2 * n + 1 + 3}),
            "mmio_loop": (3 * n + 3, {"alu": n + 2, "load": n, "branch": n + 1}, {}),
            "nested": (5 * n + 8, {"alu": 2 * n + 3, "store": 2, "load": 2, "branch": 3 * n + 1}, {}),
            "mix": (8 * n + 4, {"alu": 3 * n + 3, "load": n, "store": n, "mul": n, "div": n, "branch": n + 1},
                    # lw; addi (load-use: +1); sw; mul; add (mul latency 5: +4);
                    # divu (result in 18); addi; bnez; the divide still in flight
                    # at the block's end is waited for: 28 cycles an iteration;
                    # auipc, addi, li before the first; the last bnez is
                    # mispredicted (3), ret is predicted
                    {"typ": 28 * n + 3 + 3 + 1}),
        }
    v7m = not board.startswith("m0")
    exp = {
        "loop2": (2 * n + 1, {"alu": n, "branch": n + 1},
                  # M3/M4: subs 1, bne 1 + 1 refill when taken, bx lr 1 + 2
                  # M0: subs 1, bne 1 + 2 when taken, bx lr 3
                  {"typ": (3 * n + 2) if v7m else (4 * n + 1)}),
        "mmio_loop": (3 * n + 2, {"alu": n, "load": n + 1, "branch": n + 1}, {}),
        "nested": (5 * n + 3, {"alu": 2 * n + 1, "branch": 3 * n, "load_multi": 1, "store_multi": 1},
                   # M3: push 3, mov 1, n x (bl 2, adds 1, bx 3, subs 1, bne 1+1) - 1, pop {r4,pc} 3+3
                   {"typ": 3 + 1 + 9 * n - 1 + 6} if v7m else {}),
    }
    if v7m:
        exp["mix"] = (12 * n + 5, {"alu": 3 * n + 2, "load": n + 1, "store": n, "mul": n, "mul_long": 2 * n,
                                   "div": n, "load_multi": n + 1, "store_multi": n + 1, "branch": n}, {})
    else:
        exp["mix"] = (9 * n + 5, {"alu": 3 * n + 2, "load": n + 1, "store": n, "mul": n,
                                  "load_multi": n + 1, "store_multi": n + 1, "branch": n}, {})
    if board.startswith("m4"):
        exp["fpu_mix"] = (8 * n + 10, {"load": 3, "store": 1, "alu": n + 1, "system": 2, "fpu_alu": 2 * n + 2,
                                       "fpu_load": n, "fpu_store": n, "fpu_divsqrt": 2 * n, "branch": n + 1},
                          # per iteration vldr 2, vadd 1, vmul 1, vdiv 14, vsqrt 14,
                          # vstr 2, subs 1, bne 1 + 1
                          {})
    return exp


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=20000, help="loop iterations (enough to meet icount budget stops)")
    args = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    stops = rewinds = 0

    for board, (machine, cc, src) in BOARDS.items():
        qemu = "qemu-system-riscv32" if board.startswith("e31") else "qemu-system-arm"
        if not shutil.which(cc[0]) or not shutil.which(qemu):
            print("  skip  %s: %s or %s not installed" % (board, cc[0], qemu))
            continue
        elf = os.path.join(OUT, board + ".elf")
        subprocess.run(cc + ["-DN_LOOP=%d" % args.n, os.path.join(SRC, src), "-o", elf], check=True)
        for func, (insns, classes, cyc) in expected(board, args.n).items():
            js = os.path.join(OUT, "%s-%s.json" % (board, func))
            r = subprocess.run([sys.executable, CYCLES, elf, "--machine", machine, "--from-symbol", func,
                                "--top", "0", "--json", js], capture_output=True, text=True)
            if r.returncode != 0:
                check(False, "%s %s: cycles.py failed: %s" % (board, func, r.stderr.strip()[-300:]))
                continue
            with open(js) as f:
                d = json.load(f)
            stops += d["log"]["stops"]
            rewinds += d["log"]["rewinds"]
            got = {k: v for k, v in d["classes"].items() if v}
            check(d["instructions"] == insns and d["entries"] == 1,
                  "%s %s: %d instructions (expected %d)" % (board, func, d["instructions"], insns))
            check(got == classes, "%s %s: mix %s%s" % (board, func, sorted(got.items()),
                                                          "" if got == classes else " expected %s" % sorted(classes.items())))
            if func == "loop2":
                check(d["cond_taken"] == args.n - 1 and d["cond_not_taken"] == 1,
                      "%s loop2: branches taken %d, not taken %d" % (board, d["cond_taken"], d["cond_not_taken"]))
            if "typ" in cyc:
                check(d["cycles"]["typ"] == cyc["typ"], "%s %s: %d cycles (model worked by hand: %d)" % (
                    board, func, d["cycles"]["typ"], cyc["typ"]))
            if d["log"]["warnings"] or d["log"]["unknown_block_executions"]:
                check(False, "%s %s: warnings %s" % (board, func, d["log"]["warnings"]))
        # a call counted apart: nested without leaf (leaf is adds/addi + return)
        js = os.path.join(OUT, "%s-exclude.json" % board)
        subprocess.run([sys.executable, CYCLES, elf, "--machine", machine, "--from-symbol", "nested",
                        "--exclude-symbol", "leaf", "--top", "0", "--json", js], check=True, capture_output=True)
        with open(js) as f:
            d = json.load(f)
        total = expected(board, args.n)["nested"][0]
        check(d["excluded_instructions"] == 2 * args.n and d["instructions"] == total - 2 * args.n,
              "%s nested without leaf: %d + %d apart (expected %d + %d)" % (
                  board, d["instructions"], d["excluded_instructions"], total - 2 * args.n, 2 * args.n))
    check(rewinds > 0, "blocks re-translated around I/O were met (%d rewinds)" % rewinds)
    check(stops > 0, "blocks stopped by the icount budget were met (%d)" % stops)
    sys.exit(summary("cycles-selftest"))


if __name__ == "__main__":
    main()
