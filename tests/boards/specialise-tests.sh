#!/bin/sh
# Firmware built for its scene (SPECIALISE=1, the default: the scene's
# tables a constant where the tracer reads them, the program optimised
# whole) is the generic firmware's algorithm (SPECIALISE=0): the same
# image, byte for byte, within its backend's floor of the exact build at
# the same samples (fixed 50 dB, float 60 dB), and fewer instructions a
# pixel. Each case builds both and runs both under the emulator
# (deterministic counts: QEMU -icount shift=0, rp2040js):
#  - the card scene (4 spheres, a plane) on the Cortex-M4F in float and
#    the Cortex-M3 in fixed point, point-sampled and filtered textures,
#    at most 0.85 of the generic instructions a pixel;
#  - the showpiece (BVH, solids, CSG, anti-aliased by default) and
#    picolib on the M3, at most the generic count;
#  - the card on the Pico (core 0 alone, CORES=1: the code, not the
#    split), at most the generic cycles (SysTick);
#  - SPECIALISE=2 refused with a message; make size bounds the
#    specialised card's stack from the link's call graph, at least what
#    its run measured.
RT=${1:-build/host/rt}
OUT=build/test-specialise
. tests/boards/board-case.sh

# run_exact NAME VARS...: make run, which also renders the exact (double)
# build at the same samples in the same format ($OUT/NAME-exact.png)
run_exact() {
    one=$1
    shift
    make -s -j2 firmware "$@" >"$OUT/$one.build" 2>&1 &&
        make -s run "$@" RUN_OUT="$OUT/$one.png" RUN_REF="$OUT/$one-exact.png" RUN_AREA="$OUT/$one-area.png" \
            >"$OUT/$one.run" 2>&1 &&
        cp "$(make -s print-fwdir "$@")/report-$(printf '%s\n' "$@" | sed -n 's/^BACKEND=//p' | tail -1 | grep . || echo fixed).txt" \
            "$OUT/$one.report"
}
value() { awk -v k="$2" '$1 == k { print $2 }' "$OUT/$1.report"; }

# pair NAME KEY LIMIT BUDGET VARS...: generic and specialised, same image,
# KEY of the specialised at most LIMIT (a fraction) of the generic's and
# at most BUDGET (about 3% above its count when written: a regression of
# the specialised kernel alone fails too)
pair() {
    n=$1 key=$2 limit=$3 budget=$4
    shift 4
    if ! board_fw "$n-generic" "$@" SPECIALISE=0 || ! run_exact "$n-spec" "$@" SPECIALISE=1; then
        bad "$n: build or run failed: $(tail -3 "$OUT/$n-spec.build" "$OUT/$n-spec.report" 2>/dev/null | tr '\n' ' ')"
        return
    fi
    g=$(value "$n-generic" "$key") s=$(value "$n-spec" "$key")
    floor=50
    case " $* " in *" BACKEND=float "*) floor=60 ;; esac
    exact=$("$RT" compare "$OUT/$n-spec.png" "$OUT/$n-spec-exact.png") exact_psnr=$exact
    if "$RT" compare "$OUT/$n-spec.png" "$OUT/$n-spec-exact.png" --psnr-min $floor >/dev/null; then
        exact=
    else
        exact="under $floor dB: $exact"
    fi
    if ! cmp=$("$RT" compare "$OUT/$n-spec.png" "$OUT/$n-generic-board.png" --max-error 0); then
        bad "$n: the specialised image differs from the generic one: $cmp"
    elif [ -n "$exact" ]; then
        bad "$n: the specialised image against the exact build at the same samples: $exact"
    elif [ -z "$g" ] || [ -z "$s" ]; then
        bad "$n: no $key in the reports"
    elif [ "$s" -gt "$budget" ]; then
        bad "$n: $key $s over its budget $budget (generic $g)"
    elif awk -v s="$s" -v g="$g" -v l="$limit" 'BEGIN { exit !(s <= g * l) }'; then
        ok "$n: same image, $(echo "$exact_psnr" | awk '{ print $2 }') dB from the exact build (floor $floor); $key $s against $g generic ($(awk -v s="$s" -v g="$g" 'BEGIN { printf "%.3f", s / g }'), limit $limit, budget $budget)"
    else
        bad "$n: $key $s against $g generic: over $limit of it"
    fi
}

card="SCENE=scenes/bench/card.nff SIZE=80x60 DEPTH=3 AA=0"
pair card-m4f-float-pointtex instructions_per_pixel 0.85 800 BOARD=mps2-an386 BACKEND=float $card TEXTURE_FILTER=0
pair card-m4f-float instructions_per_pixel 0.85 950 BOARD=mps2-an386 BACKEND=float $card
pair card-m3-fixed-pointtex instructions_per_pixel 0.85 1310 BOARD=mps2-an385 BACKEND=fixed $card TEXTURE_FILTER=0
pair card-m3-fixed instructions_per_pixel 0.85 1630 BOARD=mps2-an385 BACKEND=fixed $card
pair showpiece-m3-fixed-aa3 instructions_per_pixel 1 128000 BOARD=mps2-an385 SCENE=scenes/showpiece.nff SIZE=24x24
pair picolib-m3-fixed instructions_per_pixel 1 2400 BOARD=mps2-an385 SCENE=scenes/bench/picolib.nff SIZE=40x30 DEPTH=6 AA=0
# (scanline order: the budget is the render's; progressive display, the
# panel's default, adds its passes' walk: bench/pico-frames.md)
pair card-pico-fixed render_cycles 1 2780000 BOARD=pico CORES=1 SCENE=scenes/bench/card.nff SIZE=24x18 DEPTH=3 PROGRESSIVE=0

if msg=$(make -s firmware SPECIALISE=2 2>&1); then
    bad "SPECIALISE=2 built"
else
    ok "SPECIALISE=2 refused: $(echo "$msg" | grep -o 'SPECIALISE=2.*' | head -1)"
fi
# the stack bound of a whole-program build: from the link's call graph,
# and not below what the card's run measured
bound=$(make -s size BOARD=mps2-an386 BACKEND=float $card TEXTURE_FILTER=0 2>&1 | awk '/^worst-case stack/ { print $(NF-1) }')
used=$(value card-m4f-float-pointtex-spec stack_high_water)
if [ -n "$bound" ] && [ -n "$used" ] && [ "$bound" -ge "$used" ] && [ "$bound" -gt 300 ]; then
    ok "make size of the specialised card firmware: stack bound $bound bytes, $used measured"
else
    bad "make size of the specialised card firmware: bound '$bound', measured '$used'"
fi
summary specialise
