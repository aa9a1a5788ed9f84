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
#  - the clock tree (clock.c), on the host against a model of RCC and
#    FLASH_ACR that keeps RM0090's rules (tests/boards/stm32f4_clock_test.c): a
#    crystal that answers gives 168 MHz (84 on a Nucleo-64) from the HSE,
#    one that does not the same from the HSI, wait states that do not
#    stick or an RCC that reads 0 leave SYSCLK on the HSI and say why;
#    wait states before the switch, APB limits, HSEBYP and PLLCFGR
#    written only when allowed, PLLCFGR's reserved bits kept, the PLL's
#    input as fast as an exact set-up allows (2 MHz where one does), the
#    flash prefetch off on a revision A F405/F407 only, in every variant
#    (8, 12 and 25 MHz crystals, the Nucleo's bypass clock, none);
#  - a fault (a read of the CCM RAM, which QEMU does not model) ends the
#    run with status 4 and its report line, and run.sh says so;
#  - the Nucleo-64 variant (STM32=nucleo64: USART2, 512 KiB / 96 KiB)
#    gives the host's image over USART2 (QEMU's second serial port); a
#    crystal out of the HSE's range does not build;
#  - a scene's `resolution 320 240` is the frame when SIZE is not given,
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

# the clock tree on the host against a model of RCC and FLASH_ACR (what
# QEMU cannot check), in each variant: tests/boards/stm32f4_clock_test.c
for v in "" "-DSTM32_SYSCLK_MHZ=84 -DSTM32_HSE_BYPASS=1" "-DSTM32_HSE_MHZ=12" "-DSTM32_HSE_MHZ=25" "-DSTM32_HSE_MHZ=0"; do
    if cc -std=c11 -Wall -Wextra -Werror $v -Iplatform/stm32f4 tests/boards/stm32f4_clock_test.c -o "$OUT/clock-test" \
           2>"$OUT/clock.build" && "$OUT/clock-test" >"$OUT/clock.txt"; then
        ok "clock tree ($(head -1 "$OUT/clock.txt" | cut -d' ' -f2-)): $(tail -1 "$OUT/clock.txt" | cut -d' ' -f2-)"
    else
        bad "clock tree ${v:-(default)}: $(grep FAIL "$OUT/clock.txt" | head -2) $(tail -2 "$OUT/clock.build")"
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
