#!/bin/sh
# Cost of one intersection test on the board, per primitive kind: a scene
# holding only that primitive, 32x32 eye rays straight to scene_nearest
# (one leaf: no box tests), instructions per test with the ray set-up
# subtracted (QEMU -icount shift=0, exact).
RT=${RT:-build/host/rt}
OUT=build/bench-prims
mkdir -p "$OUT"
head='v\nfrom 0.4 -6 1.5\nat 0 0 0\nup 0 0 1\nangle 30\nhither 1\nresolution 32 32\nf 0.8 0.6 0.5 0.8 0.2 10 0 1\n'
printf '%-16s %10s %8s %22s\n' primitive tests hits "instructions per test"
while IFS='|' read -r name body; do
    [ -z "$name" ] && continue
    f="$OUT/$name.nff"
    printf "$head$body" >"$f"
    d=$(make -s print-fwdir SCENE="$f" SIZE=32x32 AA=0)
    if make -s SCENE="$f" SIZE=32x32 AA=0 "$d/prims.elf" >"$OUT/$name.build" 2>&1 &&
       timeout 300 qemu-system-arm -M mps2-an385 -nographic -monitor none \
           -semihosting-config enable=on,target=native -icount shift=0 -kernel "$d/prims.elf" \
           </dev/null >"$OUT/$name.stream" 2>/dev/null; then
        "$RT" receive "$OUT/$name.stream" -o "$OUT/unused.png" >"$OUT/$name.report" 2>/dev/null
        t=$(awk '$1 == "tests" { print $2 }' "$OUT/$name.report")
        h=$(awk '$1 == "hits" { print $2 }' "$OUT/$name.report")
        i=$(awk '$1 == "instructions_per_test" { print $2 }' "$OUT/$name.report")
        printf '%-16s %10s %8s %22s\n' "$name" "$t" "$h" "$i"
    else
        printf '%-16s  failed (see %s)\n' "$name" "$OUT/$name.build"
    fi
done <<'LIST'
sphere|s 0 0 0 1\n
cylinder|c 0 0 -1 0.7 0 0 1 0.7\n
cone|c 0 0 -1 1 0 0 1 0.1\n
triangle|p 3\n-1 0 -1\n1 0 -1\n0 0 1.2\n
polygon-8|p 8\n0 0 1.5\n0.4 0 0.4\n1.5 0 0\n0.4 0 -0.4\n0 0 -1.5\n-0.4 0 -0.4\n-1.5 0 0\n-0.4 0 0.4\n
patch|pp 3\n-1 0 -1 -0.3 -1 0\n1 0 -1 0.3 -1 0\n0 0.5 1 0 -1 0.4\n
box|transform\nrotate 1 2 3 30\nbox -1 -0.6 -0.7 1 0.6 0.7\nend\n
torus|transform\nrotate 1 0 0 60\ntorus 1 0.35\nend\n
ellipsoid|transform\nrotate 0 1 1 40\nellipsoid 1.2 0.6 0.9\nend\n
hyperboloid|hyperboloid 0.5 0.5 0.7 1\n
general-quadric|quadric 1 2 1 0.5 0 0 0 0 0 -1 -1 -1 -1 1 1 1\n
csg-difference|difference\nbox -0.8 -0.8 -0.8 0.8 0.8 0.8\ns 0.8 -0.8 0.8 0.7\nend\n
csg-lens|intersection\ns 0 -0.6 0 1\ns 0 0.6 0 1\nend\n
LIST
