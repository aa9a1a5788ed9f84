#!/bin/sh
# Reference tests: the double build against tests/host/ref_tracer.c, a separate
# brute-force double-precision tracer written from docs/shading-model.md
# alone. Every SPD size-1 and size-2 scene without patches is rendered at
# 128x128, depth 5, by both; the double build must reach PSNR >= 70 dB.
# The teapots (smooth patches, the patch policy of docs/shading-model.md)
# must reach 50 dB: a few pixels lie where a policy rule or a tie between
# coplanar faces flips with the last bit of a hit point (teapot-1: 56.7 dB).
# Prints one line of figures per scene and "name: N passed, M failed".
SIZE=128x128
DEPTH=5
PSNR_MIN=70
. tests/host/host-lib.sh
echo "reference tests: double build vs tests/host/ref_tracer.c at $SIZE depth $DEPTH (PSNR >= $PSNR_MIN dB)"
build_ref_tracer || { summary reference-tests; exit 1; }
for s in balls-1 balls-2 gears-1 rings-1 rings-2 tetra-1 tetra-2 teapot-1 teapot-2; do
    r="$OUT/$s-ref.ppm" d="$OUT/$s-double.png"
    min=$PSNR_MIN
    case $s in teapot-*) min=50 ;; esac
    if "$REF" scenes/spd/$s.nff -o "$r" --size $SIZE --depth $DEPTH 2>"$OUT/$s.err" &&
       "$RT" scenes/spd/$s.nff -o "$d" --size $SIZE --depth $DEPTH --double --quiet 2>>"$OUT/$s.err"; then
        check "$s" "$RT" compare "$r" "$d" --psnr-min $min
    else
        bad "$(printf '%-28s render failed: %s' "$s" "$(cat "$OUT/$s.err")")"
    fi
done

# The reference tracer itself rejects a truncated entity: exit status 2
# and a "file:line: message" diagnostic.
printf 'v\nfrom 0 -5 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 8 8\nf 1 0 0 1 0 10 0 1\ns 1 2\n' >"$OUT/truncated.nff"
"$REF" "$OUT/truncated.nff" -o "$OUT/truncated.ppm" 2>"$OUT/truncated.err"
status=$?
msg=$(cat "$OUT/truncated.err")
case $status:$msg in
2:"$OUT/truncated.nff:9: "*)
    ok "$(printf '%-28s %s' "ref_tracer rejects 's 1 2'" "$msg")" ;;
*)
    bad "$(printf '%-28s exit %s: %s' "ref_tracer rejects 's 1 2'" "$status" "$msg")" ;;
esac
summary reference-tests
