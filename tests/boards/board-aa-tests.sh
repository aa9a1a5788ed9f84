#!/bin/sh
# Anti-aliasing on the boards (make AA=LEVELS[,THRESHOLD], SPP=N):
#  - mps2-an385 (Cortex-M3, fixed point): AA=3 on balls-2, rings-1,
#    teapot-1 and the showpiece, SPP=2 on tetra-2, AA=2,20 in rgb565 at
#    an odd size: the image byte-identical to rt --aa/--spp with one
#    thread, the counters equal, the stack high-water within the budget of
#    tests/boards/budgets.sh (the cell loop adds a few hundred bytes under
#    trace_ray);
#  - mps2-an521, both cores (bands of 4 lines with AA: each traces its
#    top row of corners again): AA=3 byte-identical to the host and to one
#    core, the critical path at most 0.56 of one core's instructions;
#  - pruning: firmware without AA links none of it (aa.h's sampler
#    aa_sample is absent), with AA it does;
#  - firmware without AA (generic, balls-2 and the showpiece): code within
#    the budget of tests/boards/budgets.sh (that AA adds nothing to it is
#    the pruning check's: no sampler linked);
#  - the cost at 128x128 (instructions per pixel under -icount shift=0,
#    deterministic): AA=3 over one sample <= 4.0 on teapot-1 and the
#    showpiece; balls-2 and rings-1, whose edge samples meet their
#    mirrors and cost about twice an average sample, <= 6.5 (the 4x
#    target is not met there);
#  - RAM: the micro:bit's link at AA=3, 128x128, fails naming AA= among
#    what to lower.
RT=${1:-build/host/rt}
OUT=build/test-board-aa
. tests/boards/board-case.sh
. tests/boards/budgets.sh
scene_file() { [ -f scenes/spd/$1.nff ] && echo scenes/spd/$1.nff || echo scenes/$1.nff; }
# fw NAME [make variables]: build and run, one sample a pixel unless the
# variables say otherwise (image $OUT/NAME-board.png, report
# $OUT/NAME.report; board_fw: the caller counts)
fw() {
    n=$1
    shift
    board_fw $n AA=0 "$@"
}
value() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }

echo "board anti-aliasing tests: QEMU mps2-an385 and mps2-an521 against rt --aa / --spp"
# same_as_host NAME SIZE MAKE-AA-VARS -- RT-ARGS
same_as_host() {
    n=$1 size=$2 scene=$3 vars=$4 args=$5
    if ! fw $n SCENE=$(scene_file $scene) SIZE=$size DEPTH=5 $vars; then
        bad "$n: firmware build or run failed: $(tail -2 "$OUT/$n.build" "$OUT/$n.report" 2>/dev/null)"
        return
    fi
    "$RT" $(scene_file $scene) -o "$OUT/$n-host.png" --fixed --size $size --depth 5 --threads 1 --quiet --stats $args \
        2>"$OUT/$n-host.stats"
    hw=$(value stack_high_water "$OUT/$n.report")
    if cmp=$("$RT" compare "$OUT/$n-board.png" "$OUT/$n-host.png" --max-error 0) &&
       same=$(sh tests/boards/same-counters.sh "$OUT/$n-host.stats" "$OUT/$n.report") && [ "${hw:-99999}" -le $FW_STACK_MAX ]; then
        ok "$n: board == rt $args ($cmp), counters equal, $(value instructions_per_pixel "$OUT/$n.report") instructions/pixel, stack $hw bytes"
    else
        bad "$n: board vs rt $args: ${cmp:-differs}; counters: $same; stack ${hw:-?}"
    fi
}
for s in balls-2 rings-1 teapot-1 showpiece; do
    same_as_host "$s-aa3" 64x64 $s "AA=3" "--aa 3"
done
same_as_host "tetra-2-spp2" 64x64 tetra-2 "SPP=2" "--spp 2"
same_as_host "rings-1-aa2_20-rgb565" 47x31 rings-1 "AA=2,20 FORMAT=rgb565" "--aa 2,20 --format rgb565"

# two cores
two=balls-2-an521 one=balls-2-an521-1core
if fw $two BOARD=mps2-an521 SCENE=scenes/spd/balls-2.nff SIZE=64x64 DEPTH=5 AA=3 &&
   fw $one BOARD=mps2-an521 CORES=1 SCENE=scenes/spd/balls-2.nff SIZE=64x64 DEPTH=5 AA=3; then
    "$RT" scenes/spd/balls-2.nff -o "$OUT/$two-host.png" --fixed --size 64x64 --depth 5 --aa 3 --quiet
    cp=$(value critical_path_instructions "$OUT/$two.report") whole=$(value render_instructions "$OUT/$one.report")
    if "$RT" compare "$OUT/$two-board.png" "$OUT/$two-host.png" --max-error 0 >/dev/null &&
       "$RT" compare "$OUT/$two-board.png" "$OUT/$one-board.png" --max-error 0 >/dev/null &&
       [ -n "$cp" ] && [ -n "$whole" ] && [ $((cp * 100)) -le $((whole * 56)) ]; then
        ok "mps2-an521, two cores, AA=3: == one core == host; critical path $(value critical_path_instructions_per_pixel "$OUT/$two.report") vs one core $(value instructions_per_pixel "$OUT/$one.report") instructions/pixel (<= 0.56)"
    else
        bad "mps2-an521 AA=3: two cores, one core and host differ, or critical path $cp over 0.56 of $whole"
    fi
else
    bad "mps2-an521 AA=3: build or run failed: $(tail -2 "$OUT/$two.report")"
fi

# pruning, in the generic firmware (SPECIALISE=0), which the code figures
# below were measured on
d0=$(make -s print-fwdir AA=0 SCENE=scenes/spd/balls-2.nff SIZE=64x64 SPECIALISE=0)
d1=$(make -s print-fwdir AA=0 SCENE=scenes/spd/balls-2.nff SIZE=64x64 AA=3)
make -s -j2 firmware AA=0 SCENE=scenes/spd/balls-2.nff SIZE=64x64 SPECIALISE=0 >"$OUT/prune.build" 2>&1
# (GCC may clone it as aa_sample.constprop.N or .isra.N)
if ! arm-none-eabi-nm "$d0/fixed.elf" | grep -Eq ' aa_sample(\.[a-z]+\.[0-9]+)?$' &&
   arm-none-eabi-nm "$d1/fixed.elf" | grep -Eq ' aa_sample(\.[a-z]+\.[0-9]+)?$'; then
    ok "firmware without AA links no anti-aliasing (its sampler aa_sample absent; present with AA=3)"
else
    bad "pruning: aa_sample linked without AA, or missing with it"
fi

# code without AA, generic (text, vectors and exidx: the scene tables are
# data): within the code budget
make -s -j2 firmware AA=0 SCENE=scenes/showpiece.nff SIZE=128x128 SPECIALISE=0 >>"$OUT/prune.build" 2>&1
for dir in "$d0" "$(make -s print-fwdir AA=0 SCENE=scenes/showpiece.nff SIZE=128x128 SPECIALISE=0)"; do
    c=$(code_of "$dir/fixed.elf")
    if [ -n "$c" ] && [ "$c" -gt 0 ] && [ "$c" -le $FW_CODE_MAX ]; then
        ok "$(basename "$dir") without AA: code $c bytes <= $FW_CODE_MAX"
    else
        bad "$(basename "$dir") without AA: code ${c:-?} bytes, over $FW_CODE_MAX"
    fi
done

# cost at 128x128
for case in teapot-1:4.0 showpiece:4.0 balls-2:6.5 rings-1:6.5; do
    s=${case%%:*} max=${case#*:}
    if fw $s-128 SCENE=$(scene_file $s) SIZE=128x128 DEPTH=5 && fw $s-128-aa3 SCENE=$(scene_file $s) SIZE=128x128 DEPTH=5 AA=3; then
        one=$(value instructions_per_pixel "$OUT/$s-128.report") aa=$(value instructions_per_pixel "$OUT/$s-128-aa3.report")
        if awk -v a="$aa" -v o="$one" -v m="$max" 'BEGIN { exit !(a > 0 && o > 0 && a <= m * o) }'; then
            ok "$s 128x128: AA=3 $aa instructions/pixel, one sample $one: $(awk -v a="$aa" -v o="$one" 'BEGIN { printf "%.2f", a / o }')x <= ${max}x"
        else
            bad "$s 128x128: AA=3 $aa instructions/pixel over ${max}x one sample's $one"
        fi
    else
        bad "$s 128x128: build or run failed"
    fi
done

# RAM: AA=3's rows of corners do not fit the micro:bit's 16 KiB at
# 128x128; the link fails naming AA= among what to lower (one sample's
# overflow does not name it: tests/boards/ports-tests.sh).
if make -s -j2 firmware AA=3 BOARD=microbit SCENE=scenes/spd/balls-1.nff SIZE=128x128 >"$OUT/overflow-aa.build" 2>&1; then
    bad "microbit AA=3 at 128x128 linked: its RAM overflow not caught"
elif msg=$(grep -o 'RAM overflow.*' "$OUT/overflow-aa.build" | head -1) && echo "$msg" | grep -q 'lower make AA= (.*BAND_LINES='; then
    ok "microbit AA=3 at 128x128: $msg"
else
    bad "microbit AA=3 at 128x128: the RAM overflow does not name AA=: $(tail -3 "$OUT/overflow-aa.build")"
fi
summary board-aa-tests
