#!/bin/sh
# Firmware built for its scene (SPECIALISE=1) against the generic
# firmware: the benchmark scenes at 320x240, one sample a pixel, one core,
# textures filtered (the default) and point-sampled. Instructions a pixel
# inside the render (QEMU -icount shift=0; the pico's cycles counted by
# SysTick under rp2040js), code bytes (.text), the stack's high-water mark,
# and whether the two images are the same.
#   sh bench/specialise-bench.sh   (make bench keeps it as bench/specialise.md)
set -e
RT=build/host/rt
OUT=build/bench-specialise
mkdir -p "$OUT"
make -s build/host/rt
printf '%-10s %-6s %-8s %-7s %-12s %14s %14s %7s %14s %12s %s\n' board backend scene texture figure \
    generic specialised ratio "code B" "stack B" image
for bb in mps2-an386:float mps2-an385:fixed pico:fixed; do
    board=${bb%:*} backend=${bb#*:}
    key=instructions_per_pixel
    [ "$board" = pico ] && key=render_cycles
    for sd in card:3 picolib:6; do
        scene=${sd%:*} depth=${sd#*:}
        for tf in 1 0; do
            for sp in 0 1; do
                v="BOARD=$board BACKEND=$backend SCENE=scenes/bench/$scene.nff SIZE=320x240 DEPTH=$depth AA=0 TEXTURE_FILTER=$tf SPECIALISE=$sp"
                make -s -j2 firmware $v >"$OUT/build.log" 2>&1 || { tail -5 "$OUT/build.log"; exit 1; }
                make -s board-run $v RUN_OUT="$OUT/$sp.png" RUN_RT="$RT" >"$OUT/$sp.report" 2>&1 ||
                    { tail -5 "$OUT/$sp.report"; exit 1; }
                elf=$(make -s board-info $v | sed -n 's/.* elf=\([^ ]*\) .*/\1/p')
                eval "fig$sp=\$(awk -v k=$key '\$1 == k { print \$2 }' $OUT/$sp.report)"
                eval "code$sp=\$(arm-none-eabi-size $elf | awk 'NR == 2 { print \$1 }')"
                eval "stack$sp=\$(awk '\$1 == \"stack_high_water\" { print \$2 }' $OUT/$sp.report)"
            done
            [ "$board" = pico ] && fig0=$((fig0 / 76800)) fig1=$((fig1 / 76800))
            same=$("$RT" compare "$OUT/1.png" "$OUT/0.png" --max-error 0 >/dev/null && echo same || echo differs)
            printf '%-10s %-6s %-8s %-7s %-12s %14s %14s %7s %14s %12s %s\n' "$board" "$backend" "$scene" \
                "$([ $tf = 1 ] && echo filtered || echo point)" "$([ "$board" = pico ] && echo cycles/px || echo instr/px)" \
                "$fig0" "$fig1" "$(awk -v a="$fig1" -v b="$fig0" 'BEGIN { printf "%.3f", a / b }')" \
                "$code0 -> $code1" "$stack0 -> $stack1" "$same"
        done
    done
done
