#!/bin/sh
# summary.sh REPORT EXACT AREA BLURRED: make run's report. A few plain
# lines first (what was rendered on which board, the time on the board,
# the time on the wire where the board reports its UART's rate, how
# close the image is to the exact one and to what a viewer sees, where
# the PNG is, which emulator ran it), then the board's own report lines
# (REPORT: board-run's output).
# EXACT, AREA, BLURRED: `rt compare` lines of the board's image against
# the exact model at the same samples, the pixel-area image, and the
# same blurred by a pixel. The rest comes from the environment:
# SCENE SIZE DEPTH BOARD BACKEND SAMPLING OUT IMAGE_NOTE, IMAGES (the
# board's files to flash, copied beside OUT, if it has any), and from the
# board's board.mk BOARD_TITLE (the board in a phrase) and CLOCK_HZ
# (BOARD_CLOCK_HZ). TIME_TABLE (default bench/time.csv, which make bench
# writes) gives the cycles an instruction of a board without a cycle
# counter.
report=$1 exact=$2 area=$3 blurred=$4
table=${TIME_TABLE:-bench/time.csv}
field() { # field NAME LINE: the number after NAME in an rt compare line
    printf '%s\n' "$2" | awk -v k="$1" '{ for (i = 1; i < NF; i++) if ($i == k) { print $(i + 1); exit } }'
}
value() { awk -v k="$1" '$1 == k { v = $2 } END { print v }' "$report"; }
commas() { sed ':a;s/\B[0-9]\{3\}\>/,&/;ta'; }
case $BACKEND in
fixed) build="fixed-point" ;;
*) build="$BACKEND" ;;
esac
case $SAMPLING in
*--aa*) how="adaptive anti-aliasing ($(echo "$SAMPLING" | sed 's/ *--texture-filter off//')),"
    bench_sampling="aa 3" ;;
*--spp*) n=$(echo "$SAMPLING" | sed 's/.*--spp \([0-9]*\).*/\1/'); how="$n x $n samples a pixel,"
    bench_sampling="1 sample" ;;
*) how="one sample a pixel," bench_sampling="1 sample" ;;
esac
case $SAMPLING in *"--texture-filter off"*) how="${how%,}, textures point-sampled," ;; esac
mhz=$(awk -v hz="$CLOCK_HZ" 'BEGIN { printf "%g", hz / 1e6 }')
ipp=$(value instructions_per_pixel | commas) both=
# a runner that counts each core's instructions (the pico's: core 0's are
# render_instructions) gives both cores' work a pixel
if [ -n "$(value core1_render_instructions)" ]; then
    ipp=$(awk -v a="$(value render_instructions)" -v b="$(value core1_render_instructions)" -v p="$(value pixels)" \
        'BEGIN { printf "%d", (a + b) / p + 0.5 }' | commas)
    both=", both cores together"
fi

# The time on the board: the port's own cycle count where it has one
# (render_cycles: SysTick on the pico, DWT's CYCCNT on an STM32F4 chip),
# else the instructions (the critical path's on two cores) times the
# cycles an instruction bench/cycles.py priced the benchmark scene at on
# this board and backend (bench/time.csv, the row of the same sampling).
time_lines() {
    cycles=$(value render_cycles)
    instr=$(value critical_path_instructions)
    [ -n "$instr" ] || instr=$(value render_instructions)
    emulator=$(sed -n 's/^\([^ ]*\) wall time on the host (\(.*\)): \(.*\)$/\1/p' "$report")
    if [ -n "$cycles" ]; then
        if grep -q '^counter: DWT CYCCNT' "$report"; then counter="DWT's cycle counter (CYCCNT)"
        else counter="SysTick"; fi
        [ "$emulator" = rp2040js ] && counter="$counter under rp2040js (its Cortex-M0+ timing, code in SRAM)"
        time=$(awk -v c="$cycles" -v hz="$CLOCK_HZ" 'BEGIN { printf "%.3g s", c / hz }')
        render_s=$(awk -v c="$cycles" -v hz="$CLOCK_HZ" 'BEGIN { print c / hz }')
        printf '  %-15s %s at %s MHz, counted by %s;\n' "on the board" "$time" "$mhz" "$counter"
        printf '  %-15s %s instructions a pixel%s.\n' "" "$ipp" "$both"
        first=$(value first_picture_cycles)
        [ -z "$first" ] || printf '  %-15s %s ms after the render starts, panel bytes included: progressive\n  %-15s display, pass 1 of 7 (its frame: %s s).\n' \
            "first picture" "$(awk -v c="$first" -v hz="$CLOCK_HZ" 'BEGIN { printf "%.1f", c / hz * 1000 }')" "" \
            "$(awk -v c="$(value frame_cycles)" -v hz="$CLOCK_HZ" 'BEGIN { printf "%.3g", c / hz }')"
    elif grep -q 'instead of -icount' "$report"; then
        printf '  %-15s no time: the instruction counts are host time (QEMU_ACCEL), not instructions.\n' "on the board"
    elif [ -n "$instr" ]; then
        # the row of this board, backend and sampling; else its one-sample row
        cpi=$(awk -F, -v b="$BOARD" -v be="$BACKEND" -v s="$bench_sampling" '
            NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
            $col["board"] == b && $col["backend"] == be && $col["cpi"] != "" {
                if ($col["sampling"] == s) exact = $col["cpi"] "|" s
                else if ($col["sampling"] == "1 sample") one = $col["cpi"] "|" $col["sampling"] }
            END { print exact != "" ? exact : one }' "$table" 2>/dev/null)
        if [ -n "$cpi" ]; then
            case $cpi in
            *"|aa 3") on="with --aa 3" ;;
            *) on="with one sample a pixel" ;;
            esac
            cpi=${cpi%%|*}
            time=$(awk -v n="$instr" -v c="$cpi" -v hz="$CLOCK_HZ" 'BEGIN { printf "%.3g s", n * c / hz }')
            render_s=$(awk -v n="$instr" -v c="$cpi" -v hz="$CLOCK_HZ" 'BEGIN { print n * c / hz }')
            if [ -n "$(value critical_path_instructions)" ]; then # the slowest core's share
                what="the critical path's $(echo "$instr" | commas) instructions ($(value cores) cores)"
            else
                what="$ipp instructions a pixel"
            fi
            printf '  %-15s about %s at %s MHz, estimated: %s x %.2f cycles an\n' \
                "on the board" "$time" "$mhz" "$what" "$cpi"
            printf '  %-15s instruction, the mix bench/cycles.py priced on the card scene %s\n' "" "$on"
            printf '  %-15s (%s; the core'"'"'s documented timings, no flash wait states).\n' "" "$table"
        else
            printf '  %-15s %s instructions a pixel; %s has no cycles an instruction for %s %s\n' \
                "on the board" "$ipp" "$table" "$BOARD" "$BACKEND"
            printf '  %-15s (make bench writes it), so no time is given.\n' ""
        fi
    fi
}

# The time the picture takes on the wire, where the board reports its
# console's rate and the bytes it carried (uart_baud, uart_bytes: the
# stm32f4): 10 bits a byte (8N1). The board sends each band when it is
# done and renders on once it is out, so from reset to the last byte
# takes the render's time and the wire's together.
wire_lines() {
    baud=$(value uart_baud) bytes=$(value uart_bytes)
    [ -n "$baud" ] && [ -n "$bytes" ] || return 0
    wire=$(awk -v n="$bytes" -v b="$baud" 'BEGIN { printf "%.3g s", n * 10 / b }')
    printf '  %-15s %s at %s baud (8N1: 10 bits a byte), for the %s bytes the UART\n' "on the wire" "$wire" \
        "$baud" "$(echo "$bytes" | commas)"
    printf '  %-15s carried (the frame'"'"'s records and the report lines)' ""
    if [ -n "$render_s" ]; then
        printf ';\n  %-15s %s from reset to the last byte, render and wire together.\n' "" \
            "$(awk -v r="$render_s" -v n="$bytes" -v b="$baud" 'BEGIN { printf "%.3g s", r + n * 10 / b }')"
    else
        printf '.\n'
    fi
}

echo
echo "$SCENE, $SIZE, depth $DEPTH, $how"
echo "rendered by the $build firmware on $BOARD: $BOARD_TITLE, at $mhz MHz."
render_s=
time_lines
wire_lines
case $SAMPLING in
*--aa*) same="at the same samples (its splits replayed)" ;;
*) same="at the same samples" ;;
esac
printf '  %-15s %s dB from the exact model %s, largest error %s/255.\n' \
    "number format" "$(field psnr "$exact")" "$same" "$(field max-error "$exact")"
printf '  %-15s %s dB from the image averaged over each pixel'"'"'s area, %s of pixels off by\n' \
    "what is seen" "$(field psnr "$area")" "$(field over8 "$area")"
printf '  %-15s more than 8/255 (%s dB both blurred by a pixel, as an eye sees a small panel).\n' "" \
    "$(field psnr "$blurred")"
# the PNG, and the files for the board beside it
for_board=$(printf '%s\n' $IMAGES | awk 'NF { s = n++ ? s " and " $0 : $0 } END { if (n) printf ", and for the board %s", s }')
printf '  %-15s %s%s%s.\n' "image" "$OUT" "$IMAGE_NOTE" "$for_board"
echo "(PSNR: 10 log10(1 / mean squared error); above about 40 dB a difference is hard to see.)"
sed -n 's/^\([^ ]*\) wall time on the host (\(.*\)): \(.*\)$/\1 ran it in \3 on this machine (\2)./p' "$report"
echo
echo "The board's report (each counter is described under rt --stats in docs/cli.md):"
grep -v '^progress_rows\|^progress_pass\|^board render time\|wall time on the host' "$report" | sed 's/^/  /'
