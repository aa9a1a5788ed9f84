#!/bin/sh
# Pixel format tests: a scene rendered through every framebuffer format
# (RT_FB_FORMATS, include/rt_fb.h; rt --format) and expanded back to 8-bit RGB
# must match the RGB888 render within the format's quantisation:
#   rgb888, xrgb8888   exact
#   rgb565, rgb565be   R, B within 5/255 and G within 3/255 (half a 5- or
#                      6-bit step, plus the rounding of the expansion);
#                      both byte orders give the same image
#   l8                 R = G = B, within 1/255 of the Rec.601 luma
#                      0.299 R + 0.587 G + 0.114 B of the RGB888 image,
#                      computed here in floating point
#   l4                 R = G = B, within 9/255 of that luma (half a 4-bit
#                      step, 8.5, plus rounding)
# An odd width (61) exercises the last L4 byte's padding.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-formats}
mkdir -p "$OUT"
. tests/lib/check.sh
echo "format tests: every pixel format against the rgb888 render"
for f in scenes/spd/balls-1.nff scenes/showpiece.nff; do
    s=$(basename "$f" .nff)
    for fmt in rgb888 rgb565 rgb565be xrgb8888 l8 l4; do
        if ! "$RT" "$f" -o "$OUT/$s-$fmt.ppm" --size 61x37 --format $fmt --quiet 2>"$OUT/$s-$fmt.err"; then
            bad "$s $fmt: render failed: $(cat "$OUT/$s-$fmt.err")"
            continue
        fi
    done
    for fmt in rgb888 rgb565 rgb565be xrgb8888 l8 l4; do
        [ -f "$OUT/$s-$fmt.ppm" ] || continue
        if msg=$(python3 - "$OUT/$s-rgb888.ppm" "$OUT/$s-$fmt.ppm" $fmt "$OUT/$s-rgb565.ppm" <<'PY'
import sys
sys.path.insert(0, 'tests/lib')
from ppm import read as ppm
ref_path, path, fmt, p565 = sys.argv[1:5]
w, h, ref = ppm(ref_path)
w2, h2, img = ppm(path)
assert (w, h) == (w2, h2), "size differs"
worst = [0, 0, 0]
grey_ok = True
for i in range(w * h):
    r, g, b = ref[3*i:3*i+3]
    o = img[3*i:3*i+3]
    if fmt in ('l8', 'l4'):
        grey_ok &= o[0] == o[1] == o[2]
        y = 0.299 * r + 0.587 * g + 0.114 * b
        e = abs(o[0] - y)
        worst = [max(worst[0], e)] * 3
    else:
        for k in range(3):
            worst[k] = max(worst[k], abs(o[k] - (r, g, b)[k]))
limit = {'rgb888': (0, 0, 0), 'xrgb8888': (0, 0, 0), 'rgb565': (5, 3, 5), 'rgb565be': (5, 3, 5),
         'l8': (1, 1, 1), 'l4': (9, 9, 9)}[fmt]
ok = grey_ok and all(worst[k] <= limit[k] for k in range(3))
if fmt == 'rgb565be':
    same = ppm(p565)[2] == img
    ok = ok and same
    extra = ', same image as rgb565' if same else ', NOT the same image as rgb565'
else:
    extra = ''
print('max error R/G/B %s (limit %s)%s%s' % ('/'.join('%.2f' % e for e in worst), '/'.join(map(str, limit)),
      '' if grey_ok else ', NOT grey', extra))
sys.exit(0 if ok else 1)
PY
); then
            ok "$s $fmt: $msg"
        else
            bad "$s $fmt: $msg"
        fi
    done
done
# Ordered dithering (--dither): each pixel within one step of the source
# (rgb565: 9/255 R, B and 5/255 G; l8: 2/255 of the 8-bit luma; l4: 17/255
# of it), not the undithered image, and closer to the source as an eye
# sees it: after a Gaussian blur of 1 pixel (rt compare --blur 1) the
# dithered image's PSNR against the source (rgb888; for l4, the l8 render)
# is at least 5 dB above the undithered one's (128x128, the showpiece).
for f in scenes/spd/balls-1.nff scenes/showpiece.nff; do
    s=$(basename "$f" .nff)
    for case in rgb565:rgb888:9 l8:l8:2 l4:l8:17; do
        fmt=${case%%:*} rest=${case#*:} src=${rest%%:*} lim=${rest#*:}
        "$RT" "$f" -o "$OUT/$s-$fmt-dither.ppm" --size 61x37 --format $fmt --dither --quiet 2>/dev/null
        if e=$("$RT" compare "$OUT/$s-$fmt-dither.ppm" "$OUT/$s-$src.ppm" --max-error $lim) &&
           ! cmp -s "$OUT/$s-$fmt-dither.ppm" "$OUT/$s-$fmt.ppm"; then
            ok "$s $fmt --dither: within $lim/255 of $src ($e), not the undithered image"
        else
            bad "$s $fmt --dither: over $lim/255 from $src, or the same as undithered ($e)"
        fi
    done
done
f=scenes/showpiece.nff
for fmt in rgb888 l8; do
    "$RT" $f -o "$OUT/blur-src-$fmt.ppm" --size 128x128 --format $fmt --quiet 2>/dev/null
done
for case in rgb565:rgb888 l4:l8; do
    fmt=${case%%:*} src=${case#*:}
    "$RT" $f -o "$OUT/blur-$fmt.ppm" --size 128x128 --format $fmt --quiet 2>/dev/null
    "$RT" $f -o "$OUT/blur-$fmt-dither.ppm" --size 128x128 --format $fmt --dither --quiet 2>/dev/null
    plain=$("$RT" compare "$OUT/blur-$fmt.ppm" "$OUT/blur-src-$src.ppm" --blur 1 | sed 's/psnr \([^ ]*\) dB.*/\1/')
    dith=$("$RT" compare "$OUT/blur-$fmt-dither.ppm" "$OUT/blur-src-$src.ppm" --blur 1 | sed 's/psnr \([^ ]*\) dB.*/\1/')
    if [ -n "$dith" ] && [ -n "$plain" ] && awk -v d="$dith" -v p="$plain" 'BEGIN { exit !(d >= p + 5) }'; then
        ok "showpiece $fmt, blurred 1 px, vs $src: $plain dB undithered, $dith dB dithered"
    else
        bad "showpiece $fmt, blurred 1 px, vs $src: $plain dB undithered, $dith dB dithered (want +5 dB)"
    fi
done
summary format-tests
