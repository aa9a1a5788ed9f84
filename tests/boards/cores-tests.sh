#!/bin/sh
# Two cores (mps2-an521, app/firmware/bands.c), 64x64, depth 5:
#  - the two-core image is byte-identical to the same board on one core
#    (make CORES=1) and to the host fixed build; the UART stream's frame
#    records (header, bands, end) are byte-identical to one core's;
#  - the ray counts equal one core's; every band was rendered once;
#  - the critical path (the later core's render plus its waits, counted
#    per core under -icount) is at most 0.54 of one core's instructions
#    on balls-2 and the showpiece (a 1.85x speed-up or better);
#  - under -icount the run is deterministic (two runs, the same report);
#  - under -accel tcg,thread=multi (the cores truly in parallel, not
#    deterministic) the image is still the same;
#  - both stacks' guards intact.
RT=${1:-build/host/rt}
OUT=build/test-cores
. tests/boards/board-case.sh
B=mps2-an521
val() { awk -v k="$2" '$1 == k { print $2 }' "$1"; }
# run NAME [make variables]: build and run on $B (image $OUT/NAME-board.png,
# report $OUT/NAME.report; board_fw: the caller counts)
run() {
    rn=$1
    shift
    board_fw $rn AA=0 BOARD=$B "$@"
}
stream_of() { eval "$(make -s board-info AA=0 BOARD=$B "$@")"; echo "${elf%.elf}.stream"; }

echo "cores: $B, two Cortex-M33, against one core and the host"
for s in scenes/spd/balls-2.nff scenes/spd/rings-1.nff scenes/showpiece.nff; do
    n=$(basename $s .nff)
    vars="SCENE=$s SIZE=64x64 DEPTH=5"
    if ! run $n-1 $vars CORES=1 || ! run $n-2 $vars; then
        bad "$n: build or run failed: $(tail -3 "$OUT/$n-1.build" "$OUT/$n-1.report" "$OUT/$n-2.build" "$OUT/$n-2.report" 2>/dev/null | tail -4)"
        continue
    fi
    "$RT" $s -o "$OUT/$n-host.png" --fixed --size 64x64 --depth 5 --quiet
    if "$RT" compare "$OUT/$n-2-board.png" "$OUT/$n-1-board.png" --max-error 0 >/dev/null &&
       "$RT" compare "$OUT/$n-2-board.png" "$OUT/$n-host.png" --max-error 0 >/dev/null; then
        ok "$n: two cores == one core == host fixed (byte-identical)"
    else
        bad "$n: two-core image differs from one core's or the host's"
    fi
    if msg=$(python3 tests/boards/stream-frames.py "$(stream_of $vars CORES=1)" "$(stream_of $vars)"); then
        ok "$n: UART stream: $msg"
    else
        bad "$n: UART stream: $msg"
    fi
    if same=$(sh tests/boards/same-counters.sh "$OUT/$n-1.report" "$OUT/$n-2.report" rays); then
        ok "$n: $same with one core's"
    else
        bad "$n: $same"
    fi
    one=$(val "$OUT/$n-1.report" render_instructions)
    cp=$(val "$OUT/$n-2.report" critical_path_instructions)
    c0=$(val "$OUT/$n-2.report" core0_render_instructions) c1=$(val "$OUT/$n-2.report" core1_render_instructions)
    w0=$(val "$OUT/$n-2.report" core0_wait_instructions) w1=$(val "$OUT/$n-2.report" core1_wait_instructions)
    b0=$(val "$OUT/$n-2.report" core0_bands) b1=$(val "$OUT/$n-2.report" core1_bands)
    turns=$(val "$OUT/$n-2.report" cores_one_at_a_time)
    if [ "$turns" = 1 ] && [ $((b0 + b1)) -eq 64 ] && [ "$b0" -gt 0 ] && [ "$b1" -gt 0 ] &&
       [ "$cp" -eq $((c0 + w0 > c1 + w1 ? c0 + w0 : c1 + w1)) ]; then
        ok "$n: bands $b0 + $b1 = 64; critical path = max(core0 $c0 + $w0, core1 $c1 + $w1) = $cp"
    else
        bad "$n: bands ${b0:-?} + ${b1:-?}, one-at-a-time ${turns:-?}, critical path ${cp:-?} vs cores ${c0:-?}+${w0:-?}, ${c1:-?}+${w1:-?}"
    fi
    ratio=$(awk -v c="$cp" -v o="$one" 'BEGIN { printf "%.4f", c / o }')
    case $n in
    rings-1) ok "$n: critical path $ratio of one core's $one instructions (speed-up $(awk -v r=$ratio 'BEGIN { printf "%.2f", 1 / r }')x; reported, not asserted)" ;;
    *) if [ -n "$cp" ] && [ -n "$one" ] && awk -v r="$ratio" 'BEGIN { exit !(r + 0 > 0 && r <= 0.54) }'; then
           ok "$n: critical path $ratio of one core's $one instructions <= 0.54 (speed-up $(awk -v r=$ratio 'BEGIN { printf "%.2f", 1 / r }')x)"
       else
           bad "$n: critical path $ratio of one core's $one instructions > 0.54"
       fi ;;
    esac
    hw0=$(val "$OUT/$n-2.report" stack_high_water) hw1=$(val "$OUT/$n-2.report" core1_stack_high_water)
    if [ "$(val "$OUT/$n-2.report" stack_guard_intact)" = 1 ] && [ -n "$hw1" ]; then
        ok "$n: stacks $hw0 and $hw1 bytes, both guards intact"
    else
        bad "$n: stack guard broken or core 1 unmeasured (${hw0:-?}, ${hw1:-?})"
    fi
done

# Deterministic under -icount shift=0,sleep=off: the same report twice.
if run again SCENE=scenes/spd/balls-2.nff SIZE=64x64 DEPTH=5 &&
   grep -v "wall time" "$OUT/balls-2-2.report" >"$OUT/again-a.txt" && grep -v "wall time" "$OUT/again.report" >"$OUT/again-b.txt" &&
   cmp -s "$OUT/again-a.txt" "$OUT/again-b.txt"; then
    ok "balls-2: a second -icount run reports the same counts"
else
    bad "balls-2: two -icount runs differ"
fi

# The cores truly in parallel (not deterministic): the same image.
vars="SCENE=scenes/spd/balls-2.nff SIZE=64x64 DEPTH=5"
if make -s board-run AA=0 BOARD=$B $vars QEMU_ACCEL="-accel tcg,thread=multi" RUN_OUT="$OUT/multi.png" RUN_RT="$RT" \
       >"$OUT/multi.report" 2>&1 &&
   "$RT" compare "$OUT/multi.png" "$OUT/balls-2-1-board.png" --max-error 0 >/dev/null; then
    ok "balls-2 under -accel tcg,thread=multi: the same image (bands $(val "$OUT/multi.report" core0_bands) + $(val "$OUT/multi.report" core1_bands))"
else
    bad "balls-2 under -accel tcg,thread=multi: $(tail -2 "$OUT/multi.report")"
fi

summary cores
