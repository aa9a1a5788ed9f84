#!/bin/sh
# summary.sh REPORT EXACT AREA BLURRED: make run's report. A few plain
# lines first (what was rendered where, the time on the board, how close
# the image is to the exact one and to what a viewer sees, where the PNG
# is), then the board's own report lines (REPORT: board-run's output).
# EXACT, AREA, BLURRED: `rt compare` lines of the board's image against
# the exact model at the same samples, the pixel-area image, and the
# same blurred by a pixel. The rest comes from the environment:
# SCENE SIZE DEPTH BOARD BACKEND SAMPLING OUT IMAGE_NOTE.
report=$1 exact=$2 area=$3 blurred=$4
field() { # field NAME LINE: the number after NAME in an rt compare line
    printf '%s\n' "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) { print $(i + 1); exit } }'
}
value() { awk -v k="$1" '$1 == k { v = $2 } END { print v }' "$report"; }
board=$(sed -n '1s/^# board.mk - //p' "platform/$BOARD/board.mk")
case $BACKEND in
fixed) build="fixed-point" ;;
*) build="$BACKEND" ;;
esac
case $SAMPLING in
*--aa*) how="adaptive anti-aliasing ($(echo "$SAMPLING" | sed 's/ *--texture-filter off//'))" ;;
*--spp*) n=$(echo "$SAMPLING" | sed 's/.*--spp \([0-9]*\).*/\1/'); how="$n x $n samples a pixel" ;;
*) how="one sample a pixel" ;;
esac
case $SAMPLING in *"--texture-filter off"*) how="$how, textures point-sampled" ;; esac
ipp=$(value instructions_per_pixel | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta')
# run.sh's line: "board render time at 25 MHz (1 instr/cycle, ...): 37.14 s"
time=$(sed -n 's/^board render time at \([0-9.]* MHz\) (\(.*\)): \(.*\)$/\3 at \1 (\2)/p' "$report")
qemu=$(sed -n 's/^QEMU wall time on the host (\(.*\)): \(.*\)$/\2 (\1)/p' "$report")

echo
echo "$SCENE, $SIZE, depth $DEPTH, $how,"
echo "rendered by the $build firmware on $BOARD (${board%.})."
[ -n "$time" ] && printf '  %-15s %s; %s instructions a pixel\n' "on the board" "$time" "$ipp"
case $SAMPLING in
*--aa*) same="at the same samples (its splits replayed)" ;;
*) same="at the same samples" ;;
esac
printf '  %-15s %s dB from the exact model %s, largest error %s/255\n' \
    "number format" "$(field psnr "$exact")" "$same" "$(field max-error "$exact")"
printf '  %-15s %s dB from the image averaged over each pixel'"'"'s area, %s of pixels off by\n' \
    "what is seen" "$(field psnr "$area")" "$(field over8 "$area")"
printf '  %-15s more than 8/255 (%s dB both blurred by a pixel, as an eye sees a small panel)\n' "" \
    "$(field psnr "$blurred")"
printf '  %-15s %s%s\n' "image" "$OUT" "$IMAGE_NOTE"
echo "(PSNR: 10 log10(1 / mean squared error); above about 40 dB a difference is hard to see."
echo " QEMU took $qemu on this machine.)"
echo
echo "The board's report (each counter is described under rt --stats in docs/cli.md):"
grep -v '^progress_rows\|^board render time\|^QEMU wall time' "$report" | sed 's/^/  /'
