#!/bin/sh
# The bench files' freshness and speed budgets: deterministic counts of
# the benchmark scenes on the emulated cores, at a size that runs in
# seconds (80x60; the large scenes at 64x64 as bench/boards.md has them).
# First each count a bench file records beside its figures
# (bench/freshness.py), within 1% of it: a change that moves one fails
# here, naming the make bench-STEP that measures the file again. Then the
# scenes no bench file records, each against a budget a little above
# today's count, so a change that slows the render fails here and must say
# why in this file. Instructions inside the render are QEMU's
# -icount shift=0 count; the pico's cycles are rp2040js's. bench/scenes.md
# and bench/boards.md have the full-size figures (make bench).
# Then the accuracy floors of the benchmark scenes at 320x240, where they
# are timed: fixed and float against the exact double build.
RT=${1:-build/host/rt}
OUT=build/test-speed
. tests/boards/board-case.sh

# budget BOARD BACKEND SCENE SIZE DEPTH KEY MAX: build, run, KEY <= MAX
budget() {
    n="$1-$2-$(basename "$3" .nff)-$4"
    vars="AA=0 BOARD=$1 BACKEND=$2 SCENE=$3 SIZE=$4 DEPTH=$5"
    board_build $n $vars && board_run $n $vars || return
    v=$(awk -v k="$6" '$1 == k { print $2 }' "$OUT/$n.report")
    if [ -z "$v" ]; then
        bad "$n: the report has no $6"
    elif [ "$v" -le "$7" ]; then
        ok "$n depth $5: $6 $v <= $7"
    else
        bad "$n depth $5: $6 $v > $7 (the budget; a slower render must say why)"
    fi
}

echo "speed tests: the bench files' freshness counts, the benchmark scenes' counts against their budgets"
# The counts the bench files' figures rest on (bench/freshness.py), each
# within 1% of the file's: the card on the M3 (fixed, generic too, and with
# --aa 3), the M4F (float) and the pico (one core, and its default two
# cores); a slower render fails there too, until make bench-STEP measures
# the file again and shows what it costs.
python3 bench/freshness.py --check --lines >"$OUT/freshness.lines" 2>&1
relay "$OUT/freshness.lines"
grep -q '^  ok ' "$OUT/freshness.lines" || bad "bench/freshness.py --check passed no check"
CARD=scenes/bench/card.nff
# card and picolib filter their checkers (docs/shading-model.md, "Filtered
# textures"): 1.23x (M3, card) to 1.29x (pico, picolib) the point-sampled
# counts, 1,790 and 7,927 before.
PICOLIB=scenes/bench/picolib.nff
budget microbit fixed $CARD 80x60 3 instructions_per_pixel 5297
budget pico fixed $PICOLIB 80x60 6 cycles_per_pixel 10264
# large scenes: the M3 at bench/boards.md's size and depth
budget mps2-an385 fixed scenes/spd/balls-2.nff 64x64 5 instructions_per_pixel 6570
budget mps2-an385 fixed scenes/spd/rings-1.nff 64x64 5 instructions_per_pixel 7070
budget mps2-an385 fixed scenes/spd/teapot-1.nff 64x64 5 instructions_per_pixel 4961

# Accuracy floors at the benchmarks' own size: fixed >= 50 dB and float
# >= 60 dB against the exact double build at the same samples.
for f in $CARD $PICOLIB scenes/bench/whitted.nff; do
    s=$(basename "$f" .nff)
    for b in double fixed float; do
        "$RT" "$f" -o "$OUT/$s-$b.png" --$b --quiet 2>>"$OUT/$s.err"
    done
    check "$s 320x240 (fixed)" "$RT" compare "$OUT/$s-fixed.png" "$OUT/$s-double.png" --psnr-min 50
    check "$s 320x240 (float)" "$RT" compare "$OUT/$s-float.png" "$OUT/$s-double.png" --psnr-min 60
done
summary speed
