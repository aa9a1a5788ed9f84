#!/bin/sh
# The Pico's frame, as a Display Pack user sees it: the card scene (or
# SCENES, below) at 320x240 (fixed, 125 MHz, the ST7789 panel), on one
# core (CORES=1) and both, in scanline order (PROGRESSIVE=0) and in
# progressive display's passes (PROGRESSIVE=1, the panel's default).
# run.mjs times the panel's bytes at SPI0's clock (62.5 MHz), queued
# behind the render (rp2040js sends them at once): frame_cycles runs from
# the render's start to the panel's last byte, first_picture_cycles to
# pass 1's last byte (the whole picture on the panel). Per row: the
# frame's time, the first picture's, the two-core frame as a share of the
# one-core frame in the same order (and the critical path of the firmware's
# own counts: the later core's render plus waits), progressive over
# scanline, and whether the finished panel is the one-core scanline one.
#   sh bench/pico-frames.sh    (make bench keeps it as bench/pico-frames.md)
set -e
HZ=125000000
SIZE=${SIZE:-320x240} # (another size for a quick look: SIZE=40x32 sh bench/pico-frames.sh)
# The card scene, the one the README times, by default: rp2040js emulates
# 2.5 to 5 M cycles a second, so the four frames of one scene take 4 to 8
# minutes, the showpiece's (46 s of the Pico's time each) an hour.
# SCENES="card:3 picolib:6 whitted:5 showpiece:5" measures them all.
SCENES=${SCENES:-card:3}
OUT=build/bench-pico-frames
mkdir -p "$OUT"
make -s build/host/rt
val() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }
row() { printf '%-9s %-5s %-11s %14s %10s %13s %13s %11s %s\n' "$@"; }
row scene cores order frame_cycles frame_ms first_pic_ms "share (cp)" "prog/scan" panel
for sd in $SCENES; do
    s=${sd%:*} d=${sd#*:}
    scene=scenes/bench/$s.nff
    [ "$s" = showpiece ] && scene=scenes/showpiece.nff
    for c in 1 2; do
        for p in 0 1; do
            vars="BOARD=pico SCENE=$scene SIZE=$SIZE DEPTH=$d CORES=$c PROGRESSIVE=$p"
            make -s -j2 firmware $vars >"$OUT/build.log" 2>&1 || { tail -5 "$OUT/build.log"; exit 1; }
            elf=$(make -s board-info $vars | sed -n 's/.*elf=\([^ ]*\).*/\1/p')
            r=$OUT/$s-$c-$p
            node tools/emu/pico/run.mjs "$elf" "$r.png" build/host/rt $HZ >"$r.report" 2>&1 || { tail -5 "$r.report"; exit 1; }
            f=$(val frame_cycles "$r.report") fp=$(val first_picture_cycles "$r.report") cp=$(val critical_path_cycles "$r.report")
            eval "f_${c}_$p=$f"
            one=$(eval echo \$f_1_$p)
            share=- ratio=-
            [ "$c" = 2 ] && share=$(awk -v a="$f" -v b="$one" -v cp="$cp" -v o="$(val render_cycles "$OUT/$s-1-$p.report")" \
                'BEGIN { printf "%.4f (%.4f)", a / b, cp / o }')
            [ "$p" = 1 ] && ratio=$(awk -v a="$f" -v b="$(eval echo \$f_${c}_0)" 'BEGIN { printf "%.4f", a / b }')
            same=$(cmp -s "$r.png" "$OUT/$s-1-0.png" && echo identical || echo DIFFERS)
            row "$s" "$c" "$([ "$p" = 1 ] && echo progressive || echo scanline)" "$f" \
                "$(awk -v f="$f" -v hz=$HZ 'BEGIN { printf "%.1f", f / hz * 1000 }')" \
                "$([ -n "$fp" ] && awk -v f="$fp" -v hz=$HZ 'BEGIN { printf "%.1f", f / hz * 1000 }' || echo -)" \
                "$share" "$ratio" "$same"
        done
    done
done
