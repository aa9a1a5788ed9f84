#!/bin/sh
# Firmware built for its scene (SPECIALISE=1, the default) against the
# generic firmware (SPECIALISE=0): the benchmark scenes at 320x240, one
# sample a pixel, one core, textures filtered (the default) and
# point-sampled, and the default scene as make run renders it. Per pair:
#  - instructions a pixel inside the render (QEMU -icount shift=0; the
#    pico's cycles counted by SysTick under rp2040js);
#  - code bytes (.text), make size's stack bound and the measured
#    high-water mark, the build's wall time from a clean build folder
#    (make -j2 firmware, core and scene tables included, on the machine
#    make bench runs on);
#  - the specialised image's PSNR against the exact (double) build at the
#    same samples, in the board's format (make run's reference), and
#    whether the two images are the same.
#   sh bench/specialise-bench.sh   (make bench keeps it as bench/specialise.md)
set -e
RT=build/host/rt
OUT=build/bench-specialise
mkdir -p "$OUT"
make -s build/host/rt
row() { printf '%-10s %-6s %-9s %-8s %-9s %9s %9s %6s %15s %13s %13s %11s %9s %s\n' "$@"; }
row board backend scene texture figure generic special ratio "code B" "stack bound" "stack used" "build s" "exact dB" image
# case BOARD BACKEND SCENE DEPTH TEXTURE_FILTER [VARS...]
case_() {
    board=$1 backend=$2 scene=$3 depth=$4 tf=$5
    shift 5
    key=instructions_per_pixel
    [ "$board" = pico ] && key=cycles_per_pixel
    for sp in 0 1; do
        v="BOARD=$board BACKEND=$backend SCENE=scenes/$scene.nff DEPTH=$depth TEXTURE_FILTER=$tf SPECIALISE=$sp $*"
        rm -rf "$(make -s print-fwdir $v)"
        t0=$(date +%s.%N)
        make -s -j2 firmware $v >"$OUT/build.log" 2>&1 || { tail -5 "$OUT/build.log"; exit 1; }
        eval "build$sp=\$(awk -v a=$t0 -v b=$(date +%s.%N) 'BEGIN { printf \"%.1f\", b - a }')"
        make -s run $v RUN_OUT="$OUT/$sp.png" RUN_REF="$OUT/ref.png" RUN_AREA="$OUT/area.png" >"$OUT/$sp.run" 2>&1 ||
            { tail -5 "$OUT/$sp.run"; exit 1; }
        cp "$(make -s print-fwdir $v)/report-$backend.txt" "$OUT/$sp.report"
        elf=$(make -s board-info $v | sed -n 's/.* elf=\([^ ]*\) .*/\1/p')
        eval "fig$sp=\$(awk -v k=$key '\$1 == k { print \$2 }' $OUT/$sp.report)"
        eval "code$sp=\$(arm-none-eabi-size $elf | awk 'NR == 2 { print \$1 }')"
        eval "used$sp=\$(awk '\$1 == \"stack_high_water\" { print \$2 }' $OUT/$sp.report)"
        eval "bound$sp=\$(make -s size $v | awk '/^worst-case stack/ { print \$(NF - 1) }')"
        exact=$("$RT" compare "$OUT/$sp.png" "$OUT/ref.png" | awk '{ print $2 }')
    done
    same=$("$RT" compare "$OUT/1.png" "$OUT/0.png" --max-error 0 >/dev/null && echo same || echo differs)
    row "$board" "$backend" "$(basename "$scene")" "$([ "$tf" = 1 ] && echo filtered || echo point)" \
        "$([ "$board" = pico ] && echo cycles/px || echo instr/px)" "$fig0" "$fig1" \
        "$(awk -v a="$fig1" -v b="$fig0" 'BEGIN { printf "%.3f", a / b }')" "$code0 -> $code1" \
        "$bound0 -> $bound1" "$used0 -> $used1" "$build0 -> $build1" "$exact" "$same"
}
for bb in mps2-an386:float mps2-an385:fixed pico:fixed; do
    for sd in card:3 picolib:6; do
        for tf in 1 0; do
            case_ ${bb%:*} ${bb#*:} bench/${sd%:*} ${sd#*:} $tf SIZE=320x240 AA=0
        done
    done
done
# the default scene, as make run renders it (128x128, the board's AA)
case_ mps2-an385 fixed showpiece 5 1
