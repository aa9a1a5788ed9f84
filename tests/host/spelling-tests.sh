#!/bin/sh
# Images depend on the numbers' values, not on how they are written: every
# scene of scenes/ and tests/ (the fuzz seeds and the bad inputs too) is
# rewritten with trailing zeros, leading zeros, exponents and '+' signs
# (tests/host/respell.py) and must render byte-identical images, or fail with
# the same message (but for the token it quotes), in the fixed, float and
# double builds.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-spelling}
. tests/lib/check.sh
mkdir -p "$OUT"
echo "spelling tests: 16x16 depth 3, each scene as written and respelled, every backend"
for f in scenes/*.nff scenes/*/*.nff tests/fuzz/corpus/*.nff tests/host/bad/*.nff; do
    name=$(echo "$f" | tr '/' '_')
    python3 tests/host/respell.py "$f" "$OUT/$name" || { bad "$f: respell.py"; continue; }
    for b in --fixed --float --double; do
        "$RT" "$f" -o "$OUT/a.ppm" --size 16x16 --depth 3 $b 2>"$OUT/a.err"; sa=$?
        "$RT" "$OUT/$name" -o "$OUT/b.ppm" --size 16x16 --depth 3 $b 2>"$OUT/b.err"; sb=$?
        # (a message quoting the token it found quotes it as written)
        ea=$(sed "s|^$f:||; s|, found '.*'||" "$OUT/a.err") eb=$(sed "s|^$OUT/$name:||; s|, found '.*'||" "$OUT/b.err")
        if [ $sa -ne $sb ] || [ "$ea" != "$eb" ]; then
            bad "$f $b: status $sa/$sb, '$ea' / '$eb'"
        elif [ $sa -eq 0 ] && ! cmp -s "$OUT/a.ppm" "$OUT/b.ppm"; then
            bad "$f $b: the respelled scene renders a different image"
        else
            count_pass
        fi
        rm -f "$OUT/a.ppm" "$OUT/b.ppm"
    done
done
echo "  ($pass scene and backend pairs identical)"
# the scale itself: one sphere's radius written five ways
for b in --fixed --float --double; do
    ks=""
    for r in 1.5 1.50 15e-1 +0001.5000 0.15E+1; do
        printf 'v\nfrom 0 -20 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 8 8\nf 1 1 1 1 0 1 0 1\ns 0 0 0 %s\n' "$r" >"$OUT/k.nff"
        ks="$ks $("$RT" "$OUT/k.nff" -o "$OUT/k.ppm" --stats $b 2>&1 | awk '/scene_scale_log2/ { print $2 }')"
    done
    if [ "$ks" = " 3 3 3 3 3" ]; then
        ok "$b: radius 1.5, 1.50, 15e-1, +0001.5000, 0.15E+1: scene scale 2^3 each (1.5 < 2 = 2^(4-3))"
    else
        bad "$b: radius 1.5 written five ways gives scales$ks, want 3 each"
    fi
done
summary spelling
