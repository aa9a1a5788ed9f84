#!/bin/sh
# The STM32F4 (platform/stm32f4/, QEMU's netduinoplus2): beyond what
# tests/boards/ports-tests.sh checks on every board (the host's image byte for
# byte in each backend, counters, budgets, stack),
#  - the image is the chip's: the .bin starts with the vector table (SP in
#    SRAM, reset in flash, Thumb), the .hex carries the same bytes at
#    0x08000000, and the ELF has no BKPT (semihosting);
#  - under QEMU, where RCC reads 0 and CYCCNT stays 0, the run completes
#    at the reset clock and says so (sysclk_hz 16000000, a clock line
#    naming the PLL), counts instructions with TIM2 and names it, gives
#    no cycle count, prints its progress, and ends on exit_status 0;
#  - TIM2's count of the render equals bench/cycles.py's count of the
#    same run within 0.01% (the difference: the counter reads);
#  - the clock tree (clock.c), on the host against a model of RCC, PWR
#    and FLASH_ACR that keeps the chips' rules
#    (tests/boards/stm32f4_clock_test.c), built with each variant's own
#    flags: an HSE that answers gives the variant's SYSCLK from it, one
#    that does not (or the wrong HSE=crystal|bypass) the same from the
#    HSI, wait states that do not stick or an RCC that reads 0 leave
#    SYSCLK on the HSI and say why; the voltage scale, wait states
#    before the switch, APB limits, HSEBYP and PLLCFGR written only when
#    allowed, PLLCFGR's reserved bits kept, the PLL's input as fast as an
#    exact set-up allows, the flash prefetch off on a revision A
#    F405/F407 only, and the console's BRR and which rates fit, in every
#    variant of board.mk's table and a few other choices (8, 12 and 25
#    MHz crystals, none, bypass, 921600 and 2000000 baud); the 25 MHz
#    crystal's dividers on the F411 and F401;
#  - BAUD=921600 and 2000000 taken by every variant, a rate the divider
#    misses by more than 2% (or cannot make) refused by make, naming
#    BAUD, the clock and the error; a bad STM32, HSE, STM32_LED_ON or
#    STM32_USART (or FLASHER) refused naming what it may be; make flash
#    on a BlackPill through dfu-util;
#  - the BlackPill variants under QEMU: the host's image byte for byte,
#    the link within the chip's flash and RAM (the F401's 256 KiB / 64
#    KiB), uart_bytes equal to the stream's bytes before that line, and
#    from QEMU's log of register writes, the voltage scale, the BRR, and
#    the active-low LED on PC13 off before the pin drives it, lit after
#    a good run;
#  - a fault (a read of the CCM RAM, which QEMU does not model) ends the
#    run with status 4 and its report line, and run.sh says so;
#  - the Nucleo-64 variant (STM32=nucleo64: USART2, 512 KiB / 96 KiB)
#    gives the host's image over USART2 (QEMU's second serial port); a
#    crystal out of the HSE's range does not build;
#  - a scene's `resolution 320 240` is the frame when SIZE is not given,
#    and make run's report gives its time on the wire at 115200 baud,
#    and make image with make run's variables hands over the ELF make run
#    ran (the board's AA=3 in both).
# One sample a pixel (AA=0) in the other cases.
RT=${1:-build/host/rt}
OUT=build/test-stm32f4
mkdir -p "$OUT"
. tests/lib/check.sh
vars="BOARD=stm32f4 SCENE=scenes/spd/balls-2.nff SIZE=32x32 DEPTH=5"

echo "stm32f4: the image for the chip, and its run under QEMU"
if ! make -s -j2 firmware AA=0 $vars >"$OUT/build.log" 2>&1; then
    bad "firmware build failed: $(tail -3 "$OUT/build.log")"
    summary board-stm32f4
    exit 1
fi
eval "$(make -s board-info AA=0 $vars)"
bin="${elf%.elf}.bin" hex="${elf%.elf}.hex"
# the vector table: initial SP and reset handler, little-endian words
set -- $(od -An -tx4 -N8 "$bin")
sp=$((0x$1)) reset=$((0x$2))
if [ $sp -gt $((0x20000000)) ] && [ $sp -le $((0x20020000)) ] && [ $((reset & 1)) = 1 ] &&
   [ $reset -gt $((0x08000000)) ] && [ $reset -lt $((0x08000000 + $(wc -c <"$bin"))) ]; then
    ok ".bin starts with the vector table: SP 0x$1 in SRAM, reset 0x$2 in the image, Thumb"
else
    bad ".bin's first words are not a vector table: SP 0x$1, reset 0x$2"
fi
${cross}objcopy -I ihex -O binary "$hex" "$OUT/from-hex.bin"
if cmp -s "$OUT/from-hex.bin" "$bin" && grep -q '^:020000040800F2' "$hex"; then
    ok ".hex holds the .bin's $(wc -c <"$bin") bytes at 0x08000000"
else
    bad ".hex and .bin differ, or the .hex is not at 0x08000000"
fi
n=$(${cross}objdump -d "$elf" | grep -c 'bkpt')
[ "$n" = 0 ] && ok "no bkpt in the image: no semihosting" || bad "$n bkpt instructions in the image"

if make -s board-run AA=0 $vars RUN_OUT="$OUT/board.png" RUN_RT="$RT" >"$OUT/report.txt" 2>"$OUT/run.err"; then
    ok "run ends on its exit_status line ($(grep -c progress_rows "$OUT/report.txt") progress lines)"
else
    bad "run failed: $(tail -3 "$OUT/run.err")"
fi
r="$OUT/report.txt"
last=$(grep -v '^board render time\|^QEMU wall time' "$r" | tail -1)
[ "$last" = "exit_status 0" ] && ok "the report's last line: exit_status 0" || bad "the report's last line: $last"
if grep -qx 'sysclk_hz 16000000' "$r" && grep -q '^clock: the PLL never reported lock' "$r"; then
    ok "QEMU's RCC never locks the PLL: reported, render at 16 MHz ($(grep -c . "$r") report lines)"
else
    bad "no sysclk_hz 16000000 and clock line: $(grep -E '^(sysclk|clock)' "$r")"
fi
if grep -q '^counter: TIM2, instructions' "$r" && grep -q '^render_instructions ' "$r" && ! grep -q '^render_cycles' "$r"; then
    ok "CYCCNT reads 0: TIM2 counts instructions, named; no cycle count reported"
else
    bad "counter lines: $(grep -E '^(counter|render_)' "$r")"
fi
first=$(awk '$1 == "progress_rows" { print $2; exit }' "$r")
final=$(awk '$1 == "progress_rows" { v = $2 } END { print v }' "$r")
[ "$first" = 4 ] && [ "$final" = 32 ] && ok "progress: first band (4 rows) to the last (32)" ||
    bad "progress_rows from ${first:-?} to ${final:-?}"

# TIM2 against the trace: the render's instructions, display sink apart
fw=$(awk '$1 == "render_instructions" { print $2 }' "$r")
python3 bench/cycles.py "$elf" --machine stm32f4 --from-symbol rt_render --exclude-symbol stream_begin \
    --exclude-symbol stream_flush --top 0 --json "$OUT/cycles.json" >"$OUT/cycles.txt" 2>&1
traced=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["instructions"])' "$OUT/cycles.json" 2>/dev/null)
if [ -n "$fw" ] && [ -n "$traced" ] && awk -v a="$fw" -v b="$traced" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= a / 10000) }'; then
    ok "TIM2's render_instructions $fw, the trace's $traced"
else
    bad "TIM2's render_instructions ${fw:-?}, the trace's ${traced:-?}: $(tail -2 "$OUT/cycles.txt")"
fi

# a fault: status 4 and its line, not a hang
fault="$OUT/fault.elf"
if ${cross}gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard -O2 -ffreestanding -nostdlib -nostartfiles \
       -DBOARD_COUNTERS_PROBED=1 -DBOARD_LED=1 -DBOARD_CYCLES=1 -Iinclude -Iplatform -Iapp/firmware \
       -T platform/stm32f4/link.ld -Lapp/firmware -Wl,--defsym=STM32_FLASH=1024K,--defsym=STM32_RAM=128K \
       tests/boards/stm32f4_fault.c platform/arch/cortex-m/startup.c platform/stm32f4/board.c platform/stm32f4/clock.c \
       app/firmware/report.c \
       -lgcc -o "$fault" 2>"$OUT/fault.build"; then
    QEMU="qemu-system-arm -M netduinoplus2" RUN_END=report timeout 120 sh tools/firmware/run.sh "$fault" \
        "$OUT/fault.png" "$RT" >"$OUT/fault.report" 2>"$OUT/fault.err"
    st=$?
    if [ $st = 4 ] && grep -aq 'fault: abort' "${fault%.elf}.stream" && grep -aq 'exit_status 4' "${fault%.elf}.stream"; then
        ok "a BusFault (CCM read) ends the run: status 4, 'fault: abort', exit_status 4"
    else
        bad "the faulting image: status $st, $(tail -2 "$OUT/fault.err")"
    fi
else
    bad "the faulting image did not build: $(tail -3 "$OUT/fault.build")"
fi

# the clock tree on the host against a model of RCC, PWR and FLASH_ACR
# (what QEMU cannot check), built with the flags each variant's firmware
# gets (make stm32-clock-flags): every row of board.mk's table, then
# other crystals, none, a BlackPill's 8 MHz crystal, a clock signal
# (HSE=bypass) and the faster rates: tests/boards/stm32f4_clock_test.c
variants=$(make -s stm32-variants BOARD=stm32f4)
for v in $variants "STM32=f405 HSE_MHZ=12" "STM32=f405 HSE_MHZ=25" "STM32=f405 HSE_MHZ=0" \
         "STM32=blackpill-f411 HSE_MHZ=8" "STM32=blackpill-f411 HSE=bypass BAUD=921600" \
         "STM32=blackpill-f401 BAUD=2000000" "STM32=blackpill-f401 STM32_USART=2 BAUD=921600"; do
    case $v in *=*) ;; *) v="STM32=$v" ;; esac
    if flags=$(make -s stm32-clock-flags BOARD=stm32f4 $v 2>"$OUT/clock.build") &&
       cc -std=c11 -Wall -Wextra -Werror $flags -Iplatform/stm32f4 tests/boards/stm32f4_clock_test.c -o "$OUT/clock-test" \
           2>>"$OUT/clock.build" && "$OUT/clock-test" >"$OUT/clock.txt"; then
        ok "clock tree, $v ($(head -1 "$OUT/clock.txt" | cut -d' ' -f2-)): $(tail -1 "$OUT/clock.txt" | cut -d' ' -f2-)"
    else
        bad "clock tree, $v: $(grep FAIL "$OUT/clock.txt" | head -2) $(tail -2 "$OUT/clock.build")"
    fi
done
# the 25 MHz crystal of the BlackPills, as the issue asks: the PLL's
# dividers and the console's BRR the clock test printed
for v in blackpill-f411 blackpill-f401; do
    flags=$(make -s stm32-clock-flags BOARD=stm32f4 STM32=$v)
    cc -std=c11 $flags -Iplatform/stm32f4 tests/boards/stm32f4_clock_test.c -o "$OUT/clock-test" 2>/dev/null &&
        "$OUT/clock-test" >"$OUT/clock-$v.txt"
done
pll411=$(grep -o 'PLL from the HSE: M [0-9]*, N [0-9]*, P [0-9]*, Q [0-9]*' "$OUT/clock-blackpill-f411.txt")
pll401=$(grep -o 'PLL from the HSE: M [0-9]*, N [0-9]*, P [0-9]*, Q [0-9]*' "$OUT/clock-blackpill-f401.txt")
# 25 / 13 x 208 / 4 = 100 MHz (VCO 400 MHz); 25 / 25 x 336 / 4 = 84 MHz
[ "$pll411" = "PLL from the HSE: M 13, N 208, P 4, Q 9" ] && [ "$pll401" = "PLL from the HSE: M 25, N 336, P 4, Q 7" ] &&
    grep -q 'ok    BAUD 115200 from USART1.s 100 MHz: BRR 868 ' "$OUT/clock-blackpill-f411.txt" &&
    grep -q 'ok    BAUD 115200 from USART1.s 84 MHz: BRR 729 ' "$OUT/clock-blackpill-f401.txt" &&
    ok "25 MHz crystal: F411 $pll411 (100 MHz), BRR 868; F401 $pll401 (84 MHz), BRR 729" ||
    bad "25 MHz crystal: F411 '$pll411', F401 '$pll401'"

# BAUD: checked against the console's divider at the variant's clock
# when make reads the variables; the rates common adapters take fit
# every variant, on either USART
for v in $variants; do
    for u in 1 2; do
        for b in 921600 2000000; do
            make -s board-info BOARD=stm32f4 STM32=$v STM32_USART=$u BAUD=$b >/dev/null 2>>"$OUT/baud.txt" ||
                echo "STM32=$v STM32_USART=$u BAUD=$b refused" >>"$OUT/baud.txt"
        done
    done
done
[ ! -s "$OUT/baud.txt" ] && ok "BAUD=921600 and 2000000 taken by every variant ($(echo $variants)) on USART1 and 2" ||
    bad "BAUD: $(head -2 "$OUT/baud.txt")"
refuse() { # refuse VARS... -- WORDS: make refuses, naming each word
    _v= _w=
    while [ "$1" != -- ]; do _v="$_v $1"; shift; done
    shift
    if msg=$(make -s board-info BOARD=stm32f4 $_v 2>&1); then
        bad "${_v# }: taken"
        return
    fi
    for _w in "$@"; do
        case $msg in *"$_w"*) ;; *) bad "$_v: the message does not say '$_w': $msg"; return ;; esac
    done
    msg=${msg#*\*\*\* }
    ok "${_v# } refused: ${msg%.  Stop.}"
}
refuse STM32=blackpill-f401 BAUD=4800000 -- BAUD=4800000 '84 MHz' '2.78%'
refuse STM32=blackpill-f411 BAUD=7000000 -- BAUD=7000000 '100 MHz' 6250000
refuse STM32=blackpill-f411 BAUD=1200 -- BAUD=1200 '100 MHz'
refuse STM32=blackpill-f411 BAUD=fast -- BAUD=fast 'whole number'
refuse STM32=blackpill -- STM32=blackpill blackpill-f411 blackpill-f401
refuse STM32=blackpill-f411 HSE=xtal -- HSE=xtal crystal bypass
refuse STM32=blackpill-f411 STM32_LED_ON=on -- STM32_LED_ON=on high low
refuse STM32=blackpill-f411 STM32_USART=3 -- STM32_USART=3 PA9
refuse FLASHER=jlink -- FLASHER=jlink openocd st-flash dfu-util
# a BlackPill has no ST-LINK: make flash goes through the ROM's DFU
# bootloader, the .bin at the start of flash (make -n: nothing run)
cmd=$(make -n flash $vars AA=0 STM32=blackpill-f411 2>&1 | tail -1)
case $cmd in
"dfu-util -a 0 -s 0x08000000:leave -D "*blackpill-f411/fixed.bin) ok "STM32=blackpill-f411: make flash runs $cmd" ;;
*) bad "STM32=blackpill-f411: make flash runs '$cmd'" ;;
esac

# The BlackPills under QEMU (its F405 has room for either map): the
# host's image byte for byte over USART1, the link within the chip's
# flash and RAM, the bytes sent as the report counts them (uart_bytes:
# the stream's bytes before that line), and, from QEMU's log of every
# register write, what the chip would be told: VOS for the clock
# (scale 1 on the F411, 2 on the F401), BRR for 115200 baud at the 16
# MHz QEMU leaves it on, and the LED on PC13 off (the pin high) before
# it drives it, lit (the pin low) at the end of a good run
for v in blackpill-f411:512K:128K:0xc000 blackpill-f401:256K:64K:0x8000; do
    name=${v%%:*} rest=${v#*:}
    flash=${rest%%:*} rest=${rest#*:} ram=${rest%%:*} vos=${rest#*:}
    bvars="$vars STM32=$name"
    if ! make -s -j2 firmware AA=0 $bvars >"$OUT/$name.build" 2>&1; then
        bad "STM32=$name does not build: $(tail -3 "$OUT/$name.build")"
        continue
    fi
    eval "$(make -s board-info AA=0 $bvars)"
    mem=$(awk '/^Memory Configuration/ { m = 1 } m && ($1 == "FLASH" || $1 == "RAM") { print $1, $3 } /^Linker script/ { m = 0 }' \
              "${elf%.elf}.map" | while read -r n len; do printf '%s%d ' $n $((len)); done)
    want="FLASH$((${flash%K} * 1024)) RAM$((${ram%K} * 1024)) "
    [ -f "$OUT/host.png" ] || "$RT" scenes/spd/balls-2.nff -o "$OUT/host.png" --fixed --size 32x32 --depth 5 --threads 1 --quiet
    rm -f "$OUT/$name.png"
    if make -s board-run AA=0 $bvars RUN_OUT="$OUT/$name.png" RUN_RT="$RT" \
           BOARD_QEMU="qemu-system-arm -M netduinoplus2 -trace memory_region_ops_write -D $OUT/$name.mmio" \
           >"$OUT/$name.report" 2>&1 &&
       cmp=$("$RT" compare "$OUT/$name.png" "$OUT/host.png" --max-error 0) && [ "$mem" = "$want" ]; then
        ok "STM32=$name: the host's image byte for byte ($cmp); $mem"
    else
        bad "STM32=$name: $(tail -2 "$OUT/$name.report") ${cmp:-}; $mem (want $want)"
    fi
    sent=$(awk '$1 == "uart_bytes" { print $2 }' "$OUT/$name.report")
    at=$(python3 -c 'import sys; d = open(sys.argv[1], "rb").read(); print(d.find(b"uart_bytes ") - 3)' "${elf%.elf}.stream")
    [ -n "$sent" ] && [ "$sent" = "$at" ] && grep -qx 'uart_baud 115200' "$OUT/$name.report" &&
        ok "STM32=$name: uart_bytes $sent, the stream's bytes before that line; uart_baud 115200" ||
        bad "STM32=$name: uart_bytes ${sent:-?}, the stream has $at before it"
    # (writes as QEMU logs them: addr, value; PWR_CR, USART1_BRR, GPIOC's MODER and BSRR)
    awk '/memory_region_ops_write/ { for (i = 1; i < NF; i++) { if ($i == "addr") a = $(i + 1); if ($i == "value") v = $(i + 1) }
         if (a == "0x40007000" || a == "0x40011008" || a == "0x40020800" || a == "0x40020818") print a, v }' \
        "$OUT/$name.mmio" >"$OUT/$name.writes"
    pwr=$(awk '$1 == "0x40007000" { v = $2 } END { print v }' "$OUT/$name.writes")
    brr=$(awk '$1 == "0x40011008" { v = $2 } END { print v }' "$OUT/$name.writes")
    led=$(awk '$1 == "0x40020818" || ($1 == "0x40020800" && !m) { if ($1 == "0x40020800") m = 1; printf "%s%s", s, ($1 == "0x40020800" ? "moder" : $2); s = " " }' "$OUT/$name.writes")
    last=$(awk '$1 == "0x40020818" { v = $2 } END { print v }' "$OUT/$name.writes")
    # 16 MHz / 115200 = 138.9: BRR 139; BSRR bit 13 sets PC13, bit 29 resets it
    if [ $((pwr & 0xc000)) = $((vos)) ] && [ $((brr)) = 139 ] && [ "${led%% *}" = 0x2000 ] &&
       [ "$(echo "$led" | cut -d' ' -f2)" = moder ] && [ "$last" = 0x20000000 ]; then
        ok "STM32=$name, the writes QEMU logged: PWR_CR $pwr (VOS $(( (pwr >> 14) & 3 ))), BRR $((brr)), LED off before the pin drives it, lit (PC13 low) at the end"
    else
        bad "STM32=$name, the writes: PWR_CR ${pwr:-?} (want VOS bits $vos), BRR ${brr:-?}, LED: ${led:-?} ... last ${last:-?}"
    fi
done

# the Nucleo-64 variant and a crystal that does not divide
# (QEMU's second serial port is USART2: nothing would arrive from USART1)
nvars="$vars STM32=nucleo64"
if make -s -j2 firmware AA=0 $nvars >"$OUT/nucleo.build" 2>&1; then
    eval "$(make -s board-info AA=0 $nvars)"
    mem=$(awk '/^Memory Configuration/ { m = 1 } m && ($1 == "FLASH" || $1 == "RAM") { print $1, $3 } /^Linker script/ { m = 0 }' \
              "${elf%.elf}.map" | while read -r name len; do printf '%s%d ' $name $((len)); done)
    "$RT" scenes/spd/balls-2.nff -o "$OUT/host.png" --fixed --size 32x32 --depth 5 --threads 1 --quiet
    if make -s board-run AA=0 $nvars RUN_OUT="$OUT/nucleo.png" RUN_RT="$RT" >"$OUT/nucleo.report" 2>&1 &&
       cmp=$("$RT" compare "$OUT/nucleo.png" "$OUT/host.png" --max-error 0) && [ "$mem" = "FLASH524288 RAM98304 " ]; then
        ok "STM32=nucleo64: over USART2, the host's image byte for byte; $mem"
    else
        bad "STM32=nucleo64: $(tail -2 "$OUT/nucleo.report") $cmp; $mem"
    fi
else
    bad "STM32=nucleo64 does not build: $(tail -3 "$OUT/nucleo.build")"
fi
if make -s firmware AA=0 $vars HSE_MHZ=3 >"$OUT/hse.build" 2>&1; then
    bad "HSE_MHZ=3 built"
else
    ok "HSE_MHZ=3 refused: $(grep -o 'HSE_MHZ=3.*' "$OUT/hse.build" | head -1)"
fi

# The scene's resolution is the frame (no SIZE given): a 320x240 scene
# (one sphere: cheap) renders 320x240 with the board's sampling (AA=3 for
# every goal), equal to rt's fixed --aa 3 byte for byte; and make image
# with the same variables hands over the image of the ELF make run ran,
# rebuilding nothing
sph="$OUT/sphere-320x240.nff"
printf 'v\nfrom 0 -6 1\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 320 240\nl -3 -6 5\nf 0.9 0.3 0.2 0.8 0.2 10 0 1\ns 0 0 0 1\n' >"$sph"
sv="BOARD=stm32f4 SCENE=$sph RUN_OUT=$OUT/sphere.png RUN_REF=$OUT/sphere-ref.png RUN_AREA=$OUT/sphere-area.png RUN_RT=$RT"
rm -f "$OUT/sphere.png" "$OUT/sphere.bin"
if make run $sv >"$OUT/sphere-run.log" 2>&1; then
    elf=$(sed -n 's/^ *RUN *\([^ ]*\.elf\) on .*/\1/p' "$OUT/sphere-run.log")
    dims=$(python3 -c 'import struct, sys; print("%dx%d" % struct.unpack(">II", open(sys.argv[1], "rb").read()[16:24]))' "$OUT/sphere.png")
    "$RT" "$sph" -o "$OUT/sphere-host.png" --fixed --aa 3 --threads 1 --quiet
    if [ "$dims" = 320x240 ] && cmp=$("$RT" compare "$OUT/sphere.png" "$OUT/sphere-host.png" --max-error 0); then
        ok "resolution 320 240, no SIZE: make run renders $dims, AA=3 by default, == rt --fixed --aa 3 ($cmp)"
    else
        bad "resolution 320 240: the board's frame is ${dims:-?}, against rt --fixed --aa 3: ${cmp:-?}"
    fi
    # the time on the wire: the frame's records (9 bytes of header, 60
    # bands of 4 lines each with 9 bytes of framing, 230,400 of pixels, 5
    # at the end) and the report lines, 10 bits a byte at 115200 baud
    sent=$(sed -n 's/^ *uart_bytes \([0-9]*\)$/\1/p' "$OUT/sphere-run.log")
    frame=$((9 + 60 * 9 + 320 * 240 * 3 + 5))
    wire=$(awk -v n="${sent:-0}" 'BEGIN { printf "%.3g s", n * 10 / 115200 }')
    if [ -n "$sent" ] && [ "$sent" -gt $frame ] && [ "$sent" -lt $((frame + 2000)) ] &&
       grep -q "^  on the wire *$wire at 115200 baud" "$OUT/sphere-run.log" &&
       grep -q 'from reset to the last byte, render and wire together\.$' "$OUT/sphere-run.log"; then
        ok "make run's report: a 320x240 RGB888 frame is $wire on the wire at 115200 baud ($sent bytes: $frame of frame records, the rest report lines), render and wire together"
    else
        bad "make run's wire time: uart_bytes ${sent:-?} (frame $frame), want $wire: $(grep -A2 'on the wire' "$OUT/sphere-run.log")"
    fi
    sum_run=$(cksum <"$OUT/sphere.bin")
    make image $sv >"$OUT/sphere-image.log" 2>&1
    info_elf=$(make -s board-info $sv | sed -n 's/.* elf=\([^ ]*\) .*/\1/p')
    if [ -n "$elf" ] && [ "$elf" = "$info_elf" ] && cmp -s "$OUT/sphere.bin" "${elf%.elf}.bin" &&
       [ "$(cksum <"$OUT/sphere.bin")" = "$sum_run" ] && ! grep -qE '^ *(CC|LD) ' "$OUT/sphere-image.log"; then
        ok "make image (the same variables) hands over $elf's image, as make run ran it; nothing rebuilt"
    else
        bad "make run ran '$elf', make image's is '$info_elf': $(tail -3 "$OUT/sphere-image.log")"
    fi
else
    bad "make run of a 320x240 scene: $(tail -5 "$OUT/sphere-run.log")"
fi
summary board-stm32f4
