#!/bin/sh
# Every board and backend (platform/*/board.mk, BOARD_BACKENDS) at 32x32,
# depth 5, on SPD balls-2, and in the fixed and float backends on the
# benchmark scenes of scenes/bench (the full matrix is make bench's):
#  - identity: the board's image is byte-identical to the host build of
#    the same backend (rt --fixed / --float) in the board's pixel format,
#    and the core's counters in its report equal rt --stats;
#  - budgets from the linked ELF: no heap; no soft-float helper in a fixed
#    build; no __aeabi_f*/__aeabi_d* in a hard-float float build (double
#    stays soft-float on a single-precision FPU); flash (code,
#    scene tables, data image) and RAM (data, bss, stack) within the
#    board's memory as its linker script declares it;
#  - from the run: the measured stack high-water mark inside the stack
#    and its guard intact (every core's on a board with two).
# The double backend (soft-float everywhere, the benchmark's cost of the
# exact reference) calls newlib's pow on the board and glibc's on the
# host: its identity is what the two libraries give on this scene.
RT=${1:-build/host/rt}
OUT=build/test-ports
. tests/boards/board-case.sh
SOFT_FLOAT='^(__aeabi_[fd](add|sub|mul|div|cmp.*|2.*)|__aeabi_[ui]?[lu]?2[fd]|__aeabi_[fd]2.*|__(add|sub|mul|div)[sd]f3|__float[a-z]*[sd]f|__fix[a-z]*[sd]f[a-z]*|__extendsfdf2|__truncdfsf2|__(eq|ne|lt|le|gt|ge|un)[sd]f2)$'
HEAP='^(malloc|free|calloc|realloc|_sbrk|sbrk|_malloc_r)$'

echo "ports: every board and backend against the host"
for b in $(ls platform/*/board.mk | cut -d/ -f2); do
    eval "$(make -s board-info AA=0 DITHER=0 BOARD=$b SCENE=scenes/spd/balls-2.nff SIZE=32x32 DEPTH=5)"
    for be in $backends; do
        # the benchmark scenes (planes, textures, the sky) in the backends
        # a user would run: fixed and float
        scenes=scenes/spd/balls-2.nff
        [ $be = double ] || scenes="$scenes scenes/bench/card.nff scenes/bench/picolib.nff scenes/bench/whitted.nff"
        for s in $scenes; do
            t0=$(date +%s)
            n=$b-$be-$(basename $s .nff)
            vars="BOARD=$b BACKEND=$be SCENE=$s SIZE=32x32 DEPTH=5 AA=0 DITHER=0"
            board_build $n $vars && board_run $n $vars || continue
            eval "$(make -s board-info $vars)"
            # a panel drawn in progressive passes (its report says so): the
            # host in the same order, for the same counts of the core's
            # caches (the image is the scanline order's either way:
            # tests/host/progressive-tests.sh)
            prog=$(awk '$1 == "progress_pass" { print "--progressive"; exit }' "$OUT/$n.report")
            ipp=$(report_val instructions_per_pixel "$OUT/$n.report")
            board_vs_host $n "$be ($format)" "$ipp instructions/pixel ($(($(date +%s) - t0)) s)" \
                $s --$be --size 32x32 --depth 5 --format $format $prog
            # budgets from the ELF
            syms=$(${cross}nm "$elf" | awk '{ print $NF }')
            found=$(echo "$syms" | grep -E "$HEAP" | tr '\n' ' ')
            if [ $be = fixed ]; then
                found="$found$(echo "$syms" | grep -E "$SOFT_FLOAT" | tr '\n' ' ')"
                what="heap or soft-float helper"
            elif [ $be = float ] && [ -n "$fpu" ]; then
                found="$found$(echo "$syms" | grep -E '^__aeabi_[fd]' | tr '\n' ' ')"
                what="heap or __aeabi_f*/__aeabi_d* (hard-float)"
            else
                what="heap"
            fi
            [ -z "$found" ] && ok "$n: links no $what" || bad "$n: links $what: $found"
            map="${elf%.elf}.map"
            eval "$(awk '/^Memory Configuration/ { m = 1 } m && $1 == "FLASH" { printf "flash=%d ", strtonum($3) }
                        m && $1 == "RAM" { printf "ram=%d ", strtonum($3) } /^Linker script/ { m = 0 }' "$map" 2>/dev/null ||
                   python3 -c '
import re, sys
t = open(sys.argv[1]).read().split("Linker script")[0]
for n in ("FLASH", "RAM"):
    m = re.search(r"^" + n + r"\s+0x[0-9a-f]+\s+(0x[0-9a-f]+)", t, re.M)
    print("%s=%d" % (n.lower(), int(m.group(1), 16)), end=" ")' "$map")"
            # flash: what is loaded; RAM: what is not, and what reset
            # copies there (.data; code and scene tables run from SRAM)
            eval "$(${cross}objdump -h "$elf" | awk -f tools/firmware/sections.awk | awk '
                $5 != "ram" { fl += $2 } $5 != "flash" { ram += $2 }
                END { printf "used_flash=%d used_ram=%d\n", fl, ram }')"
            if [ "${flash:-0}" -gt 0 ] && [ "$used_flash" -le "$flash" ] && [ "${ram:-0}" -gt 0 ] && [ "$used_ram" -le "$ram" ]; then
                ok "$n: flash $used_flash of $flash bytes, RAM $used_ram of $ram bytes (data, bss, stack, and what runs from RAM)"
            else
                bad "$n: flash $used_flash of ${flash:-?}, RAM $used_ram of ${ram:-?} bytes"
            fi
            hw=$(awk '$1 == "stack_high_water" { print $2 }' "$OUT/$n.report")
            sz=$(awk '$1 == "stack_size" { print $2 }' "$OUT/$n.report")
            guard=$(awk '$1 == "stack_guard_intact" { print $2 }' "$OUT/$n.report")
            hw1=$(awk '$1 == "core1_stack_high_water" { print $2 }' "$OUT/$n.report")
            if [ -n "$hw" ] && [ "$hw" -lt "$sz" ] && [ "${hw1:-0}" -lt "$sz" ] && [ "$guard" = 1 ]; then
                ok "$n: stack high-water $hw${hw1:+ (core 1: $hw1)} of $sz bytes, guard intact"
            else
                bad "$n: stack high-water ${hw:-?} of ${sz:-?} bytes, guard ${guard:-?}"
            fi
        done
    done
done
# A frame whose band buffer and stack do not fit the micro:bit's 16 KiB of
# RAM fails to link, saying what to lower; with a smaller band it builds.
if make -s -j2 firmware AA=0 DITHER=0 BOARD=microbit SCENE=scenes/spd/balls-1.nff SIZE=1024x16 >"$OUT/overflow.build" 2>&1; then
    bad "microbit at 1024x16 (12 KiB band buffer + 4 KiB stack) linked: RAM overflow not caught"
elif grep -q "RAM overflow: data, bss and stack exceed the board's RAM: lower make BAND_LINES=" "$OUT/overflow.build" &&
     make -s -j2 firmware AA=0 DITHER=0 BOARD=microbit SCENE=scenes/spd/balls-1.nff SIZE=1024x16 BAND_LINES=2 >>"$OUT/overflow.build" 2>&1; then
    ok "microbit at 1024x16: $(grep -o 'RAM overflow.*' "$OUT/overflow.build" | head -1); BAND_LINES=2 links"
else
    bad "microbit at 1024x16: no clear RAM overflow message, or BAND_LINES=2 failed: $(tail -2 "$OUT/overflow.build")"
fi
summary ports
