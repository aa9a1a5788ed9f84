#!/bin/sh
# Bad input and CLI errors: each tests/bad/NAME.nff must fail with exit
# status 2 and exactly "tests/bad/NAME.nff:<NAME.expect>" on stderr, and
# leave no output image behind.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-cli}
mkdir -p "$OUT"
pass=0 fail=0
ok() { pass=$((pass + 1)); printf '  ok    %s\n' "$1"; }
bad() { fail=$((fail + 1)); printf '  FAIL  %s\n' "$1"; }

echo "bad-input tests: exact 'file:line: message', exit status 2, no image written"
for f in tests/bad/*.nff; do
    name=$(basename "$f" .nff)
    want="$f:$(cat "tests/bad/$name.expect")"
    rm -f "$OUT/out.png"
    got=$("$RT" "$f" -o "$OUT/out.png" 2>&1 >/dev/null)
    status=$?
    if [ $status -eq 2 ] && [ "$got" = "$want" ] && [ ! -e "$OUT/out.png" ]; then
        ok "$name: $got"
    else
        bad "$name: status $status, got '$got', want '$want'"
    fi
done

# expect_cli NAME STATUS MESSAGE-SUBSTRING -- command...
expect_cli() {
    name=$1 want_status=$2 want_msg=$3
    shift 4
    rm -f "$OUT/out.png"
    got=$("$@" 2>&1 >/dev/null)
    status=$?
    case "$got" in
    *"$want_msg"*) matched=1 ;;
    *) matched=0 ;;
    esac
    if [ $status -eq "$want_status" ] && [ $matched -eq 1 ] && [ ! -e "$OUT/out.png" ]; then
        ok "$name: $got"
    else
        bad "$name: status $status (want $want_status), got '$got', want '*$want_msg*'"
    fi
}
S=scenes/spd/tetra-1.nff
expect_cli "unknown flag" 2 "unknown option '--bogus'" -- "$RT" $S -o "$OUT/out.png" --bogus
expect_cli "missing value" 2 "--depth needs a number" -- "$RT" $S -o "$OUT/out.png" --depth
expect_cli "bad size" 2 "--size: expected WxH" -- "$RT" $S -o "$OUT/out.png" --size 12
expect_cli "depth over max" 2 "--depth: expected 1..RT_MAX_DEPTH" -- "$RT" $S -o "$OUT/out.png" --depth 99
expect_cli "no output" 2 "no output file given" -- "$RT" $S
expect_cli "scene is a directory" 2 "tests/bad: cannot read" -- "$RT" tests/bad -o "$OUT/out.png"
expect_cli "missing scene" 2 "cannot open" -- "$RT" "$OUT/nope.nff" -o "$OUT/out.png"
expect_cli "unknown extension" 1 "unknown image format" -- "$RT" $S -o "$OUT/out.jpg" --size 8x8
expect_cli "unwritable path" 1 "cannot open" -- "$RT" $S -o "$OUT/no/such/dir/out.png" --size 8x8
[ ! -e "$OUT/out.jpg" ] && ok "unknown extension leaves no file" || bad "unknown extension left $OUT/out.jpg"
expect_cli "compare size mismatch" 2 "differ" -- sh -c "'$RT' $S -o '$OUT/a.png' --size 8x8 && '$RT' $S -o '$OUT/b.png' --size 8x9 && '$RT' compare '$OUT/a.png' '$OUT/b.png'"
expect_cli "compare threshold" 1 "psnr" -- sh -c "'$RT' $S -o '$OUT/a.png' --size 32x32 && '$RT' scenes/spd/balls-1.nff -o '$OUT/b.png' --size 32x32 && '$RT' compare '$OUT/a.png' '$OUT/b.png' --psnr-min 40 1>&2"
# A 10 MB line (one huge number): a clear error, no crash or hang.
big="$OUT/ten-mb-line.nff"
{ printf 'v\nfrom 0 -5 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 8 8\nf 1 1 1 1 0 1 0 1\ns '
  head -c 10000000 /dev/zero | tr '\0' '7'; printf ' 0 0 1\n'; } >"$big"
expect_cli "10 MB line" 2 "ten-mb-line.nff:9: s: scene too large for the fixed range" -- "$RT" "$big" -o "$OUT/out.png"

# Inputs the fuzzer once broke: must now load and render, or fail cleanly.
for f in tests/fuzz-found/*.nff; do
    msg=$("$RT" "$f" -o "$OUT/found.png" --size 16x16 --quiet 2>&1); status=$?
    if [ $status -eq 0 ] || { [ $status -eq 2 ] && echo "$msg" | grep -q "^$f:[0-9]*: "; }; then
        ok "fuzz regression $(basename "$f"): status $status"
    else
        bad "fuzz regression $(basename "$f"): status $status: $msg"
    fi
done

# Capacities: every overflow names its capacity and how to raise it, and
# the scene compiler (board capacities) says it the same way as rt.
SCENEC=build/scenec/rt-scenec
capacity_case() { # name, scene body generator output file
    f="$OUT/cap-$1.nff"
    a=$("$RT" "$f" -o "$OUT/out.png" 2>&1 >/dev/null)
    b=$("$SCENEC" "$f" -o "$OUT/cap.c" 2>&1 >/dev/null)
    pat="^$f:[0-9]*: too many $2: capacity $3 = [0-9]* (raise it with -D$3=N)\$"
    if echo "$a" | grep -q "$pat" && echo "$b" | grep -q "$pat"; then
        ok "capacity $3: rt '$(echo "$a" | sed "s|$OUT/||")', scene compiler '$(echo "$b" | sed "s|$OUT/||")'"
    else
        bad "capacity $3: rt '$a', scene compiler '$b'"
    fi
}
hdr='v\nfrom 0 -30 0\nat 0 0 0\nup 0 0 1\nangle 45\nhither 1\nresolution 8 8\nf 1 1 1 1 0 1 0 1\n'
{ printf "$hdr"; for i in $(seq 40); do echo "l $i 0 5"; done; } >"$OUT/cap-lights.nff"
capacity_case lights lights RT_MAX_LIGHTS
{ printf "$hdr"; for i in $(seq 1100); do echo "f 1 1 1 $i 0 1 0 1"; done; } >"$OUT/cap-materials.nff"
capacity_case materials materials RT_MAX_MATERIALS
{ printf "$hdr"; for i in $(seq 70); do echo "box $i 0 0 $i.5 1 1"; done; } >"$OUT/cap-shapes.nff"
capacity_case shapes shapes RT_MAX_SHAPES
{ printf "$hdr"; for i in $(seq 60); do printf 'transform\ntranslate %s 0 0\nbox 0 0 0 1 1 1\nend\n' "$i"; done; } >"$OUT/cap-xforms.nff"
capacity_case xforms "transforms" RT_MAX_XFORMS
{ printf "$hdr"; for i in $(seq 10); do echo transform; done; echo "box 0 0 0 1 1 1"; for i in $(seq 10); do echo end; done; } >"$OUT/cap-blocks.nff"
capacity_case blocks "nested blocks" RT_MAX_BLOCK_DEPTH

echo "cli-tests: $pass passed, $fail failed"
[ $fail -eq 0 ]
