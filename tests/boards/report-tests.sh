#!/bin/sh
# make run's report (tools/firmware/summary.sh) on every board of
# platform/*/board.mk, from a canned board report and canned `rt compare`
# lines (no emulator runs):
#  - the opening lines read as sentences: the board's BOARD_TITLE whole,
#    the clock from its BOARD_CLOCK_HZ, every parenthesis closed, no "()",
#    no line that starts with ")" or a bare ".", no empty figure;
#  - the time on the board: a board whose report has render_cycles (the
#    pico's SysTick) gets cycles / clock, "counted by"; the others get
#    instructions x the CPI of a canned time table's row for that board,
#    backend and sampling, "estimated", and the figure is that product;
#    on two cores the critical path's instructions, named so (the pico's
#    two cores: both cores' instructions a pixel, summed); a board
#    missing from the table gets a sentence saying there is no time, not
#    an empty figure;
#  - the time on the wire where the report gives the UART's rate and
#    bytes (the stm32f4's uart_baud, uart_bytes), with the render's;
#  - the pico's title says both cores, or one under CORES=1; the image
#    line names the PNG and the board's files to flash (IMAGES), if any;
#  - the emulator that ran it named right (rp2040js where board.mk sets
#    no QEMU, else QEMU) with its wall time, and no such sentence when the
#    report has no wall time; and every runner prints the wall-time line
#    summary.sh reads.
# tests/boards/report-tests.sh
. tests/lib/check.sh
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT

# a board's BOARD_TITLE and BOARD_CLOCK_HZ, as make reads them
printf 'print-title:\n\t@echo "$(BOARD_CLOCK_HZ)|$(BOARD_TITLE)"\n' >"$tmp/title.mk"
table=$tmp/time.csv
echo "board,clock_mhz,backend,sampling,size,ipp,cpi,cpp,cycles,seconds,psnr,max_error,area_psnr,area_over8,note" >"$table"

boards=$(for f in platform/*/board.mk; do basename "$(dirname "$f")"; done)
n=0
for b in $boards; do
    n=$((n + 1))
    # a CPI per board, different for each sampling, so the row used shows
    echo "$b,1,fixed,1 sample,320x240,1000,1.$n,,estimated,,,,,," >>"$table"
    echo "$b,1,fixed,aa 3,320x240,3000,2.$n,,estimated,,,,,," >>"$table"
done

exact="psnr 70.96 dB  max-error 5  over2 0.100%  over8 0.000%"
area="psnr 48.28 dB  max-error 9  over2 1.000%  over8 0.189%"
blur="psnr 58.39 dB  max-error 3  over2 0.000%  over8 0.000%"
# summarize BOARD REPORT SAMPLING [TABLE [IMAGES]]: summary.sh's opening lines
summarize() {
    SCENE=scenes/showpiece.nff SIZE=128x128 DEPTH=5 BOARD=$1 BOARD_TITLE=$title CLOCK_HZ=$hz BACKEND=fixed \
        SAMPLING=$3 OUT=out/x.png IMAGE_NOTE="" TIME_TABLE=${4:-$table} IMAGES=${5:-} \
        sh tools/firmware/summary.sh "$2" "$exact" "$area" "$blur" | sed '/^The board/,$d'
}
# sentences TEXT: what is wrong with the opening lines as sentences, or nothing
sentences() {
    printf '%s\n' "$1" | awk '
        NF == 0 { next }
        { line = /^  / ? substr($0, 19) : $0 } # the text after the label column
        line ~ /^ *[).,;]/ { print "a line starts with a fragment: " $0 }
        line ~ /\(\)/ { print "an empty (): " $0 }
        line ~ / [.,;]/ { print "a space before punctuation: " $0 }
        line ~ /(^|  )(s|dB|MHz|on|at|of|in) / { print "an empty figure: " $0 }
        { t = $0; opened += gsub(/\(/, "", t); closed += gsub(/\)/, "", t) }
        { last = $0 }
        END { if (opened != closed) print "parentheses: " opened " opened, " closed " closed"
              if (last !~ /[.)]$/) print "the last line is not a sentence'"'"'s end: " last }'
}

for b in $boards; do
    info=$(make -s --no-print-directory -f Makefile -f "$tmp/title.mk" print-title BOARD="$b" 2>&1)
    hz=${info%%|*} title=${info#*|}
    if [ -z "$title" ] || [ -z "$hz" ]; then
        bad "$b: no BOARD_TITLE or BOARD_CLOCK_HZ in its board.mk ($info)"
        continue
    fi
    mhz=$(awk -v hz="$hz" 'BEGIN { printf "%g", hz / 1e6 }')
    if grep -q '^BOARD_QEMU *:= *[^ ]' "platform/$b/board.mk"; then emu=QEMU; else emu=rp2040js; fi
    rep=$tmp/$b.txt
    { echo "pixels 16384"; echo "render_instructions 163840000"; echo "instructions_per_pixel 10000"
      [ $emu = rp2040js ] && echo "render_cycles 250000000"
      echo "$emu wall time on the host (boot, render, output): 7.5 s"; } >"$rep"
    out=$(summarize "$b" "$rep" "--aa 3")
    wrong=$(sentences "$out")
    second=$(printf '%s\n' "$out" | sed -n 3p)
    if [ -z "$wrong" ] && [ "$second" = "rendered by the fixed-point firmware on $b: $title, at $mhz MHz." ]; then
        ok "$b: the opening lines are sentences; \"$second\""
    else
        bad "$b: the opening lines: $wrong | $second"
    fi
    if [ $emu = rp2040js ]; then
        want=$(awk -v hz="$hz" 'BEGIN { printf "%.3g s", 250000000 / hz }')
        printf '%s\n' "$out" | grep -q "on the board *$want at $mhz MHz, counted by SysTick under rp2040js" &&
            ok "$b: the time from its counted cycles ($want at $mhz MHz, counted by SysTick)" ||
            bad "$b: the counted time ($want): $out"
    else
        cpi=$(awk -F, -v b="$b" '$1 == b && $4 == "aa 3" { printf "%.2f", $7 }' "$table")
        want=$(awk -v c="$cpi" -v hz="$hz" 'BEGIN { printf "%.3g s", 163840000 * c / hz }')
        printf '%s\n' "$out" | grep -q "on the board *about $want at $mhz MHz, estimated: 10,000 instructions a pixel x $cpi cycles" &&
            ok "$b: the time estimated at the table's --aa 3 CPI ($want: 163,840,000 x $cpi at $mhz MHz)" ||
            bad "$b: the estimated time ($want, CPI $cpi): $out"
    fi
    others=$(printf '%s\n' "$out" | grep -c 'QEMU\|rp2040js' | tr -d ' ')
    printf '%s\n' "$out" | grep -qx "$emu ran it in 7.5 s on this machine (boot, render, output)." &&
        [ "$(printf '%s\n' "$out" | grep -v "(QEMU's model)" | grep -c "$( [ $emu = QEMU ] && echo rp2040js || echo QEMU)")" = 0 ] &&
        ok "$b: $emu named, with its wall time ($others lines name an emulator)" ||
        bad "$b: the emulator ($emu): $out"
done

# one sample: the table's one-sample row; no wall time: no sentence about it
b=mps2-an385
info=$(make -s --no-print-directory -f Makefile -f "$tmp/title.mk" print-title BOARD=$b 2>&1)
hz=${info%%|*} title=${info#*|}
printf 'pixels 100\nrender_instructions 1000000\ninstructions_per_pixel 10000\n' >"$tmp/bare.txt"
out=$(summarize $b "$tmp/bare.txt" "")
cpi=$(awk -F, -v b="$b" '$1 == b && $4 == "1 sample" { printf "%.2f", $7 }' "$table")
if [ -z "$(sentences "$out")" ] && printf '%s\n' "$out" | grep -q "x $cpi cycles" &&
    printf '%s\n' "$out" | grep -q 'with one sample a pixel' && ! printf '%s\n' "$out" | grep -q 'ran it in'; then
    ok "$b, one sample, no wall time: the one-sample CPI ($cpi), no emulator sentence"
else
    bad "$b, one sample, no wall time: $(sentences "$out") | $out"
fi
# two cores: the time is the critical path's, and says so
printf 'pixels 100\nrender_instructions 1000000\ninstructions_per_pixel 10000\ncores 2\ncritical_path_instructions 600000\n' >"$tmp/two.txt"
out=$(summarize $b "$tmp/two.txt" "")
want=$(awk -v c="$cpi" -v hz="$hz" 'BEGIN { printf "%.3g s", 600000 * c / hz }')
if [ -z "$(sentences "$out")" ] && printf '%s\n' "$out" | grep -q "about $want at .* the critical path's 600,000 instructions (2 cores) x $cpi"; then
    ok "two cores: the critical path's 600,000 instructions x $cpi ($want)"
else
    bad "two cores ($want): $(sentences "$out") | $out"
fi
# the pico's two cores: the runner counts each core's instructions, and
# the line a pixel gives both cores' together
printf 'pixels 100\nrender_cycles 5000000\nrender_instructions 1000000\ninstructions_per_pixel 10000\ncore1_render_instructions 1200000\nrp2040js wall time on the host (x): 1.0 s\n' >"$tmp/pico2.txt"
out=$(summarize pico "$tmp/pico2.txt" "")
if [ -z "$(sentences "$out")" ] && printf '%s\n' "$out" | grep -q "22,000 instructions a pixel, both cores together\."; then
    ok "pico, two cores: 22,000 instructions a pixel, both cores together (the runner's two counts)"
else
    bad "pico, two cores: $(sentences "$out") | $out"
fi
# the pico's title says how many cores render: both, or one (CORES=1)
for c in 2 1; do
    info=$(make -s --no-print-directory -f Makefile -f "$tmp/title.mk" print-title BOARD=pico CORES=$c 2>&1)
    hz=${info%%|*} title=${info#*|}
    out=$(summarize pico "$tmp/pico2.txt" "")
    case $c in
    2) want="with both Cortex-M0+ cores" not="one Cortex-M0+ core" ;;
    *) want="with one Cortex-M0+ core of its two (CORES=1)" not="both" ;;
    esac
    line=$(printf '%s\n' "$out" | sed -n 3p)
    if [ -z "$(sentences "$out")" ] && printf '%s\n' "$line" | grep -qF "$want" && ! printf '%s\n' "$line" | grep -qF "$not"; then
        ok "pico, CORES=$c: \"$line\""
    else
        bad "pico, CORES=$c: expected \"$want\" and no \"$not\": $line $(sentences "$out")"
    fi
done
# the image line names the PNG and the board's files to flash (copied
# beside it by make run), and only the PNG on a board with none
for case in "pico|out/x.uf2|out/x.png, and for the board out/x.uf2." \
            "stm32f4|out/x.bin out/x.hex|out/x.png, and for the board out/x.bin and out/x.hex." \
            "mps2-an385||out/x.png."; do
    b=${case%%|*} rest=${case#*|}
    images=${rest%%|*} want=${rest#*|}
    info=$(make -s --no-print-directory -f Makefile -f "$tmp/title.mk" print-title BOARD=$b 2>&1)
    hz=${info%%|*} title=${info#*|}
    line=$(summarize $b "$tmp/pico2.txt" "" "$table" "$images" | grep '^  image ')
    if [ "$(printf '%s\n' "$line" | sed 's/^  image  *//')" = "$want" ]; then
        ok "$b: the image line names ${images:-no file for the board}: $line"
    else
        bad "$b: the image line, expected '$want': '$line'"
    fi
done
# a board and backend the table does not have: a sentence, no figure
head -1 "$table" >"$tmp/empty.csv"
out=$(summarize $b "$tmp/bare.txt" "--aa 3" "$tmp/empty.csv")
if [ -z "$(sentences "$out")" ] && printf '%s\n' "$out" | grep -q 'so no time is given\.' &&
    ! printf '%s\n' "$out" | grep -q ' s at '; then
    ok "$b, no row in the time table: says no time is given"
else
    bad "$b, no row in the time table: $(sentences "$out") | $out"
fi

# a board that reports its UART's rate and bytes (the stm32f4): the time
# on the wire, 10 bits a byte, and reset to the last byte, render and
# wire together; a board that does not gets no such line
b=stm32f4
info=$(make -s --no-print-directory -f Makefile -f "$tmp/title.mk" print-title BOARD=$b 2>&1)
hz=${info%%|*} title=${info#*|}
printf 'pixels 76800\nrender_instructions 69047664\ninstructions_per_pixel 899\nuart_baud 921600\nuart_bytes 230954\n' >"$tmp/wire.txt"
out=$(summarize $b "$tmp/wire.txt" "")
cpi=$(awk -F, -v b="$b" '$1 == b && $4 == "1 sample" { printf "%.2f", $7 }' "$table")
wire=$(awk 'BEGIN { printf "%.3g s", 230954 * 10 / 921600 }')
both=$(awk -v c="$cpi" -v hz="$hz" 'BEGIN { printf "%.3g s", 69047664 * c / hz + 230954 * 10 / 921600 }')
if [ -z "$(sentences "$out")" ] && printf '%s\n' "$out" | grep -q "on the wire *$wire at 921600 baud (8N1: 10 bits a byte), for the 230,954 bytes" &&
    printf '%s\n' "$out" | grep -q "^ *$both from reset to the last byte, render and wire together\.$" &&
    ! summarize mps2-an385 "$tmp/bare.txt" "" | grep -q 'on the wire'; then
    ok "$b: on the wire $wire (230,954 bytes at 921600 baud), $both from reset to the last byte; none on a board without uart_baud"
else
    bad "$b: the time on the wire ($wire, $both): $(sentences "$out") | $out"
fi

# every runner prints the wall-time line summary.sh reads
for r in tools/firmware/run.sh tools/emu/*/run.sh tools/emu/pico/run.mjs; do
    [ -f "$r" ] || continue
    grep -q '\(QEMU\|rp2040js\) wall time on the host (' "$r" &&
        ok "$r prints \"<emulator> wall time on the host (...)\"" ||
        bad "$r prints no wall-time line summary.sh reads"
done

summary report-tests
