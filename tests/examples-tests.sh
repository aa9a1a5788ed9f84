#!/bin/sh
# The examples (examples/): each builds against rt.h alone (plus the core's
# sources, as a user's build would compile them), runs on the host and
# must give the same pixels as `rt` renders the same scene: the LVGL-style
# DMA sink in RGB565 big-endian stepping the frame, the Zephyr-style sink
# with a pitch, and the tiled render through a 16-line buffer.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-examples}
SCENE=scenes/spd/balls-1.nff
mkdir -p "$OUT"
pass=0 fail=0
ok() { pass=$((pass + 1)); printf '  ok    %s\n' "$1"; }
bad() { fail=$((fail + 1)); printf '  FAIL  %s\n' "$1"; }

# name, rt options giving the same frame
for spec in "lvgl_flush:--size 64x64 --format rgb565be" "zephyr_display:--size 64x64" "tiled:--size 96x80"; do
    name=${spec%%:*} opts=${spec#*:}
    if ! cc -std=c11 -Wall -Wextra -Werror -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined \
            -Isrc -Iexamples -o "$OUT/$name" "examples/$name.c" src/*.c -lm 2>"$OUT/$name.build"; then
        bad "$name: build failed: $(head -3 "$OUT/$name.build")"
        continue
    fi
    if ! "$OUT/$name" $SCENE "$OUT/$name.ppm" >"$OUT/$name.log" 2>&1; then
        bad "$name: run failed: $(head -3 "$OUT/$name.log")"
        continue
    fi
    "$RT" $SCENE -o "$OUT/$name-ref.png" $opts --quiet
    if cmp=$("$RT" compare "$OUT/$name.ppm" "$OUT/$name-ref.png" --max-error 0); then
        ok "$name: same pixels as rt $opts ($(head -1 "$OUT/$name.log" | sed 's/^[a-z_]*: //'))"
    else
        bad "$name: differs from rt $opts: $cmp"
    fi
done
echo "examples-tests: $pass passed, $fail failed"
[ $fail -eq 0 ]
