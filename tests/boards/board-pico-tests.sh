#!/bin/sh
# The Pico (platform/pico/, RP2040 under rp2040js): beyond what
# tests/boards/ports-tests.sh checks on every board,
#  - the image is the chip's: the UF2 checks out (uf2.mjs check: blocks,
#    family, addresses, boot2's CRC, the vector table at 0x10000100), and
#    the ELF has no BKPT (semihosting) and no address of the emulator-only
#    counter block (0x40068000), and only reset runs from flash: the
#    render misses the XIP cache nowhere (run.mjs --xip-model);
#  - run.mjs boots that UF2 as the chip does (boot ROM's CRC check, boot2
#    from SRAM against its flash model), with its strict checks on: a
#    block touched in reset, an unmapped access, UART or SPI without
#    clk_peri, flash before boot2 set up XIP, a BKPT would each fail;
#  - the panel as run.mjs decodes it (ST7789 MADCTL and window model, the
#    module's glass) equals the host's fixed render in rgb565be byte for
#    byte, on the three benchmark scenes and at an odd size, for both
#    PANEL choices and flipped, and the report's counters equal rt --stats
#    (on two cores its ray counts: each band is a render of its own);
#  - the report's SysTick cycles equal the emulator's own count within
#    0.1% (run.mjs fails the run otherwise; checked here too), clk_sys and
#    clk_peri are 125 MHz, the exit status 0, and the firmware printed its
#    progress;
#  - progressive display (PROGRESSIVE=1, the default): the panel after
#    each pass, taken by run.mjs at board_pass_shown, equals the host's
#    rt --progressive-pass N (two sizes, both panels), pass 1 is on the
#    panel within 5% of the frame's time, and PROGRESSIVE=0 draws in
#    scanline order (its progress in rows); the board's own frame_ms and
#    first_picture_us equal the runner's count within 2%, on two cores
#    where core 1 ends pass 1, and on one;
#  - the UART stream (PICO_DISPLAY=uart) equals the host's in rgb888;
#  - both cores (the default; app/firmware/bands.c) give the panel
#    bytes core 0 alone gives (CORES=1), the report has each core's
#    cycles and bands (and the runner each core's instructions), the two-core frame's critical path and its time on
#    core 0 are at most 0.55 of one core's cycles, and each core's stack
#    sits in its own 4 KiB SRAM bank;
#  - the SIO divider (PICO_DIVIDER=1, the default) and libgcc's division
#    (0) give the same image and counters, the divider in fewer cycles on
#    a scene that divides (rings-1: cylinders);
#  - a crystal that never starts (run.mjs --no-crystal): the firmware's
#    bounded wait expires and it says so, status 5, LED off (on after a
#    good run);
#  - what silicon would not survive fails with its reason: a damaged
#    boot2 CRC, clk_peri left stopped (tests/boards/pico_clk_peri_off.c), and on small
#    images (tests/boards/pico_fault.S) a block written in reset, a bkpt, a read
#    of 0x40068000, a boot2 that leaves XIP unset, the TIMER read with
#    the watchdog's tick as at reset; a mirrored
#    MADCTL (the image differs), no INVON (inverted colours), a missing
#    row offset, a byte sent with chip select high, and the damaged
#    transfers of before (data short of its window, a window off the
#    panel, pixels before sleep out, a frame band lost, the clear lost);
#    a frame larger than the panel does not build;
#  - the runner's second core (core1.mjs) on small images
#    (tests/boards/pico_core1.c): each FIFO, event, spinlock, divider, launch
#    and reset behaviour against the datasheet's value, and a broken
#    launch, entry, vector table, divider read or end failing with its
#    reason;
#  - the scene's resolution is the frame when SIZE is not given: a
#    `resolution 320 240` scene fills the 320x240 panel (make run), the
#    UF2 says so in its check line, make image with the same variables
#    hands over the UF2 make run ran (make run's image line names it
#    beside the PNG), and on PANEL=240x240 the scene is a
#    build error naming both sizes; a 160x120 frame is centred on the
#    panel with every other pixel black (the whole panel checked).
RT=${1:-build/host/rt}
OUT=build/test-pico
. tests/boards/board-case.sh
val() { report_val "$@"; }
elf_of() { make -s board-info BOARD=pico "$@" | sed -n 's/.*elf=\([^ ]*\)\.elf.*/\1/p'; }

echo "pico: rp2040js RP2040, booted from the UF2 as the chip boots, against the hosted fixed build"
pico_case() { # NAME SCENE SIZE DEPTH FORMAT [MAKE-VARS]
    n=$1 scene=$2 size=$3 depth=$4 format=$5 vars=$6
    set -- BOARD=pico SCENE="$scene" SIZE="$size" DEPTH="$depth" $vars
    board_build $n "$@" || return 1
    base=$(elf_of "$@")
    if chk=$(node tools/emu/pico/uf2.mjs check "$base.uf2" 2>&1); then
        ok "$n: $chk"
    else
        bad "$n: the UF2 does not check out: $chk"
    fi
    board_run $n "$@" || return 1
    # progressive passes (the panel's default): the host in the same order,
    # for the same counts of the core's caches; the image is the scanline
    # order's either way (tests/host/progressive-tests.sh; and pass 7 below)
    prog=$(awk '$1 == "progress_pass" { print "--progressive"; exit }' "$OUT/$n.report")
    ipp=$(val instructions_per_pixel "$OUT/$n.report") cpp=$(val cycles_per_pixel "$OUT/$n.report")
    board_vs_host $n "fixed $format" "$size depth $depth, $ipp instructions and $cpp cycles a pixel" \
        "$scene" --size "$size" --depth "$depth" --format "$format" $prog
    # SysTick's count against the emulator's, in the same window
    sys=$(val render_cycles "$OUT/$n.report") emu=$(val emulator_render_cycles "$OUT/$n.report")
    ins=$(val render_instructions "$OUT/$n.report")
    if [ -n "$sys" ] && [ -n "$emu" ] && [ -n "$ins" ] &&
       awk -v a="$sys" -v b="$emu" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(b > 0 && d <= b / 1000) }' &&
       [ "$sys" -ge "$ins" ]; then
        ok "$n: SysTick render_cycles $sys, the emulator's $emu (within 0.1%), >= $ins instructions"
    else
        bad "$n: SysTick render_cycles ${sys:-?} against the emulator's ${emu:-?}, instructions ${ins:-?}"
    fi
    if [ "$(val clk_sys_hz "$OUT/$n.report")" = 125000000 ] && [ "$(val clk_peri_hz "$OUT/$n.report")" = 125000000 ] &&
       grep -q 'clk_sys 125.000 MHz, clk_peri 125.000 MHz' "$OUT/$n.report" && [ "$(val exit_status "$OUT/$n.report")" = 0 ]; then
        ok "$n: clk_sys and clk_peri 125 MHz (as set, and as the emulator computes them), exit_status 0"
    else
        bad "$n: clocks or exit status: $(grep -E 'clk_|exit_status' "$OUT/$n.report" | tr '\n' ' ')"
    fi
}
pico_case card-320 scenes/bench/card.nff 40x30 3 rgb565be
pico_case picolib-320 scenes/bench/picolib.nff 40x30 6 rgb565be
pico_case whitted-240 scenes/bench/whitted.nff 40x30 5 rgb565be "PANEL=240x240 CORES=1"
pico_case showpiece-odd-320 scenes/showpiece.nff 47x31 5 rgb565be
pico_case showpiece-odd-240-flip scenes/showpiece.nff 47x31 5 rgb565be "PANEL=240x240 PANEL_FLIP=1 PROGRESSIVE=0"
pico_case card-320-flip scenes/bench/card.nff 40x30 3 rgb565be PANEL_FLIP=1
pico_case showpiece-uart scenes/showpiece.nff 32x24 5 rgb888 PICO_DISPLAY=uart
# the divider against libgcc's division in the generic firmware, where
# the quotients are calls of their own (built for the scene, the two run
# within 0.1% of each other: code placement moves as much)
pico_case rings-div scenes/spd/rings-1.nff 24x24 5 rgb565be SPECIALISE=0
pico_case rings-nodiv scenes/spd/rings-1.nff 24x24 5 rgb565be "PICO_DIVIDER=0 SPECIALISE=0"

# Both cores (the default build) against core 0 alone (make CORES=1), in
# scanline order (the passes of progressive display, split as
# app/firmware/bands.c says, are checked against the host's below),
# on a frame of CORES_BANDS bands of 4 lines: the same panel bytes (the whole
# panel as the glass shows it), each core's cycles and bands in the
# report, and the two-core frame within CORES_SHARE of one core's cycles,
# both its critical path (the later core's render plus its waits, output
# left out) and its time on core 0 (render_cycles). rp2040js steps the two
# cores by their cycles, so the figures repeat exactly.
CORES_SIZE=80x48 CORES_BANDS=12 CORES_SHARE=0.55
pico_case card-cores2 scenes/bench/card.nff $CORES_SIZE 3 rgb565be PROGRESSIVE=0
pico_case card-cores1 scenes/bench/card.nff $CORES_SIZE 3 rgb565be "CORES=1 PROGRESSIVE=0"
r2=$OUT/card-cores2.report r1=$OUT/card-cores1.report
p2=$(elf_of SCENE=scenes/bench/card.nff SIZE=$CORES_SIZE DEPTH=3 PROGRESSIVE=0).panel.stream
p1=$(elf_of SCENE=scenes/bench/card.nff SIZE=$CORES_SIZE DEPTH=3 CORES=1 PROGRESSIVE=0).panel.stream
if [ -s "$p2" ] && cmp -s "$p1" "$p2"; then
    ok "two cores: the whole panel byte-identical to one core's ($(wc -c <"$p2") bytes of $(basename "$p2"))"
else
    bad "two cores: the panel differs from one core's ($p2, $p1)"
fi
c0=$(val core0_render_cycles "$r2") c1=$(val core1_render_cycles "$r2") b0=$(val core0_bands "$r2") b1=$(val core1_bands "$r2")
i0=$(val render_instructions "$r2") i1=$(val core1_render_instructions "$r2")
if [ "$(val cores "$r2")" = 2 ] && [ "$(val cores_one_at_a_time "$r2")" = 0 ] && [ "${c0:-0}" -gt 0 ] && [ "${c1:-0}" -gt 0 ] &&
   [ "${b0:-0}" -gt 0 ] && [ "${b1:-0}" -gt 0 ] && [ $((b0 + b1)) = $CORES_BANDS ] && [ -z "$(val cores "$r1")" ] &&
   [ "${i0:-0}" -gt 0 ] && [ "${i1:-0}" -gt 0 ]; then
    ok "two cores: core 0 rendered $b0 bands in $c0 cycles, core 1 $b1 in $c1 (SysTick, each core's own); the runner counted $i0 and $i1 instructions"
else
    bad "two cores: report cores $(val cores "$r2"), cycles ${c0:-?} and ${c1:-?}, bands ${b0:-?} + ${b1:-?} of $CORES_BANDS, instructions ${i0:-?} and ${i1:-?}"
fi
one=$(val render_cycles "$r1") cp=$(val critical_path_cycles "$r2") frame=$(val render_cycles "$r2")
if share=$(awk -v one="$one" -v cp="$cp" -v f="$frame" -v max=$CORES_SHARE 'BEGIN {
        if (!(one > 0 && cp > 0 && f >= cp)) exit 1
        printf "critical path %d, %.4f of one core'"'"'s %d cycles (%.2fx), frame on core 0 %d, %.4f", cp, cp / one, one, one / cp, f, f / one
        exit !(cp / one <= max && f / one <= max) }'); then
    ok "two cores: $share, <= $CORES_SHARE"
else
    bad "two cores: critical path ${cp:-?}, frame ${frame:-?} against one core's ${one:-?} cycles (at most $CORES_SHARE): $share"
fi
hw=$(val core1_stack_high_water "$r2")
tops=$(arm-none-eabi-nm "$(elf_of SCENE=scenes/bench/card.nff SIZE=$CORES_SIZE DEPTH=3 PROGRESSIVE=0).elf" | awk '$3 == "__stack_top" || $3 == "__stack1_top" { printf "%s=%s ", $3, $1 }')
if [ "${hw:-0}" -gt 0 ] && [ "$(val stack_guard_intact "$r2")" = 1 ] &&
   [ "$tops" = "__stack1_top=20041000 __stack_top=20042000 " ]; then
    ok "two cores: each stack at the top of its own 4 KiB bank ($tops), core 1's high water $hw bytes, both guards intact"
else
    bad "two cores: stacks $tops, core 1's high water ${hw:-?}, guards $(val stack_guard_intact "$r2")"
fi

# Progress over the UART while the panel fills: rows in scanline order,
# passes in progressive display
rows=$(awk '$1 == "progress_rows" { n++; last = $2 } END { print n + 0, last }' "$OUT/showpiece-odd-240-flip.report")
[ "${rows#* }" = 31 ] && [ "${rows% *}" -ge 5 ] && ok "progress (PROGRESSIVE=0): ${rows% *} progress_rows lines, the last at row ${rows#* } of 31" ||
    bad "progress lines: $rows"
passes=$(awk '$1 == "progress_pass" { printf "%s", $2 }' "$OUT/showpiece-odd-320.report")
[ "$passes" = 1234567 ] && ok "progress (progressive): progress_pass 1 to 7" || bad "progress_pass lines: '$passes'"

# Progressive display (PROGRESSIVE=1, the panel's default; the finished
# panels above are the host's scanline images): the panel after each
# pass, as run.mjs took it at board_pass_shown, equals the host's
# rt --progressive-pass N, byte for byte; pass 1 (1/64 of the rays)
# reaches the panel within 5% of the frame's time
progressive_passes() { # NAME SCENE SIZE DEPTH [MAKE-VARS]
    n=$1 scene=$2 size=$3 depth=$4
    base=$(elf_of SCENE="$scene" SIZE="$size" DEPTH="$depth" $5)
    good=0
    for p in 1 2 3 4 5 6 7; do
        "$RT" receive "$base.pass$p.stream" -o "$OUT/$n-pass$p.png" >/dev/null 2>&1 &&
            "$RT" "$scene" -o "$OUT/$n-host-pass$p.png" --size "$size" --depth "$depth" --format rgb565be \
                --progressive-pass $p --quiet &&
            "$RT" compare "$OUT/$n-pass$p.png" "$OUT/$n-host-pass$p.png" --max-error 0 >/dev/null &&
            good=$((good + 1))
    done
    fp=$(val first_picture_cycles "$OUT/$n.report") fc=$(val frame_cycles "$OUT/$n.report")
    "$RT" "$scene" -o "$OUT/$n-host-scan.png" --size "$size" --depth "$depth" --format rgb565be --quiet &&
        "$RT" compare "$OUT/$n-board.png" "$OUT/$n-host-scan.png" --max-error 0 >/dev/null || good=0
    if [ $good -eq 7 ]; then
        ok "$n progressive: the panel after each of passes 1..7 == rt --progressive-pass N rgb565be, the last == scanline order's"
    else
        bad "$n progressive: $good of 7 passes' panels equal the host's"
    fi
    if [ -n "$fp" ] && [ -n "$fc" ] && [ $((fp * 20)) -lt "$fc" ]; then
        ok "$n progressive: the first picture on the panel after $fp cycles, the frame after $fc"
    else
        bad "$n progressive: first_picture_cycles '${fp:-?}', frame_cycles '${fc:-?}'"
    fi
}
progressive_passes card-320 scenes/bench/card.nff 40x30 3
progressive_passes showpiece-odd-320 scenes/showpiece.nff 47x31 5
progressive_passes whitted-240 scenes/bench/whitted.nff 40x30 5 "PANEL=240x240 CORES=1"
# The board's own times (frame_ms, first_picture_us: the TIMER's
# microseconds, one count for both cores) against the runner's count of
# the same events on its one clock (render start on core 0 to its end,
# and to pass 1 on the panel), within 2%: on both cores where core 1
# ends pass 1 (started on core 0, so the core's own SysTick would not
# do), and on core 0 alone
board_times() { # NAME CORE-ENDING-PASS-1
    r=$OUT/$1.report
    fp=$(val first_picture_us "$r") efp=$(val emulator_first_picture_us "$r") fm=$(val frame_ms "$r") efu=$(val emulator_frame_us "$r")
    if grep -q "^emulator_first_picture_us .*pass 1 ended on core $2)" "$r" &&
       d=$(awk -v fp="$fp" -v efp="$efp" -v fm="$fm" -v efu="$efu" 'BEGIN {
           if (!(efp > 0 && efu > 0 && fp != "" && fm != "")) exit 1
           a = (fp - efp) / efp * 100; b = (fm * 1000 - efu) / efu * 100
           printf "%+.2f%% and %+.2f%%", a, b
           exit !(a <= 2 && a >= -2 && b <= 2 && b >= -2) }'); then
        ok "$1: first_picture_us $fp and frame_ms $fm against the runner's $efp us and $efu us ($d, within 2%), pass 1 ended on core $2"
    else
        bad "$1: first_picture_us '${fp:-?}', frame_ms '${fm:-?}' against the runner's '${efp:-?}' us, '${efu:-?}' us (within 2%), pass 1 on core $2: $(grep '^emulator_first' "$r")"
    fi
}
board_times card-320 1
board_times whitted-240 0
grep -q '^progress_pass' "$OUT/showpiece-odd-240-flip.report" && bad "PROGRESSIVE=0 reports passes" ||
    ok "PROGRESSIVE=0: scanline order, no passes"
# what progressive display cannot draw does not build
for v in "BOARD=mps2-an385 PROGRESSIVE=1:not a panel" "BOARD=pico AA=2 PROGRESSIVE=1:adaptive anti-aliasing" \
         "BOARD=pico PICO_DISPLAY=uart PROGRESSIVE=1:not a panel" "BOARD=pico PROGRESSIVE=yes:0 (scanline order) or 1"; do
    if msg=$(make -s board-info ${v%%:*} 2>&1); then
        bad "${v%%:*}: accepted"
    else
        echo "$msg" | grep -q "${v#*:}" && ok "${v%%:*}: $(echo "$msg" | sed 's/.*\*\*\* //' | head -1)" ||
            bad "${v%%:*}: '$msg'"
    fi
done

# The image is the chip's
elf=$(elf_of SCENE=scenes/showpiece.nff SIZE=47x31 DEPTH=5).elf
bkpt=$(arm-none-eabi-objdump -d "$elf" | grep -c 'bkpt')
lit=$(arm-none-eabi-objdump -s "$elf" | grep -ci ' 00800640 ')
[ "$bkpt" -eq 0 ] && [ "$lit" -eq 0 ] && ok "the image has no BKPT and no 0x40068000 literal" ||
    bad "the image has $bkpt BKPT and $lit 0x40068000 literals"

# Only reset runs from flash: every other function, and the read-only
# data, is in SRAM (the render reads no flash through the XIP cache)
inflash=$(arm-none-eabi-nm "$elf" | awk 'tolower($2) ~ /^[tr]$/ && $1 ~ /^1/ && $3 !~ /^(Reset_Handler|reset_c|copy_words|vector_table)$/ { print $3 }' | tr '\n' ' ')
insram=$(arm-none-eabi-nm "$elf" | awk 'tolower($2) ~ /^[tr]$/ && $1 ~ /^2/ { n++ } END { print n + 0 }')
[ -z "$inflash" ] && [ "$insram" -gt 100 ] && ok "code in SRAM: $insram functions and read-only objects there, only reset and the vector table in flash" ||
    bad "code or read-only data in flash: $inflash($insram in SRAM)"

# The divider: the same bits, fewer cycles
if cmp -s "$OUT/rings-div-board.png" "$OUT/rings-nodiv-board.png"; then
    c1=$(val render_cycles "$OUT/rings-div.report") c0=$(val render_cycles "$OUT/rings-nodiv.report")
    if [ -n "$c1" ] && [ -n "$c0" ] && [ "$c1" -lt "$c0" ]; then
        ok "SIO divider: the same image, $c1 cycles against libgcc's $c0"
    else
        bad "SIO divider: $c1 cycles against libgcc's $c0"
    fi
else
    bad "SIO divider and libgcc's division give different images"
fi
# (the generic builds above, whose fx_wdiv* are functions of their own;
# libgcc's build calls its division from them)
wdiv_calls() {
    arm-none-eabi-objdump -d "$(elf_of SCENE=scenes/spd/rings-1.nff SIZE=24x24 DEPTH=5 SPECIALISE=0 "$@").elf" |
        awk '/^[0-9a-f]+ <.*>:$/ { fn = $2 } fn ~ /wdiv/ { f[fn] = 1 } /bl.*<__(aeabi_uidiv|udivsi3)/ && fn ~ /wdiv/ { n++ }
             END { for (k in f) nf++; print nf + 0, n + 0 }'
}
set -- $(wdiv_calls) $(wdiv_calls PICO_DIVIDER=0)
[ "$1" -gt 0 ] && [ "$2" -eq 0 ] && [ "$4" -gt 0 ] && ok "with the divider, $1 fx_wdiv* call no libgcc division (libgcc's build: $4 calls)" ||
    bad "fx_wdiv*: ${1:-?} functions, ${2:-?} calls of libgcc's division with the divider, ${4:-?} without"

# The render reads no flash past the XIP cache (run.mjs --xip-model):
# no miss as built, where code in flash would miss
b=$(elf_of SCENE=scenes/bench/card.nff SIZE=40x30 DEPTH=3)
node tools/emu/pico/run.mjs --xip-model "$b.elf" "$OUT/xip.png" "$RT" >"$OUT/xip.report" 2>&1
m=$(val xip_render_misses "$OUT/xip.report") f=$(val xip_model_code_in_flash_misses "$OUT/xip.report")
if [ "$m" = 0 ] && [ "${f:-0}" -gt 0 ]; then
    ok "XIP cache model: no miss in the render ($(val xip_render_flash_reads "$OUT/xip.report") flash reads); $f misses with code and tables in flash"
else
    bad "XIP cache model: ${m:-?} misses in the render, ${f:-?} with code in flash"
fi

# A crystal that never starts: the bounded wait expires, the firmware says
# which, stops with status 5 and leaves the LED off
b=$(elf_of SCENE=scenes/bench/card.nff SIZE=40x30 DEPTH=3)
msg=$(node tools/emu/pico/run.mjs --no-crystal "$b.elf" "$OUT/nocrystal.png" "$RT" 2>&1); status=$?
if [ $status -eq 5 ] && echo "$msg" | grep -q 'XOSC) never became stable' && echo "$msg" | grep -q 'LED (GP25) at the end: off'; then
    ok "no crystal: status 5, '$(echo "$msg" | grep XOSC)', LED off"
else
    bad "no crystal: status $status, '$(echo "$msg" | tail -3 | tr '\n' ' ')'"
fi
grep -q 'LED (GP25) at the end: on' "$OUT/card-320.report" && ok "the LED is on after a good run" || bad "the LED is not on after a good run"

# What the chip would not survive: a damaged boot2 CRC
base=$(elf_of SCENE=scenes/showpiece.nff SIZE=47x31 DEPTH=5)
mkdir -p "$OUT/badcrc"
cp "$base.elf" "$OUT/badcrc/fixed.elf"
python3 -c "import sys
d = bytearray(open(sys.argv[1], 'rb').read())
d[32 + 10] ^= 0x01          # a byte of boot2's code in the first block's payload
open(sys.argv[2], 'wb').write(d)" "$base.uf2" "$OUT/badcrc/fixed.uf2"
msg=$(node tools/emu/pico/uf2.mjs check "$OUT/badcrc/fixed.uf2" 2>&1) && bad "uf2.mjs check passed a damaged boot2: $msg" ||
    { echo "$msg" | grep -q 'CRC' && ok "uf2.mjs check: $msg" || bad "uf2.mjs check without a CRC message: $msg"; }
msg=$(node tools/emu/pico/run.mjs "$OUT/badcrc/fixed.elf" "$OUT/badcrc.png" "$RT" 2>&1); status=$?
if [ $status -ne 0 ] && echo "$msg" | grep -q 'CRC' && echo "$msg" | grep -q 'USB boot'; then
    ok "a damaged boot2 CRC: $(echo "$msg" | grep CRC | head -1)"
else
    bad "a damaged boot2 CRC: status $status, '$msg'"
fi

# ... and the runner's other checks, on small images (tests/boards/pico_fault.S)
fault_image() { # NAME BOOT2-OBJECT: $OUT/fault/NAME.elf and .uf2
    arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -nostdlib -nostartfiles -e start -DFAULT_$1 \
        -Wl,--section-start=.boot2=0x10000000 -Wl,--section-start=.text=0x10000100 \
        -o "$OUT/fault/$1.elf" tests/boards/pico_fault.S "$2" &&
        arm-none-eabi-objcopy -O binary "$OUT/fault/$1.elf" "$OUT/fault/$1.bin" &&
        node tools/emu/pico/uf2.mjs pack "$OUT/fault/$1.bin" "$OUT/fault/$1.uf2"
}
mkdir -p "$OUT/fault"
boot2=${FW_ROOT:-build/board}/pico/boot2/boot2_crc.o
arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -nostdlib -nostartfiles -e start -DFAULT_BOOT2 -Wl,-Ttext=0x20041f00 \
    -o "$OUT/fault/boot2.elf" tests/boards/pico_fault.S && arm-none-eabi-objcopy -O binary "$OUT/fault/boot2.elf" "$OUT/fault/boot2.bin" &&
    node tools/emu/pico/uf2.mjs boot2 "$OUT/fault/boot2.bin" "$OUT/fault/boot2.S" &&
    arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -c "$OUT/fault/boot2.S" -o "$OUT/fault/boot2.o"
for f in "RESET $boot2 in reset" "BKPT $boot2 HardFault" "UNMAPPED $boot2 nothing is mapped" "XIP $OUT/fault/boot2.o SSI not set up" \
         "TIMER $boot2 TIMER read with the watchdog's tick every 0 cycles"; do
    set -- $f
    name=$1 obj=$2
    shift 2
    if fault_image "$name" "$obj" >"$OUT/fault/$name.build" 2>&1; then
        msg=$(node tools/emu/pico/run.mjs "$OUT/fault/$name.elf" "$OUT/fault/$name.png" "$RT" 2>&1); status=$?
        if [ $status -ne 0 ] && echo "$msg" | grep -q "$*"; then
            ok "$(echo "$name" | tr A-Z a-z): $(echo "$msg" | grep "$*" | head -1 | cut -c1-150)"
        else
            bad "$name: status $status, '$msg'"
        fi
    else
        bad "$name: the fault image did not build: $(tail -2 "$OUT/fault/$name.build")"
    fi
done

# The second core as run.mjs models it (tools/emu/pico/core1.mjs), on
# small images (tests/boards/pico_core1.c): the launch through the boot ROM's
# wait, FIFOs, events, spinlocks, per-core SIO, a core-1 reset; and each
# broken use fails with its reason
core1_image() { # NAME [CASE]
    arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -Os -ffreestanding -nostdlib -Wall -Wextra -Werror -Iplatform/pico ${2:+-DCASE_$2} \
        -T tests/boards/pico_core1.ld -o "$OUT/core1/$1.elf" tests/boards/pico_core1.c "$boot2" -lgcc &&
        arm-none-eabi-objcopy -O binary "$OUT/core1/$1.elf" "$OUT/core1/$1.bin" &&
        node tools/emu/pico/uf2.mjs pack "$OUT/core1/$1.bin" "$OUT/core1/$1.uf2" >/dev/null
}
mkdir -p "$OUT/core1"
if core1_image pass >"$OUT/core1/pass.build" 2>&1 &&
   node tools/emu/pico/run.mjs "$OUT/core1/pass.elf" "$OUT/core1/pass.png" "$RT" >"$OUT/core1/pass.report" 2>&1; then
    # each value as the datasheet gives it (the list in tests/boards/pico_core1.c)
    for kv in stale_vld=1 stale_word=0 launched=1 cpuid0=0 cpuid1=1 roe_at_entry=10 div0=333 div1=142857 locked_count=200 \
              sev_woke=1 wfi_after_sev=0 wfi_irq_word=77 own_event=1 lock_first=32 lock_again=0 lock_st=32 lock_core1_held=0 lock_core1_freed=32 \
              fifo_full_st=4 fifo_cleared_st=0 fifo_empty_read=0 fifo_roe_st=8 irq15_roe=1 irq15_clear=0 \
              reset_stale=0 reset_more=0 relaunched=1 tie_core0=128 tie_core1=0 core1_launches=2 exit_status=0; do
        got=$(val "${kv%=*}" "$OUT/core1/pass.report")
        [ "$got" = "${kv#*=}" ] || bad "core 1 model: ${kv%=*} is ${got:-missing}, expected ${kv#*=}"
    done
    # each core's marks counted apart: 100 additions under a lock, at
    # least 5 instructions each
    for k in render_instructions core1_render_instructions; do
        [ "$(val $k "$OUT/core1/pass.report")" -ge 500 ] 2>/dev/null ||
            bad "core 1 model: $k is $(val $k "$OUT/core1/pass.report"), expected at least 500 (each core's marks counted apart)"
    done
    c1=$(val core1_instructions "$OUT/core1/pass.report")
    [ "${c1:-0}" -gt 50 ] && grep -q '^core 1 at the end: sleeping (WFI)' "$OUT/core1/pass.report" &&
        ok "core 1 model: stale 0, launch, CPUID, ROE at entry, per-core dividers, a counter under a spinlock, SEV/WFE (not WFI), SIO_IRQ_PROC1 waking WFI, spinlocks, FIFO WOF/ROE/IRQ 15, reset by PSM and relaunch, core 0 wins a tie ($c1 core-1 instructions)" ||
        bad "core 1 model: core 1 ran ${c1:-no} instructions: $(grep '^core 1 at the end' "$OUT/core1/pass.report")"
else
    bad "core 1 model: the image did not build or run: $(tail -3 "$OUT/core1/pass.build" "$OUT/core1/pass.report")"
fi
for f in "ONE_ZERO expected 0 (the second of 0, 0, 1).*received 0x00000001" \
         "NO_DRAIN expected the vector table.*received 0x00000000 (the sequence restarted" \
         "NO_THUMB entry 0x[0-9a-f]* has no Thumb bit" \
         "VTOR sets VTOR to 0x[0-9a-f]*04, not aligned to 256 bytes" \
         "DIV_EARLY core 1 reads the divider's DIV_QUOTIENT 2 cycles after" \
         "BUSY core 1 is still busy (running at" \
         "UNGUARDED core 1 writes 0x20000100, in the data the image guards by spinlock"; do
    name=${f%% *} want=${f#* }
    if core1_image "$name" "$name" >"$OUT/core1/$name.build" 2>&1; then
        msg=$(node tools/emu/pico/run.mjs "$OUT/core1/$name.elf" "$OUT/core1/$name.png" "$RT" 2>&1); status=$?
        if [ $status -ne 0 ] && echo "$msg" | grep -q "on core [01]: .*$want\|^pico run: $want"; then
            ok "core 1 $(echo "$name" | tr A-Z_ a-z\ ): $(echo "$msg" | grep 'pico run' | cut -c1-160)"
        else
            bad "core 1 $name: status $status, '$msg'"
        fi
    else
        bad "core 1 $name: the image did not build: $(tail -2 "$OUT/core1/$name.build")"
    fi
done

# ... clk_peri left stopped: a test build (its own build folder) whose
# port_init is wrapped by tests/boards/pico_clk_peri_off.c
clk_peri_off() { # MAKE-ARGS...
    make -s "$@" BOARD=pico SCENE=scenes/spd/tetra-1.nff SIZE=8x8 DEPTH=3 BOARD_TAG=-clk_peri_off \
        BOARD_SRC="platform/pico/board.c tests/boards/pico_clk_peri_off.c" BOARD_LDFLAGS=-Wl,--wrap=port_init
}
if clk_peri_off -j2 firmware >"$OUT/omit.build" 2>&1; then
    msg=$(clk_peri_off board-run RUN_OUT="$OUT/omit.png" RUN_RT="$RT" 2>&1); status=$?
    if [ $status -ne 0 ] && echo "$msg" | grep -q 'clk_peri'; then
        ok "clk_peri left stopped: $(echo "$msg" | grep clk_peri | head -1)"
    else
        bad "clk_peri left stopped: status $status, '$(echo "$msg" | tail -2)'"
    fi
else
    bad "the clk_peri_off build failed: $(tail -2 "$OUT/omit.build")"
fi

# The panel's model, from the odd frames' SPI logs (pairs: flags, byte)
panel_damage() { # WHAT LOG PANEL FLIP HOST-PNG PYTHON-ON-d EXPECTED(message, or 'differs')
    python3 -c "import sys
d = bytearray(open(sys.argv[1], 'rb').read())
cmds = [i for i in range(0, len(d), 2) if d[i] & 0x81 == 0]
$6
open(sys.argv[2], 'wb').write(d)" "$2" "$OUT/bad.spi"
    rm -f "$OUT/bad.stream" "$OUT/bad.png"
    msg=$(node tools/emu/pico/run.mjs --panel "$OUT/bad.spi" 47 31 "$OUT/bad.stream" "$3" "$4" 2>&1); status=$?
    if [ "$7" = differs ]; then
        if [ $status -eq 0 ] && "$RT" receive "$OUT/bad.stream" -o "$OUT/bad.png" >/dev/null &&
           cmp=$("$RT" compare "$OUT/bad.png" "$5" --max-error 0); then
            bad "$1: decoded to the host's image ($cmp)"
        elif [ -f "$OUT/bad.png" ]; then
            ok "$1: the panel shows a different picture ($("$RT" compare "$OUT/bad.png" "$5" | head -1))"
        else
            ok "$1: no picture: $msg"
        fi
    elif [ $status -ne 0 ] && [ ! -e "$OUT/bad.stream" ] && echo "$msg" | grep -q "$7"; then
        ok "$1: $msg"
    else
        bad "$1: status $status, '$msg'"
    fi
}
log320=$(elf_of SCENE=scenes/showpiece.nff SIZE=47x31 DEPTH=5).spi
log240=$(elf_of SCENE=scenes/showpiece.nff SIZE=47x31 DEPTH=5 PANEL=240x240 PANEL_FLIP=1 PROGRESSIVE=0).spi
host=$OUT/showpiece-odd-320-host.png
if [ -f "$log320" ] && [ -f "$log240" ]; then
    madctl="i = [c for c in cmds if d[c + 1] == 0x36][0]; d[i + 3] = "
    panel_damage "MADCTL 0x20 (MV alone: mirrored)" "$log320" 320x240 0 "$host" "${madctl}0x20" differs
    panel_damage "MADCTL 0xb0 on an upright module (turned by 180)" "$log320" 320x240 0 "$host" "${madctl}0xb0" differs
    panel_damage "no INVON (IPS glass: inverted colours)" "$log320" 320x240 0 "$host" \
        "i = [c for c in cmds if d[c + 1] == 0x21][0]; del d[i:i + 2]" differs
    panel_damage "240x240 flipped without its row offset" "$log240" 240x240 1 "$host" \
        "for c, o in [(c, o) for c in cmds if d[c + 1] == 0x2b for o in (3, 7)]: v = (d[c + o] << 8 | d[c + o + 2]) - 80; d[c + o] = v >> 8; d[c + o + 2] = v & 255" differs
    panel_damage "the 240x240 log read as the 320x240 module" "$log240" 320x240 0 "$host" "" differs
    panel_damage "a byte sent with chip select high" "$log320" 320x240 0 "$host" \
        "i = [c for c in cmds if d[c + 1] == 0x2a][0]; d[i + 2] |= 2" "chip select was high"
    panel_damage "short data" "$log320" 320x240 0 "$host" "del d[-4:-2]" "short or long data"
    panel_damage "wrong window" "$log320" 320x240 0 "$host" \
        "i = [c for c in cmds if d[c + 1] == 0x2a][0]; d[i + 7] = 0x01; d[i + 9] = 0x40" "wrong window"
    panel_damage "no sleep out" "$log320" 320x240 0 "$host" \
        "i = [c for c in cmds if d[c + 1] == 0x11][0]; del d[i:i + 2]" "before sleep out"
    panel_damage "the last band lost (the frame shows the cleared panel there)" "$log320" 320x240 0 "$host" \
        "i = [c for c in cmds if d[c + 1] == 0x2c][-1]; del d[i - 24:]" differs
    panel_damage "the clear lost" "$log320" 320x240 0 "$host" \
        "i = [c for c in cmds if d[c + 1] == 0x2c][0]; j = d.index(0x80, i); del d[i:j]" "the panel was not cleared"
    # the intact logs decode to the images the runs wrote
    for p in "$log320 320x240 0" "$log240 240x240 1"; do
        set -- $p
        if node tools/emu/pico/run.mjs --panel "$1" 47 31 "$OUT/good.stream" "$2" "$3" && "$RT" receive "$OUT/good.stream" -o "$OUT/good.png" >/dev/null &&
           "$RT" compare "$OUT/good.png" "$host" --max-error 0 >/dev/null; then
            ok "the intact SPI log of the $2 module$( [ "$3" = 1 ] && echo ', flipped') decodes to the host's image"
        else
            bad "the intact SPI log of the $2 module does not decode to the host's image"
        fi
    done
else
    bad "no SPI logs at $log320, $log240"
fi

# The SRAM copy fits the largest scene the boards bench runs (SPD
# teapot-2: 39 KB of tables) at the panel's full size
if make -s -j2 firmware BOARD=pico SCENE=scenes/spd/teapot-2.nff SIZE=320x240 DEPTH=5 >"$OUT/teapot.build" 2>&1; then
    used=$(arm-none-eabi-objdump -h "$(elf_of SCENE=scenes/spd/teapot-2.nff SIZE=320x240 DEPTH=5).elf" |
        awk -f tools/firmware/sections.awk | awk '$5 != "flash" { n += $2 } END { print n }')
    [ "$used" -le 262144 ] && ok "teapot-2 at 320x240 links: $used bytes of SRAM (code, tables, data, bss, stack) of 262144" ||
        bad "teapot-2 at 320x240: $used bytes of SRAM"
else
    bad "teapot-2 at 320x240 does not link: $(tail -2 "$OUT/teapot.build")"
fi

# Larger than the panel: a build error that says so
if make -s firmware BOARD=pico SCENE=scenes/spd/rings-1.nff SIZE=241x240 PANEL=240x240 >"$OUT/big.build" 2>&1; then
    bad "a 241x240 frame built for the 240x240 panel"
elif grep -q "the frame is larger than the 240x240 panel (PANEL=240x240): 241x240 (SIZE=241x240)" "$OUT/big.build"; then
    ok "a 241x240 frame does not build for PANEL=240x240: $(grep -o 'the frame is larger.*' "$OUT/big.build" | cut -c1-120)"
else
    bad "a 241x240 frame failed to build without the expected message: $(tail -2 "$OUT/big.build")"
fi

# The scene's resolution on the panel, no SIZE given: one sphere (cheap
# under rp2040js) at `resolution 320 240` fills the Display Pack 2.0
sphere() { # FILE W H
    printf 'v\nfrom 0 -6 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution %s %s\nl -3 -6 5\nf 0.9 0.3 0.2 1 0 1 0 1\ns 0 0 0 1\n' "$2" "$3" >"$1"
}
dims() { python3 -c 'import struct, sys; print("%dx%d" % struct.unpack(">II", open(sys.argv[1], "rb").read()[16:24]))' "$1"; }
sph="$OUT/sphere-320x240.nff"
sphere "$sph" 320 240
sv="BOARD=pico SCENE=$sph RUN_OUT=$OUT/sphere.png RUN_REF=$OUT/sphere-ref.png RUN_AREA=$OUT/sphere-area.png RUN_RT=$RT"
rm -f "$OUT/sphere.png" "$OUT/sphere.uf2"
if make run $sv >"$OUT/sphere-run.log" 2>&1; then
    elf=$(sed -n 's/^ *RUN *\([^ ]*\.elf\) on .*/\1/p' "$OUT/sphere-run.log")
    "$RT" "$sph" -o "$OUT/sphere-host.png" --fixed --format rgb565be --threads 1 --quiet
    if [ "$(dims "$OUT/sphere.png")" = 320x240 ] && cmp=$("$RT" compare "$OUT/sphere.png" "$OUT/sphere-host.png" --max-error 0) &&
       grep -q 'the 320x240 frame at 0,0' "$OUT/sphere-run.log"; then
        ok "resolution 320 240, no SIZE: make run fills the 320x240 panel, == rt --fixed rgb565be ($cmp)"
    else
        bad "resolution 320 240 on the pico: a $(dims "$OUT/sphere.png") frame, ${cmp:-differs}: $(grep '^ *panel' "$OUT/sphere-run.log")"
    fi
    # the summary's image line names both files make run wrote
    img=$(grep '^  image ' "$OUT/sphere-run.log")
    case $img in
    *" $OUT/sphere.png "*", and for the board $OUT/sphere.uf2.") ok "make run's image line names the PNG and the UF2:$(echo "$img" | tr -s ' ')" ;;
    *) bad "make run's image line does not name $OUT/sphere.png and $OUT/sphere.uf2: '$img'" ;;
    esac
    sum_run=$(cksum <"$OUT/sphere.uf2")
    make image $sv >"$OUT/sphere-image.log" 2>&1
    if [ -n "$elf" ] && [ "$elf" = "$(elf_of SCENE="$sph").elf" ] && cmp -s "$OUT/sphere.uf2" "${elf%.elf}.uf2" &&
       [ "$(cksum <"$OUT/sphere.uf2")" = "$sum_run" ] && ! grep -qE '^ *(CC|LD|UF2) ' "$OUT/sphere-image.log" &&
       grep -q 'panel: frame 320x240 centred on the 320x240 ST7789 panel' "$OUT/sphere-image.log"; then
        ok "make image hands over the UF2 of $elf, as make run ran it; its check line: $(grep -o 'panel: frame.*' "$OUT/sphere-image.log")"
    else
        bad "make run ran '$elf', make image: $(tail -3 "$OUT/sphere-image.log")"
    fi
else
    bad "make run of a 320x240 scene on the pico: $(tail -5 "$OUT/sphere-run.log")"
fi
# ... which does not fit the 240x240 module: a build error naming both
if make image $sv PANEL=240x240 >"$OUT/sphere-240.log" 2>&1; then
    bad "a 320x240 scene built for PANEL=240x240"
elif grep -q 'the frame is larger than the 240x240 panel (PANEL=240x240): 320x240 (the resolution of .*) against the panel.s 240x240' "$OUT/sphere-240.log"; then
    ok "PANEL=240x240: $(grep -o 'the frame is larger.*' "$OUT/sphere-240.log" | cut -c1-150)"
else
    bad "PANEL=240x240 and a 320x240 scene: $(tail -2 "$OUT/sphere-240.log")"
fi
# A 160x120 scene: centred on the panel, the rest of it black. The whole
# panel as the glass shows it (FIRMWARE.panel.stream), read here: 320x240,
# every pixel outside the frame at 80,60 zero, the frame there the one
# compared with the host (FIRMWARE.frame.stream)
small="$OUT/sphere-160x120.nff"
sphere "$small" 160 120
if make -s -j2 firmware BOARD=pico SCENE="$small" >"$OUT/small.build" 2>&1 &&
   make -s board-run BOARD=pico SCENE="$small" RUN_OUT="$OUT/small.png" RUN_RT="$RT" >"$OUT/small.report" 2>&1; then
    base=$(elf_of SCENE="$small")
    "$RT" "$small" -o "$OUT/small-host.png" --fixed --format rgb565be --threads 1 --quiet
    cmp=$("$RT" compare "$OUT/small.png" "$OUT/small-host.png" --max-error 0); same=$?
    panel=$(python3 -c '
import sys
p, f = open(sys.argv[1], "rb").read(), open(sys.argv[2], "rb").read()
def frame(s):
    assert s[:4] == b"RTF1" and s[9:10] == b"B"
    w, h = s[5] | s[6] << 8, s[7] | s[8] << 8
    return w, h, s[14:14 + 2 * w * h]
pw, ph, pp = frame(p)
fw, fh, fp = frame(f)
x0, y0 = (pw - fw) // 2, (ph - fh) // 2
border = sum(1 for y in range(ph) for x in range(pw)
             if not (x0 <= x < x0 + fw and y0 <= y < y0 + fh) and (pp[2 * (y * pw + x)] or pp[2 * (y * pw + x) + 1]))
inside = b"".join(pp[2 * (y * pw + x0):2 * (y * pw + x0 + fw)] for y in range(y0, y0 + fh))
lit = sum(1 for i in range(0, len(fp), 2) if fp[i] or fp[i + 1])
print(pw, ph, fw, fh, x0, y0, border, int(inside == fp), lit)
' "$base.panel.stream" "$base.frame.stream" 2>&1)
    set -- $panel
    if [ $same = 0 ] && [ "$1x$2" = 320x240 ] && [ "$3x$4" = 160x120 ] && [ "$5,$6" = 80,60 ] && [ "$7" = 0 ] && [ "$8" = 1 ] &&
       [ "${9:-0}" -gt 1000 ]; then
        ok "resolution 160 120: the frame (== host, $9 lit pixels) at 80,60 of the 320x240 panel, its other $((320 * 240 - 160 * 120)) pixels black"
    else
        bad "resolution 160 120 on the 320x240 panel: $panel; against the host: $cmp"
    fi
else
    bad "a 160x120 scene on the pico: $(tail -3 "$OUT/small.build" "$OUT/small.report")"
fi
summary board-pico-tests
