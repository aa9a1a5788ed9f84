#!/bin/sh
# Planes, textures and the sky (docs/shading-model.md, "Textures and the
# sky"), at 128x128:
#  - the model: the double build against tests/host/ref_tracer.c (written from
#    the page alone; --far gives it the far cube, 2^(9 - scene_scale_log2)
#    of rt --stats) on the benchmark scenes and scenes/textures.nff,
#    PSNR >= 70 dB;
#  - the far cube ends planes: with a small cube the double build matches
#    the tracer told of it, and differs from the tracer without it;
#  - the fixed and float builds at far distances: a floor seen to the
#    horizon from 0.3 above it (tiles far smaller than a pixel) and tiles
#    700 units from the origin. A sample within the build's rounding of a
#    tile edge may take the other tile, so single pixels flip at edges:
#    at most 0.1% of pixels off by more than 8/255 and PSNR >= 35 dB; a
#    seam (tiles of the wrong width, a row of wrong tiles) would fail;
#  - a floor that ends before the far cube's edge and a sky seen in
#    mirrors at every depth are in the benchmark scenes' comparisons.
# Prints one line of figures per check and "surfaces-tests: N passed, M failed".
SIZE=128x128
. tests/host/host-lib.sh
echo "surfaces tests: planes, textures, the sky at $SIZE"
build_ref_tracer || { summary surfaces-tests; exit 1; }
# far_of SCENE: the far cube's half side for tests/host/ref_tracer.c
far_of() {
    k=$("$RT" "$1" -o "$OUT/scale.png" --size 8x8 --stats 2>&1 >/dev/null | awk '$1 == "scene_scale_log2" { print $2 }')
    [ -n "$k" ] && awk -v k="$k" 'BEGIN { print 2 ^ (9 - k) }'
}
# model NAME SCENE DEPTH: the double build against the tracer, which
# finds the far cube by the page's scale rule itself; it must be rt's
model() {
    far=$(far_of "$2")
    if "$REF" "$2" -o "$OUT/$1-ref.ppm" --size $SIZE --depth $3 --far rule 2>"$OUT/$1.err" &&
       "$RT" "$2" -o "$OUT/$1-double.png" --size $SIZE --depth $3 --double --quiet 2>>"$OUT/$1.err"; then
        ref_far=$(awk '/^far cube/ { print $3 }' "$OUT/$1.err")
        [ -n "$far" ] && [ "$ref_far" = "$far" ] && ok "$1: far cube $far by the rule in ref_tracer and in the reader" ||
            bad "$1: far cube $ref_far by the rule in ref_tracer, $far in the reader"
        check "$1: double vs ref_tracer" "$RT" compare "$OUT/$1-ref.ppm" "$OUT/$1-double.png" --psnr-min 70
    else
        bad "$1: render failed: $(cat "$OUT/$1.err")"
    fi
}
model card scenes/bench/card.nff 3
model picolib scenes/bench/picolib.nff 6
model whitted scenes/bench/whitted.nff 5
model textures scenes/textures.nff 5

# A floor under a camera 0.1 above it, every coordinate of the geometry
# (the view's `at` among them) at most 0.1, below 2^-3: the scale is 2^7
# and the far cube's half side 4, so the floor ends 4 units out, a band
# of sky under the horizon.
printf 'v\nfrom 0 0 0.1\nat 0 0.1 0.0995\nup 0 0 1\nangle 10\nhither 0.001\nresolution 64 64\nsky 0.9 0.8 0.7 0.2 0.3 0.8 0 0 1 1\nl 0.05 0.04 0.12\nf 1 1 1 0.9 0 1 0 1\nchecker 0.01 1 1 1 0.1 0.1 0.1 xy\nplane 0 0 0 0 0 1\nf 1 0 0 1 0 1 0 1\ns 0 0.05 0.002 0.002\n' >"$OUT/cube.nff"
far=$(far_of "$OUT/cube.nff")
if [ "$far" = 4 ] && "$REF" "$OUT/cube.nff" -o "$OUT/cube-ref.ppm" --far 4 && "$REF" "$OUT/cube.nff" -o "$OUT/cube-endless.ppm" &&
   "$RT" "$OUT/cube.nff" -o "$OUT/cube-double.png" --double --quiet; then
    check "far cube 4: double vs ref_tracer --far 4" "$RT" compare "$OUT/cube-ref.ppm" "$OUT/cube-double.png" --psnr-min 70
    if "$RT" compare "$OUT/cube-endless.ppm" "$OUT/cube-double.png" --psnr-min 30 >/dev/null 2>&1; then
        bad "far cube 4: the double build matches an endless floor: the cube does not end it"
    else
        ok "far cube 4: an endless floor differs ($("$RT" compare "$OUT/cube-endless.ppm" "$OUT/cube-double.png"))"
    fi
else
    bad "far cube: scale or render failed (half side '$far', expected 8)"
fi

# far distances in the fixed and float builds
printf 'v\nfrom 0 0 0.3\nat 0 10 0.25\nup 0 0 1\nangle 50\nhither 0.01\nresolution 128 128\nsky 0.9 0.8 0.7 0.2 0.3 0.8 0 0 1 1\nl 3 -4 6\nf 1 1 1 0.9 0 1 0 1\nchecker 0.25 1 1 1 0.1 0.1 0.1 xy\nplane 0 0 0 0 0 1\nf 1 0.4 0.2 0.8 0.3 32 0 1\ns 0 3 0.4 0.4\n' >"$OUT/horizon.nff"
printf 'v\nfrom -700 -700 3\nat -702 -698 0\nup 0 0 1\nangle 40\nhither 0.01\nresolution 128 128\nl -690 -705 20\nf 1 1 1 0.9 0 1 0 1\nchecker 0.5 1 1 1 0.1 0.2 0.6 xy\nplane 0 0 0 0 0 1\nf 1 0.4 0.2 0.8 0.3 32 0 1\ns 0 0 1 1\n' >"$OUT/far-tiles.nff"
for s in horizon far-tiles; do
    if "$RT" "$OUT/$s.nff" -o "$OUT/$s-double.png" --double --quiet 2>"$OUT/$s.err"; then
        model "$s" "$OUT/$s.nff" 5
        for b in fixed float; do
            "$RT" "$OUT/$s.nff" -o "$OUT/$s-$b.png" --$b --quiet 2>>"$OUT/$s.err" &&
                check "$s ($b)" "$RT" compare "$OUT/$s-$b.png" "$OUT/$s-double.png" --psnr-min 35 --max-over8 0.1
        done
    else
        bad "$s: render failed: $(cat "$OUT/$s.err")"
    fi
done

summary surfaces-tests
