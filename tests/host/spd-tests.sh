#!/bin/sh
# SPD mode: every SPD size-2 scene rendered by the SPD procedure (512x512
# from 513x513 corner rays, depth 5, rule 8) in the fixed and the double
# build; their ray statistics must agree within 1%, and the images must
# meet the image-test tolerance. One thread each: with more, the rows of
# corners traced again at run starts depend on timing (bands.c).
RT=${1:-build/asan/rt}
OUT=${2:-build/test-spd}
mkdir -p "$OUT"
. tests/lib/check.sh
echo "SPD-mode tests: ray statistics, fixed vs double, within 1%"
stat() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }
for s in balls-2 rings-2 teapot-2 tetra-2; do
    "$RT" scenes/spd/$s.nff -o "$OUT/$s-fixed.png" --spd --fixed --threads 1 --stats --quiet 2>"$OUT/$s-fixed.stats" &&
    "$RT" scenes/spd/$s.nff -o "$OUT/$s-double.png" --spd --double --threads 1 --stats --quiet 2>"$OUT/$s-double.stats" || {
        bad "$s: render failed"; continue; }
    line="" bad=0
    for k in eye_rays eye_hits reflect_rays refract_rays shadow_rays; do
        f=$(stat "$k" "$OUT/$s-fixed.stats") d=$(stat "$k" "$OUT/$s-double.stats")
        case "$f:$d" in # a key missing from either build's statistics is a failure, not 0%
        [0-9]*:[0-9]*) ;;
        *) line="$line $k missing ('$f'/'$d');" bad=1; continue ;;
        esac
        dev=$(awk -v f="$f" -v d="$d" 'BEGIN { x = f - d; if (x < 0) x = -x; y = (d > 0) ? 100 * x / d : ((x > 0) ? 100 : 0); printf "%.3f", y }')
        line="$line $k $f/$d ($dev%);"
        awk -v v="$dev" 'BEGIN { exit !(v > 1.0) }' && bad=1
    done
    if [ $bad -eq 0 ]; then ok "$s:$line"; else bad "$s:$line"; fi
    if cmp=$("$RT" compare "$OUT/$s-fixed.png" "$OUT/$s-double.png" --psnr-min 50 --max-over8 0.25); then
        ok "$s SPD image: $cmp"
    else
        bad "$s SPD image: $cmp"
    fi
done
summary spd-tests
