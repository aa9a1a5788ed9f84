#!/bin/sh
# BVH and pruning benchmark (printed, not asserted).
#  1. cost against primitive count: balls at sizes 1, 2, 3 (10, 91, 820
#     spheres) on the board (instructions per pixel, 64x64, depth 5) and on
#     the host (render time at 512x512, fixed, median of 3), plus the
#     default size (7381 spheres) on the host;
#  2. every SPD "default" scene in SPD mode on the host, fixed and double,
#     single thread, with its ray statistics and BVH shape;
#  3. firmware code size per SPD scene with and without pruning.
RT=${RT:-build/host/rt}
BOARD=${BOARD:-mps2-an385}
OUT=build/bench-bvh
mkdir -p "$OUT"

median3() { sort -n | sed -n 2p; }
host_time() { # scene, extra args: median render time of 3 runs (after a warm-up), one thread
    f=$1; shift
    "$RT" "$f" -o "$OUT/warm.png" --quiet --threads 1 "$@" 2>/dev/null
    for i in 1 2 3; do
        "$RT" "$f" -o "$OUT/t.png" --stats --quiet --threads 1 "$@" 2>&1 | awk '$1 == "render_seconds" { print $2 }'
    done | median3
}

echo "== cost against primitive count (balls) =="
printf '%-14s %10s %16s %18s\n' scene spheres "board instr/px" "host 512x512 (s)"
for s in balls-1 balls-2 balls-3 balls-default; do
    n=$(grep -c '^s ' scenes/spd/$s.nff)
    ipp="-"
    if [ $s != balls-default ]; then
        if make -s firmware BOARD=$BOARD AA=0 SCENE=scenes/spd/$s.nff SIZE=64x64 DEPTH=5 >"$OUT/$s.build" 2>&1 &&
           make -s board-run BOARD=$BOARD AA=0 SCENE=scenes/spd/$s.nff SIZE=64x64 DEPTH=5 RUN_OUT="$OUT/$s.png" RUN_RT="$RT" \
               >"$OUT/$s.report" 2>&1; then
            ipp=$(awk '$1 == "instructions_per_pixel" { print $2 }' "$OUT/$s.report")
        fi
    fi
    printf '%-14s %10d %16s %18s\n' $s "$n" "$ipp" "$(host_time scenes/spd/$s.nff --size 512x512)"
done

echo
echo "== SPD mode (512x512 from 513x513 corner rays, depth 5), host, single thread =="
printf '%-16s %7s %9s %9s %10s %10s %10s %10s %12s\n' scene backend "time (s)" prims "bvh nodes" "eye hits" reflect refract shadow
for s in balls gears rings teapot tetra; do
    for b in fixed double; do
        t=$(host_time scenes/spd/$s-default.nff --spd --$b)
        "$RT" scenes/spd/$s-default.nff -o "$OUT/$s-$b.png" --spd --$b --threads 1 --stats --quiet 2>"$OUT/$s-$b.stats"
        st() { awk -v k="$1" '$1 == k { print $2 }' "$OUT/$s-$b.stats"; }
        printf '%-16s %7s %9s %9s %10s %10s %10s %10s %12s\n' "$s-default" $b "$t" "$(st primitives)" \
            "$(st bvh_nodes)" "$(st eye_hits)" "$(st reflect_rays)" "$(st refract_rays)" "$(st shadow_rays)"
    done
done

echo
echo "== firmware code size (bytes, scene tables excluded), 64x64, depth 5 =="
printf '%-10s %8s %10s\n' scene pruned unpruned
code_of() { $(make -s board-info BOARD=$BOARD | sed -n 's/.*cross=\([^ ]*\).*/\1/p')size -A "$1" | awk '$1 == ".text" || $1 == ".vectors" || $1 == ".ARM.exidx" { c += $2 } END { print c }'; }
for s in balls-1 gears-1 rings-1 teapot-1 tetra-1 balls-2 rings-2 teapot-2 tetra-2; do
    d=$(make -s print-fwdir BOARD=$BOARD AA=0 SCENE=scenes/spd/$s.nff SIZE=64x64 DEPTH=5)
    make -s firmware BOARD=$BOARD AA=0 SCENE=scenes/spd/$s.nff SIZE=64x64 DEPTH=5 >/dev/null 2>&1
    make -s firmware BOARD=$BOARD AA=0 SCENE=scenes/spd/$s.nff SIZE=64x64 DEPTH=5 PRUNE=0 >/dev/null 2>&1
    printf '%-10s %8s %10s\n' $s "$(code_of $d/fixed.elf)" "$(code_of $d-noprune/fixed.elf)"
done
