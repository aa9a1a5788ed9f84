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
expect_cli "unknown extension" 1 "unknown output format" -- "$RT" $S -o "$OUT/out.jpg" --size 8x8
expect_cli "unwritable path" 1 "cannot open" -- "$RT" $S -o "$OUT/no/such/dir/out.png" --size 8x8
[ ! -e "$OUT/out.jpg" ] && ok "unknown extension leaves no file" || bad "unknown extension left $OUT/out.jpg"
expect_cli "compare size mismatch" 2 "differ" -- sh -c "'$RT' $S -o '$OUT/a.png' --size 8x8 && '$RT' $S -o '$OUT/b.png' --size 8x9 && '$RT' compare '$OUT/a.png' '$OUT/b.png'"
expect_cli "compare threshold" 1 "psnr" -- sh -c "'$RT' $S -o '$OUT/a.png' --size 32x32 && '$RT' scenes/spd/balls-1.nff -o '$OUT/b.png' --size 32x32 && '$RT' compare '$OUT/a.png' '$OUT/b.png' --psnr-min 40 1>&2"
echo "cli-tests: $pass passed, $fail failed"
[ $fail -eq 0 ]
