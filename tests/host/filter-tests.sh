#!/bin/sh
# Filtered textures (docs/shading-model.md, "Filtered textures") on the
# benchmark scenes at 128x96, against the pixel-area image (rt --double
# --spp 16 --texture-filter off: point-sampled textures, the ground truth
# the filter approximates):
#  - one sample a pixel, filtered: PSNR >= 31 dB (card 32.3, picolib
#    31.6, whitted 34.4; point-sampled 26.7, 21.1, 26.5);
#  - --aa 3, filtered: PSNR >= 36 dB (41.5, 36.9, 40.2);
#  - the fixed build against the double build, filtered, at the same
#    samples: PSNR >= 55 dB, one sample and --aa 3 (59.9 to 76.3);
#  - --texture-filter off is the point-sampled model: the double build
#    against tests/host/ref_tracer.c --texture-filter off, PSNR >= 70 dB, and
#    it differs from the filtered image;
#  - a bad --texture-filter value fails with exit 2.
# Prints one line of figures per check and "filter-tests: N passed, M failed".
SIZE=128x96
. tests/host/host-lib.sh
echo "filter tests: filtered textures against the pixel-area image at $SIZE"
build_ref_tracer || { summary filter-tests; exit 1; }
for s in card picolib whitted; do
    f=scenes/bench/$s.nff o=$OUT/$s
    if ! { "$RT_FAST" "$f" -o "$o-area.png" --double --spp 16 --texture-filter off --size $SIZE --quiet &&
           "$RT" "$f" -o "$o-double.png" --double --size $SIZE --quiet &&
           "$RT" "$f" -o "$o-fixed.png" --fixed --size $SIZE --quiet &&
           "$RT" "$f" -o "$o-aa-double.png" --double --aa 3 --size $SIZE --quiet &&
           "$RT" "$f" -o "$o-aa-fixed.png" --fixed --aa 3 --size $SIZE --quiet &&
           "$RT" "$f" -o "$o-point.png" --double --texture-filter off --size $SIZE --quiet &&
           "$REF" "$f" -o "$o-point-ref.ppm" --size $SIZE --far rule --texture-filter off; } 2>"$o.err"; then
        bad "$s: render failed: $(cat "$o.err")"
        continue
    fi
    check "$s: filtered vs area" "$RT" compare "$o-double.png" "$o-area.png" --psnr-min 31
    check "$s: --aa 3 filtered vs area" "$RT" compare "$o-aa-double.png" "$o-area.png" --psnr-min 36
    check "$s: fixed vs double" "$RT" compare "$o-fixed.png" "$o-double.png" --psnr-min 55
    check "$s: --aa 3 fixed vs double" "$RT" compare "$o-aa-fixed.png" "$o-aa-double.png" --psnr-min 55
    check "$s: off vs ref_tracer off" "$RT" compare "$o-point.png" "$o-point-ref.ppm" --psnr-min 70
    if "$RT" compare "$o-point.png" "$o-double.png" --psnr-min 50 >/dev/null 2>&1; then
        bad "$s: --texture-filter off renders the filtered image"
    else
        ok "$s: off differs from filtered ($("$RT" compare "$o-point.png" "$o-double.png"))"
    fi
done
"$RT" scenes/bench/card.nff -o "$OUT/bad.png" --size 8x8 --texture-filter maybe 2>"$OUT/bad.err"
status=$?
if [ $status -eq 2 ] && grep -q "texture-filter: expected on or off, got 'maybe'" "$OUT/bad.err"; then
    ok "--texture-filter maybe: exit 2, the message"
else
    bad "--texture-filter maybe: exit $status, '$(cat "$OUT/bad.err")'"
fi
summary filter-tests
