#!/bin/sh
# The LM3S6965 board (platform/lm3s6965evb/): the frame drawn on its
# SSD0323 OLED and captured from QEMU must equal the host's fixed render
# in L4, pixel for pixel, and its report the host's counters; a frame
# smaller than the panel (odd width) is taken from the panel's top left;
# a damaged capture gives no image; a frame larger than the panel does not
# build; anti-aliased and dithered frames (make AA=3 DITHER=1) likewise.
# (The capture check needs the showpiece case's dump.)
RT=${1:-build/host/rt}
OUT=build/test-board-oled
. tests/boards/board-case.sh

echo "board tests: QEMU lm3s6965evb (OLED) against the hosted fixed build in l4"
oled_case() { # NAME SCENE SIZE [MAKE-VARS [RT-ARGS]]
    n=$1 scene=$2 size=$3 vars=$4 args=$5
    set -- BOARD=lm3s6965evb SCENE="$scene" SIZE="$size" DEPTH=5 AA=0 DITHER=0 $vars
    board_build $n "$@" && board_run $n "$@" || return
    ipp=$(report_val instructions_per_pixel "$OUT/$n.report") hw=$(report_val stack_high_water "$OUT/$n.report")
    board_vs_host $n "fixed l4${args:+ $args}" "$size on the panel, $ipp instructions/pixel, stack $hw bytes" \
        "$scene" --size "$size" --depth 5 --format l4 $args
    grep -qx "stack_guard_intact 1" "$OUT/$n.report" && grep -qx "drawn 1" "$OUT/$n.report" ||
        bad "$n $size: report lacks 'stack_guard_intact 1' or 'drawn 1'"
}
oled_case showpiece scenes/showpiece.nff 128x64
oled_case balls-2 scenes/spd/balls-2.nff 128x64
oled_case rings-1 scenes/spd/rings-1.nff 47x31
# anti-aliased and dithered, as the panel is best used
oled_case showpiece-aa-dither scenes/showpiece.nff 128x64 "AA=3 DITHER=1" "--aa 3 --dither"
oled_case rings-1-dither scenes/spd/rings-1.nff 47x31 "DITHER=1" "--dither"

# The capture check: a dump whose 4x4 blocks are not uniform greys 17*v
# (one byte changed in the showpiece's dump) gives no image.
dump=$(make -s print-fwdir BOARD=lm3s6965evb SCENE=scenes/showpiece.nff SIZE=128x64 DEPTH=5 AA=0 DITHER=0)/fixed.oled.ppm
for case in "15 1 not grey" "15+3*(512*9+6) 3 not uniform" "15+3*(512*8+4) 3 not a 4-bit grey"; do
    at=${case%% *} rest=${case#* } n=${rest%% *} want=${rest#* }
    python3 -c "import sys; d=bytearray(open(sys.argv[1],'rb').read()); i=eval(sys.argv[3]); n=int(sys.argv[4])
v = 34 if d[i] != 34 else 51
if sys.argv[5] == 'not a 4-bit grey': v = 35
d[i:i+n] = bytes([v] * n); open(sys.argv[2],'wb').write(d)" "$dump" "$OUT/bad.ppm" "$at" "$n" "$want"
    rm -f "$OUT/bad.stream"
    msg=$(sh tools/emu/lm3s6965evb/run.sh --panel "$OUT/bad.ppm" 128 64 "$OUT/bad.stream" 2>&1); status=$?
    if [ $status -ne 0 ] && [ ! -e "$OUT/bad.stream" ] && echo "$msg" | grep -q "$want"; then
        ok "capture check: $msg"
    else
        bad "capture check ($want): status $status, '$msg'"
    fi
done

# Larger than the panel: a build error that says so.
if make -s firmware AA=0 DITHER=0 BOARD=lm3s6965evb SCENE=scenes/spd/rings-1.nff SIZE=129x64 >"$OUT/big.build" 2>&1; then
    bad "a 129x64 frame built for the 128x64 OLED"
elif grep -q "the frame is larger than the 128x64 OLED" "$OUT/big.build"; then
    ok "a 129x64 frame does not build: the frame is larger than the 128x64 OLED"
else
    bad "a 129x64 frame failed to build without the expected message: $(tail -2 "$OUT/big.build")"
fi
summary board-oled-test
