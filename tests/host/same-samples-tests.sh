#!/bin/sh
# rt --same-samples B (adaptive anti-aliasing's split decisions recorded
# by build B and replayed: rt_render_opts_t.aa_splits, RT_AA_REPLAY):
#   - the number format alone: on every demo and benchmark scene
#     (scenes/*.nff, scenes/bench/*.nff) and every SPD scene
#     (scenes/spd/*.nff), at 96x72 and make run's depth (5; card 3,
#     picolib 6), --double --aa 3 --same-samples fixed >= 50 dB from
#     --fixed --aa 3 (the board's image: board == host fixed is
#     asserted bit for bit elsewhere); the figure without the option
#     (each build deciding its own splits) is printed beside it;
#   - replaying its own decisions changes nothing: --fixed --aa 3
#     --same-samples fixed is --fixed --aa 3 byte for byte;
#   - the samples are the same: with one thread, the replaying double and
#     float builds trace as many eye rays and split as many squares as
#     the fixed build (rt --stats), where without the option whitted's
#     double build splits others at 128x128 (make run's size: the
#     mismatch the option removes);
#   - the image is the same for --threads 1 and 3, and a viewport's
#     pixels are the whole frame's;
#   - without --aa (one sample, --spp) the option changes nothing;
#   - printed, not asserted: whitted with point-sampled textures
#     (--texture-filter off, make run TEXTURE_FILTER=0), where the format
#     misses 50 dB at the same samples, and the same scene with the
#     checkerboard in one colour;
#   - a bad build name fails with exit 2 and a clear message.
# The fixed references, the figures without the option and the fixed
# build's replays of itself use RT_FAST (the optimised build of the same
# source), the double and float builds' replays the build under test.
SIZE=96x72
. tests/host/host-lib.sh
echo "same-samples tests: --double --aa 3 --same-samples fixed against --fixed --aa 3 at $SIZE"

depth_of() { case $1 in card) echo 3 ;; picolib) echo 6 ;; *) echo 5 ;; esac; }
psnr_of() { "$RT" compare "$1" "$2" | sed 's/psnr \([^ ]*\) dB  max-error \([0-9]*\).*/\1 dB, max error \2/'; }

for f in scenes/*.nff scenes/bench/*.nff scenes/spd/*.nff; do
    s=$(basename "$f" .nff)
    a="--aa 3 --size $SIZE --depth $(depth_of "$s") --quiet"
    if ! { "$RT_FAST" "$f" --fixed $a -o "$OUT/$s-fixed.ppm" &&
           "$RT_FAST" "$f" --double $a -o "$OUT/$s-own.ppm" &&
           "$RT" "$f" --double $a --same-samples fixed -o "$OUT/$s-replay.ppm" &&
           "$RT_FAST" "$f" --fixed $a --same-samples fixed -o "$OUT/$s-self.ppm"; } 2>"$OUT/$s.err"; then
        bad "$s: render failed: $(grep -v 'note:' "$OUT/$s.err" | head -1)"
        continue
    fi
    check "$s: format (own splits: $(psnr_of "$OUT/$s-fixed.ppm" "$OUT/$s-own.ppm"))" \
        "$RT" compare "$OUT/$s-fixed.ppm" "$OUT/$s-replay.ppm" --psnr-min 50
    if cmp -s "$OUT/$s-fixed.ppm" "$OUT/$s-self.ppm"; then
        ok "$s: --fixed replaying its own splits: byte-identical"
    else
        bad "$s: --fixed --same-samples fixed differs from --fixed: $("$RT" compare "$OUT/$s-fixed.ppm" "$OUT/$s-self.ppm")"
    fi
done

# the same samples: eye rays and splits, one thread (with more, where
# runs start decides how many corner rows are traced again)
counts() { # SCENE SIZE ARGS...: "eye_rays N aa_splits M"
    f=$1 sz=$2; shift 2
    "$RT" "$f" --aa 3 --size "$sz" --threads 1 --quiet --stats -o "$OUT/counts.ppm" "$@" 2>&1 |
        awk '$1 == "eye_rays" || $1 == "aa_splits" { printf "%s%s %s", n++ ? " " : "", $1, $2 }'
}
W=scenes/bench/whitted.nff
for sc in "$W 128x128" "scenes/showpiece.nff $SIZE" "scenes/spd/balls-2.nff $SIZE"; do
    set -- $sc
    fixed=$(counts "$1" "$2" --fixed)
    for b in double float; do
        got=$(counts "$1" "$2" --$b --same-samples fixed)
        if [ -n "$fixed" ] && [ "$got" = "$fixed" ]; then
            ok "$(basename "$1" .nff) $2: --$b --same-samples fixed traces the fixed build's samples ($got)"
        else
            bad "$(basename "$1" .nff) $2: --$b --same-samples fixed: $got, fixed: $fixed"
        fi
    done
done
fixed=$(counts "$W" 128x128 --fixed)
own=$(counts "$W" 128x128 --double)
if [ -n "$own" ] && [ "$own" != "$fixed" ]; then
    ok "whitted 128x128: without the option the double build samples elsewhere ($own; fixed: $fixed)"
else
    bad "whitted 128x128: without the option the double build's samples are the fixed build's ($own)"
fi
# the figures at make run's size, with and without the option
"$RT_FAST" "$W" --fixed --aa 3 --size 128x128 --depth 5 --quiet -o "$OUT/w128-fixed.ppm"
"$RT_FAST" "$W" --double --aa 3 --size 128x128 --depth 5 --quiet -o "$OUT/w128-own.ppm"
check "whitted 128x128 (own splits: $(psnr_of "$OUT/w128-fixed.ppm" "$OUT/w128-own.ppm"))" \
    sh -c "\"$RT\" \"$W\" --double --aa 3 --same-samples fixed --size 128x128 --depth 5 --quiet -o \"$OUT/w128-replay.ppm\" &&
           \"$RT\" compare \"$OUT/w128-fixed.ppm\" \"$OUT/w128-replay.ppm\" --psnr-min 50"

# threads and viewports: the same pixels
for n in 1 3; do
    "$RT" "$W" --double --aa 3 --same-samples fixed --size $SIZE --threads $n --quiet -o "$OUT/w-t$n.ppm"
done
if cmp -s "$OUT/w-t1.ppm" "$OUT/w-t3.ppm" && cmp -s "$OUT/w-t1.ppm" "$OUT/whitted-replay.ppm"; then
    ok "whitted: --same-samples fixed byte-identical for --threads 1 and 3"
else
    bad "whitted: --same-samples fixed differs between --threads 1 and 3"
fi
"$RT" "$W" --double --aa 3 --same-samples fixed --size $SIZE --viewport 13,30,50,9 --quiet -o "$OUT/w-vp.ppm"
python3 tests/lib/ppm.py crop "$OUT/w-t1.ppm" 13 30 50 9 "$OUT/w-crop.ppm"
if cmp -s "$OUT/w-vp.ppm" "$OUT/w-crop.ppm"; then
    ok "whitted: --same-samples fixed with --viewport: the whole frame's pixels"
else
    bad "whitted: --same-samples fixed with --viewport differs from the whole frame's pixels"
fi

# without adaptive anti-aliasing the samples are the same already
for a in "" "--spp 2"; do
    "$RT" "$W" --double $a --size 48x36 --quiet -o "$OUT/w-plain.ppm"
    "$RT" "$W" --double $a --same-samples fixed --size 48x36 --quiet -o "$OUT/w-plain-ss.ppm"
    if cmp -s "$OUT/w-plain.ppm" "$OUT/w-plain-ss.ppm"; then
        ok "whitted ${a:-one sample}: --same-samples changes nothing"
    else
        bad "whitted ${a:-one sample}: --same-samples changes the image"
    fi
done

# point-sampled textures (make run TEXTURE_FILTER=0): printed, not asserted
# (the checkerboard's horizon, where a sample's hit point moves across a
# square's edge: docs/accuracy.md)
"$RT_FAST" "$W" --fixed --aa 3 --texture-filter off --size 128x128 --quiet -o "$OUT/wp-fixed.ppm"
"$RT_FAST" "$W" --double --aa 3 --texture-filter off --size 128x128 --quiet -o "$OUT/wp-own.ppm"
"$RT_FAST" "$W" --double --aa 3 --texture-filter off --same-samples fixed --size 128x128 --quiet -o "$OUT/wp-replay.ppm"
echo "  info  whitted 128x128 --texture-filter off: own splits $(psnr_of "$OUT/wp-fixed.ppm" "$OUT/wp-own.ppm");" \
     "same samples $(psnr_of "$OUT/wp-fixed.ppm" "$OUT/wp-replay.ppm")"
# the same with the checkerboard's two colours made one: the error was its edges
sed 's/^checker 1  1 0.1 0.05  1 0.9 0.1 xz$/checker 1  1 0.9 0.1  1 0.9 0.1 xz/' "$W" >"$OUT/whitted-plain.nff"
if cmp -s "$W" "$OUT/whitted-plain.nff"; then
    bad "whitted's checker line not found (the one-colour variant)"
else
    "$RT_FAST" "$OUT/whitted-plain.nff" --fixed --aa 3 --texture-filter off --size 128x128 --quiet -o "$OUT/wq-fixed.ppm"
    "$RT_FAST" "$OUT/whitted-plain.nff" --double --aa 3 --texture-filter off --same-samples fixed --size 128x128 \
        --quiet -o "$OUT/wq-replay.ppm"
    echo "  info  the same, the checkerboard in one colour: same samples $(psnr_of "$OUT/wq-fixed.ppm" "$OUT/wq-replay.ppm")"
fi

# bad values: exit 2, a message naming the option, no image
rm -f "$OUT/bad.png"
got=$("$RT" "$W" --aa 3 --same-samples exact --size 8x8 -o "$OUT/bad.png" 2>&1 >/dev/null); status=$?
case "$got" in
*"--same-samples: expected a build (fixed, double, double-ftol, float), got 'exact'"*)
    [ $status -eq 2 ] && [ ! -e "$OUT/bad.png" ] && ok "--same-samples exact: $(echo "$got" | head -1)" || bad "--same-samples exact: status $status" ;;
*) bad "--same-samples exact: status $status, $got" ;;
esac
"$RT" --help | grep -q -- "--same-samples B" && ok "--help names --same-samples" || bad "--help does not name --same-samples"

summary same-samples-tests
