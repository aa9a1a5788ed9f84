#!/bin/sh
# Progressive display on the Pico (one core, 125 MHz, fixed, the
# ST7789 panel): the card at 320x240 in the core's interlaced passes
# (PROGRESSIVE=1, the default) and in scanline order (PROGRESSIVE=0).
# run.mjs times the panel's bytes at SPI0's clock (62.5 MHz), queued
# behind the render (rp2040js sends them at once); render_cycles leaves
# display output out, frame_cycles runs from the render's start to the
# panel's last byte, first_picture_cycles to pass 1's last byte.
#   sh bench/progressive.sh    (make bench keeps it as bench/progressive.md)
set -e
HZ=125000000
for p in 1 0; do
    vars="BOARD=pico SCENE=scenes/bench/card.nff SIZE=320x240 DEPTH=3 PROGRESSIVE=$p"
    make -s -j2 build/host/rt firmware $vars >/dev/null
    elf=$(make -s board-info $vars | sed -n 's/.*elf=\([^ ]*\).*/\1/p')
    echo "card (depth 3, 320x240, fixed), PROGRESSIVE=$p:"
    node platform/pico/run.mjs "$elf" "build/progressive-$p.png" build/host/rt $HZ >"build/progressive-$p.report"
    grep -E '^(render_cycles|eye_rays|shadow_rays|frame_cycles|first_picture_cycles|frame_ms|first_picture_us) ' \
        "build/progressive-$p.report" | sed 's/^/  /'
done
cmp -s build/progressive-1.png build/progressive-0.png && echo "the two panels: byte-identical" ||
    { echo "the two panels differ"; exit 1; }
f1=$(awk '$1 == "frame_cycles" { print $2 }' build/progressive-1.report)
f0=$(awk '$1 == "frame_cycles" { print $2 }' build/progressive-0.report)
r1=$(awk '$1 == "render_cycles" { print $2 }' build/progressive-1.report)
r0=$(awk '$1 == "render_cycles" { print $2 }' build/progressive-0.report)
fp=$(awk '$1 == "first_picture_cycles" { print $2 }' build/progressive-1.report)
awk -v f1="$f1" -v f0="$f0" -v r1="$r1" -v r0="$r0" -v fp="$fp" -v hz=$HZ 'BEGIN {
    printf "progressive / scanline: frame %.4fx, render %.4fx; first picture %.1f ms, frame %.1f ms (scanline %.1f ms) at %d MHz\n",
        f1 / f0, r1 / r0, fp / hz * 1000, f1 / hz * 1000, f0 / hz * 1000, hz / 1e6 }'
