#!/bin/sh
# Board benchmark (printed, not asserted): instructions per pixel on the
# emulated Cortex-M3 (QEMU -icount shift=0, exact) for the fixed build and
# for the same core built with the double backend as soft-float, at 64x64,
# depth 5, with the fixed image's error against the double one.
RT=${RT:-build/host/rt}
SIZE=${SIZE:-64x64}
OUT=build/bench-board
mkdir -p "$OUT"
printf '%-10s %14s %16s %8s %10s %10s\n' scene "fixed instr/px" "double instr/px" ratio "PSNR dB" "max err"
for s in balls-1 gears-1 rings-1 teapot-1 tetra-1 balls-2 rings-2 teapot-2 tetra-2; do
    d="build/board/$s-$SIZE-d5-rgb888"
    make -s SCENE=scenes/spd/$s.nff SIZE=$SIZE DEPTH=5 "$d/fixed.elf" "$d/double.elf" >"$OUT/$s.build" 2>&1 || {
        echo "$s: build failed (see $OUT/$s.build)"; continue; }
    platform/mps2-an385/qemu-run.sh "$d/fixed.elf" "$OUT/$s-fixed.png" "$RT" >"$OUT/$s-fixed.report" 2>&1 &&
    platform/mps2-an385/qemu-run.sh "$d/double.elf" "$OUT/$s-double.png" "$RT" >"$OUT/$s-double.report" 2>&1 || {
        echo "$s: run failed"; continue; }
    f=$(awk '$1 == "instructions_per_pixel" { print $2 }' "$OUT/$s-fixed.report")
    g=$(awk '$1 == "instructions_per_pixel" { print $2 }' "$OUT/$s-double.report")
    cmp=$("$RT" compare "$OUT/$s-fixed.png" "$OUT/$s-double.png")
    psnr=$(echo "$cmp" | awk '{ print $2 }')
    maxe=$(echo "$cmp" | awk '{ print $5 }')
    printf '%-10s %14d %16d %7.1fx %10s %10s\n' "$s" "$f" "$g" "$(echo "$g $f" | awk '{ print $1 / $2 }')" "$psnr" "$maxe"
done
