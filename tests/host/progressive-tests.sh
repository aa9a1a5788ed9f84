#!/bin/sh
# rt --progressive and --progressive-pass N (the core's progressive
# display, rt_render_opts_t.progressive):
#   - the finished image is byte for byte the scanline order's, with the
#     same ray counts (every pixel traced once), in each backend, on
#     scenes and sizes that are not multiples of 8, a viewport on the
#     8-pixel grid, rgb565be dithered and uniform anti-aliasing;
#   - the picture after each pass N equals the finished image reduced by
#     the block rule (tests/host/progressive_rule.py, written from the rule
#     alone), and its eye rays are the lattice's points so far;
#   - what progressive display refuses (adaptive anti-aliasing, SPD mode,
#     l4, a viewport off the grid) and bad --progressive-pass values fail
#     with exit 2 and a clear message, the same in every backend.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-progressive}
mkdir -p "$OUT"
. tests/lib/check.sh

# counts KEYS... from a --stats file: "eye_rays=N ..." for comparison
ray_counts() { grep -E '^(eye_rays|eye_hits|reflect_rays|refract_rays|shadow_rays) ' "$1" | tr -s ' ' '=' | tr '\n' ' '; }

# same_as_scanline NAME ARGS...: --progressive gives the scanline image and rays
same_as_scanline() {
    name=$1; shift
    if ! "$RT" "$@" -o "$OUT/scan.ppm" --quiet --stats 2>"$OUT/scan.txt" ||
       ! "$RT" "$@" --progressive -o "$OUT/prog.ppm" --quiet --stats 2>"$OUT/prog.txt"; then
        bad "$name: failed: $(tail -1 "$OUT/scan.txt") $(tail -1 "$OUT/prog.txt")"
        return
    fi
    a=$(ray_counts "$OUT/scan.txt") b=$(ray_counts "$OUT/prog.txt")
    if cmp -s "$OUT/scan.ppm" "$OUT/prog.ppm" && [ "$a" = "$b" ] && [ -n "$a" ]; then
        ok "$name: --progressive byte-identical to scanline order, rays equal ($a)"
    else
        bad "$name: --progressive differs from scanline order (rays $a / $b)"
    fi
}

# passes NAME X0 Y0 ARGS...: each pass's picture against the rule
passes() {
    name=$1 x0=$2 y0=$3; shift 3
    "$RT" "$@" -o "$OUT/final.ppm" --quiet || { bad "$name: render failed"; return; }
    good=0 msg=
    for n in 1 2 3 4 5 6 7; do
        want=$(python3 tests/host/progressive_rule.py "$OUT/final.ppm" $n $x0 $y0 "$OUT/rule$n.ppm") ||
            { bad "$name: progressive_rule.py failed"; return; }
        "$RT" "$@" --progressive-pass $n -o "$OUT/pass$n.ppm" --quiet --stats 2>"$OUT/pass$n.txt"
        got=$(sed -n 's/^eye_rays *//p' "$OUT/pass$n.txt")
        if cmp -s "$OUT/pass$n.ppm" "$OUT/rule$n.ppm" && [ "$got" = "$want" ]; then
            good=$((good + 1)) msg="$msg $n:$got"
        else
            bad "$name: after pass $n the picture is not the rule's (eye rays $got, the lattice's $want)"
        fi
    done
    [ $good -eq 7 ] && ok "$name: passes 1..7 as the block rule gives them (eye rays:$msg)"
}

echo "progressive tests: --progressive is scanline order's image, passes follow the block rule"
S=scenes
same_as_scanline "card 37x29 fixed" $S/bench/card.nff --size 37x29 --fixed
same_as_scanline "card 37x29 float" $S/bench/card.nff --size 37x29 --float
same_as_scanline "card 37x29 double" $S/bench/card.nff --size 37x29 --double
same_as_scanline "showpiece 40x30 fixed rgb565be dithered" $S/showpiece.nff --size 40x30 --format rgb565be --dither
same_as_scanline "whitted 64x48 float viewport 8,16,40,32" $S/bench/whitted.nff --size 64x48 --float --viewport 8,16,40,32
same_as_scanline "csg 35x21 double viewport to the edges" $S/csg.nff --size 35x21 --double --viewport 16,8,19,13
same_as_scanline "textures 30x22 fixed --spp 2" $S/textures.nff --size 30x22 --spp 2
same_as_scanline "picolib 45x31 fixed xrgb8888" $S/bench/picolib.nff --size 45x31 --format xrgb8888

passes "card 37x29 fixed rgb565be" 0 0 $S/bench/card.nff --size 37x29 --format rgb565be
passes "showpiece 40x30 double" 0 0 $S/showpiece.nff --size 40x30 --double
passes "whitted 64x48 float viewport 8,16,40,32" 8 16 $S/bench/whitted.nff --size 64x48 --float --viewport 8,16,40,32

# refused: exit 2, a message naming why, in every backend
refuse() {
    name=$1 want=$2; shift 2
    for b in fixed float double; do
        "$RT" "$@" --$b -o "$OUT/no.ppm" --quiet 2>"$OUT/no.err"
        st=$?
        if [ $st -ne 2 ] || ! grep -q "$want" "$OUT/no.err"; then
            bad "$name --$b: exit $st, '$(cat "$OUT/no.err")' (expected 2 and '$want')"
            return
        fi
    done
    ok "$name: exit 2 in every backend: $(head -1 "$OUT/no.err")"
}
refuse "--progressive --aa 2" "not SPD mode or adaptive anti-aliasing" $S/bench/card.nff --size 16x16 --progressive --aa 2
refuse "--progressive --spd" "not SPD mode or adaptive anti-aliasing" $S/bench/card.nff --size 16x16 --progressive --spd
refuse "--progressive-pass 3 --format l4" "whole bytes a pixel" $S/bench/card.nff --size 16x16 --progressive-pass 3 --format l4
refuse "--progressive --viewport 4,0,8,8" "viewport on the 8-pixel grid" $S/bench/card.nff --size 16x16 --progressive --viewport 4,0,8,8
refuse "--progressive --viewport 0,0,12,16" "viewport on the 8-pixel grid" $S/bench/card.nff --size 16x16 --progressive --viewport 0,0,12,16
for v in 0 8 x 1.5 ''; do
    refuse "--progressive-pass '$v'" "progressive-pass" $S/bench/card.nff --size 16x16 --progressive-pass "$v"
done

summary progressive
