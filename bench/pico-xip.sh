#!/bin/sh
# The Pico's flash reads in the render, through run.mjs's model of the XIP
# cache (16 KiB, two ways, 8-byte lines, LRU assumed): the benchmark
# scenes at 320x240, as the image runs them (code and scene tables in
# SRAM) and as it would with them in flash, where reset loads them from.
# Misses are priced at boot2's 03h reads at clk_sys / 4 (96 flash clocks,
# 384 cycles a miss): an estimate, the emulator times no flash. On core 0
# alone (CORES=1): the flash reads of one core.
#   sh bench/pico-xip.sh    (make bench keeps it as bench/pico-xip.md)
set -e
for sd in card:3 picolib:6 whitted:5; do
    s=${sd%:*} d=${sd#*:}
    vars="BOARD=pico SCENE=scenes/bench/$s.nff SIZE=320x240 DEPTH=$d CORES=1 PROGRESSIVE=0"
    make -s -j2 build/host/rt firmware $vars >/dev/null
    elf=$(make -s board-info $vars | sed -n 's/.*elf=\([^ ]*\).*/\1/p')
    echo "$s (depth $d, 320x240, fixed):"
    node tools/emu/pico/run.mjs --xip-model "$elf" "build/pico-xip-$s.png" build/host/rt |
        grep -E '^(cycles_per_pixel|xip_)|^XIP cache model' | sed 's/^/  /'
done
