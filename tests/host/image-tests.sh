#!/bin/sh
# Image tests: every SPD size-1 and size-2 scene, every demo scene of
# scenes/ and the benchmark scenes of scenes/bench at 128x128, depth 5.
# The reference is the exact double build (its tolerances come from
# double precision, src/numeric/tolerance.h); the fixed
# and the float builds must each reach PSNR >= 50 dB against it with at
# most 0.25% of pixels off by more than 8/255. The double build with the
# fixed build's tolerances (--double-ftol) is printed beside them: it
# splits the fixed build's error into number format and tolerances.
# Prints one line of figures per scene and "name: N passed, M failed".
RT=${1:-build/asan/rt}
OUT=${2:-build/test-images}
SIZE=128x128
PSNR_MIN=50
OVER8_MAX=0.25
mkdir -p "$OUT"
. tests/lib/check.sh
echo "image tests: fixed and float vs the exact double build at $SIZE (PSNR >= $PSNR_MIN dB, <= $OVER8_MAX% of pixels off by > 8/255)"
for f in scenes/spd/balls-1.nff scenes/spd/gears-1.nff scenes/spd/rings-1.nff scenes/spd/teapot-1.nff \
         scenes/spd/tetra-1.nff scenes/spd/balls-2.nff scenes/spd/rings-2.nff scenes/spd/teapot-2.nff \
         scenes/spd/tetra-2.nff scenes/*.nff scenes/bench/*.nff; do
    s=$(basename "$f" .nff)
    ok=1
    for b in double fixed float double-ftol; do
        "$RT" "$f" -o "$OUT/$s-$b.png" --size $SIZE --$b --quiet 2>>"$OUT/$s.err" || ok=0
    done
    if [ $ok = 0 ]; then
        bad "$(printf '%-28s render failed: %s' "$s" "$(cat "$OUT/$s.err")")"
        continue
    fi
    tol=$("$RT" compare "$OUT/$s-double-ftol.png" "$OUT/$s-double.png" | sed 's/  over2 [^ ]*//')
    echo "        $s: double with the fixed tolerances vs exact: $tol"
    for b in fixed float; do
        check "$s ($b)" "$RT" compare "$OUT/$s-$b.png" "$OUT/$s-double.png" --psnr-min $PSNR_MIN --max-over8 $OVER8_MAX
    done
done

# Transform identities: a shape placed by a transform renders like the
# same shape written in world coordinates (the fixed build, both ways;
# tolerance: PSNR >= 50 dB, at most 0.1% of pixels off by more than 8/255,
# for the rounding of the object-space mapping).
ident() { # name, world body, transformed body
    head='v\nfrom 1 -7 3\nat 0 0 0.3\nup 0 0 1\nangle 40\nhither 1\nresolution 96 96\nl -4 -6 8\nl 5 -3 6\nf 0.8 0.8 0.8 0.8 0.2 10 0 1\np 4\n-6 -6 -1\n6 -6 -1\n6 6 -1\n-6 6 -1\nf 0.9 0.4 0.3 0.7 0.3 30 0 1\n'
    printf "$head$2" >"$OUT/$1-world.nff"
    printf "$head$3" >"$OUT/$1-xf.nff"
    if "$RT" "$OUT/$1-world.nff" -o "$OUT/$1-world.png" --quiet && "$RT" "$OUT/$1-xf.nff" -o "$OUT/$1-xf.png" --quiet; then
        check "identity: $1" "$RT" compare "$OUT/$1-xf.png" "$OUT/$1-world.png" --psnr-min 50 --max-over8 0.1
    else
        bad "identity: $1: render failed"
    fi
}
ident "translated box" 'box 0.2 -0.3 -0.5 1.8 1.1 0.9\n' 'transform\ntranslate 1 0.4 0.2\nbox -0.8 -0.7 -0.7 0.8 0.7 0.7\nend\n'
ident "sphere via scale" 's 0.5 0.2 0.3 1.1\n' 'transform\ntranslate 0.5 0.2 0.3\nscale 1.1 1.1 1.1\ns 0 0 0 1\nend\n'
ident "rotated box" 'box -1 -0.6 -0.6 1 0.6 0.6\n' 'transform\nrotate 0 0 1 90\nbox -0.6 -1 -0.6 0.6 1 0.6\nend\n'

# RGB565 framebuffer: the same render through the 16-bit format may only
# differ by the 5/6-bit quantisation (at most 255/31/2 -> 5 levels).
if "$RT" scenes/spd/balls-1.nff -o "$OUT/balls-1-565.png" --size 64x48 --format rgb565 --quiet &&
   "$RT" scenes/spd/balls-1.nff -o "$OUT/balls-1-888.png" --size 64x48 --quiet; then
    check "rgb565 vs rgb888" "$RT" compare "$OUT/balls-1-565.png" "$OUT/balls-1-888.png" --max-error 5
else
    bad "rgb565 render failed"
fi
# Adaptive depth: off by default; on, it must trace fewer reflection rays
# and stay within the image tolerance of the full tree.
"$RT" scenes/spd/rings-2.nff -o "$OUT/rings-2-full.png" --size 96x96 --stats --quiet 2>"$OUT/full.stats"
"$RT" scenes/spd/rings-2.nff -o "$OUT/rings-2-adaptive.png" --size 96x96 --adaptive 0.1 --stats --quiet 2>"$OUT/adaptive.stats"
full=$(awk '$1 == "reflect_rays" { print $2 }' "$OUT/full.stats")
adap=$(awk '$1 == "reflect_rays" { print $2 }' "$OUT/adaptive.stats")
if [ -n "$full" ] && [ -n "$adap" ] && [ "$adap" -lt "$full" ] &&
   cmp=$("$RT" compare "$OUT/rings-2-adaptive.png" "$OUT/rings-2-full.png" --psnr-min 40); then
    ok "$(printf '%-28s reflect rays %s -> %s, %s' "adaptive depth 0.1" "$full" "$adap" "$cmp")"
else
    bad "$(printf '%-28s reflect rays %s -> %s %s' "adaptive depth 0.1" "$full" "$adap" "$cmp")"
fi

# Every SPD scene, the "default" sizes included, loads within the hosted
# capacities and renders (tiny, to keep the brute-force time down).
for f in scenes/spd/*.nff; do
    s=$(basename "$f" .nff)
    case $s in *-default) ;; *) continue ;; esac
    check "$s renders (16x16)" "$RT" "$f" -o "$OUT/$s.png" --size 16x16 --quiet
done
summary image-tests
