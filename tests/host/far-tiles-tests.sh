#!/bin/sh
# Textures far from the origin (tests/host/far-tiles/): the fixed build against
# the exact double build at the same samples, 96x72, one sample a pixel.
#  - telephoto-checker: 0.3-unit tiles 1,500 units out (scale 2^-7);
#    grazing-marble: marble of period 0.2 700 units out (2^-6);
#    near-checkers: sizes 0.1, 1/3 and 7 within 100 units (2^-2).
#  - filtered (the default): >= 55 dB far (62.9, 65.3 measured), >= 65 dB
#    near (74.8);
#  - point-sampled (--texture-filter off): >= 28 dB far (34.0, 31.3) and
#    >= 40 dB near (43.2). What is left is the position grid's rounding of
#    P flipping pixels that sit on a tile or stripe edge; with a texture
#    size rounded to the grid, tiles drifted (9.9, 13.3 and 27.3 dB).
RT=${1:-build/asan/rt}
OUT=${2:-build/asan/test-far-tiles}
mkdir -p "$OUT"
. tests/lib/check.sh
echo "far tiles: fixed against double, 96x72"
for s in telephoto-checker:55:28 grazing-marble:55:28 near-checkers:65:40; do
    scene=${s%%:*} rest=${s#*:}
    min_filtered=${rest%%:*} min_point=${rest#*:}
    f=tests/host/far-tiles/$scene.nff o=$OUT/$scene
    if ! { "$RT" "$f" -o "$o-fixed.png" --fixed --quiet && "$RT" "$f" -o "$o-double.png" --double --quiet &&
           "$RT" "$f" -o "$o-pfixed.png" --fixed --texture-filter off --quiet &&
           "$RT" "$f" -o "$o-pdouble.png" --double --texture-filter off --quiet; } 2>"$o.err"; then
        bad "$scene: render failed: $(cat "$o.err")"
        continue
    fi
    check "$scene filtered" "$RT" compare "$o-fixed.png" "$o-double.png" --psnr-min "$min_filtered"
    check "$scene point-sampled" "$RT" compare "$o-pfixed.png" "$o-pdouble.png" --psnr-min "$min_point"
done
summary far-tiles
