#!/bin/sh
# Bad input and CLI errors: each tests/host/bad/NAME.nff must fail with exit
# status 2 and exactly "tests/host/bad/NAME.nff:LINE: <NAME.expect>" on stderr,
# and leave no output image behind. LINE is the one line of the file
# marked by hand with the comment "# <- error": where the entity at fault
# is (for a missing number, where the entity stops short). Then the options of rt, rt compare,
# rt receive and rt-scenec, and rt receive on good and damaged streams.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-cli}
mkdir -p "$OUT"
. tests/lib/check.sh

echo "bad-input tests: exact 'file:line: message', exit status 2, no image written, the same in every backend"
# an empty file: no line to mark, the error names line 1
: >"$OUT/empty.nff"
got=$("$RT" "$OUT/empty.nff" -o "$OUT/out.png" 2>&1 >/dev/null)
[ $? -eq 2 ] && [ "$got" = "$OUT/empty.nff:1: no 'v' viewpoint in the file" ] && ok "empty file: $got" ||
    bad "empty file: got '$got'"
for f in tests/host/bad/*.nff; do
    name=$(basename "$f" .nff)
    line=$(grep -an -- '# <- error' "$f" | cut -d: -f1)
    case "$line" in
    '' | *[!0-9]*) bad "$name: mark exactly one line with '# <- error'"; continue ;;
    esac
    want="$f:$line: $(cat "tests/host/bad/$name.expect")"
    for backend in --fixed --float --double; do
        rm -f "$OUT/out.png"
        got=$("$RT" "$f" -o "$OUT/out.png" $backend 2>&1 >/dev/null)
        status=$?
        if [ $status -eq 2 ] && [ "$got" = "$want" ] && [ ! -e "$OUT/out.png" ]; then
            ok "$name $backend: $got"
        else
            bad "$name $backend: status $status, got '$got', want '$want'"
        fi
    done
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
expect_cli "size over the maximum" 2 "--size: expected WxH from 1x1 to 4096x4096 (RT_MAX_WIDTH x RT_MAX_HEIGHT), got '10000x10000'" -- "$RT" $S -o "$OUT/out.png" --size 10000x10000
expect_cli "depth over max" 2 "--depth: expected 1..8 (RT_MAX_DEPTH: a deeper tree needs a build with -DRT_MAX_DEPTH=N)" -- "$RT" $S -o "$OUT/out.png" --depth 99
expect_cli "no output" 2 "no output file given" -- "$RT" $S
expect_cli "scene is a directory" 2 "tests/host/bad: cannot read" -- "$RT" tests/host/bad -o "$OUT/out.png"
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

# Options (getopt_long): help and version on every command, both value
# forms, '--', errors with a usage hint.
SCENEC=build/scenec/rt-scenec
version=$(sed -n 's/^#define RT_VERSION_STRING "\(.*\)"$/\1/p' include/rt_version.h)
for cmd in "$RT" "$RT compare" "$RT receive" "$SCENEC"; do
    name=$(basename "$(echo "$cmd" | cut -d' ' -f1)")$(echo "$cmd" | sed -n 's/^[^ ]* / /p')
    out=$($cmd --version 2>"$OUT/err"); status=$?
    want="$(basename "$(echo "$cmd" | cut -d' ' -f1)") $version"
    if [ $status -eq 0 ] && [ -n "$version" ] && [ "$out" = "$want" ] && [ ! -s "$OUT/err" ]; then
        ok "$name --version: '$out'"
    else
        bad "$name --version: status $status, '$out' (want '$want'), stderr '$(cat "$OUT/err")'"
    fi
    for h in --help -h; do
        out=$($cmd $h 2>"$OUT/err"); status=$?
        if [ $status -eq 0 ] && [ "${out#usage: }" != "$out" ] && [ ! -s "$OUT/err" ]; then
            ok "$name $h: usage on stdout, exit 0 ($(echo "$out" | wc -l) lines)"
        else
            bad "$name $h: status $status, stdout '$(echo "$out" | head -1)', stderr '$(cat "$OUT/err")'"
        fi
    done
    out=$($cmd --bogus-option 2>"$OUT/err"); status=$?
    if [ $status -eq 2 ] && [ -z "$out" ] && grep -q "unknown option '--bogus-option'" "$OUT/err" && grep -q -- "--help' for usage" "$OUT/err"; then
        ok "$name --bogus-option: exit 2, '$(head -1 "$OUT/err")' and a usage hint"
    else
        bad "$name --bogus-option: status $status, stderr '$(cat "$OUT/err")'"
    fi
done
"$RT" --help | grep -q -- "--stats" && "$RT" compare --help | grep -q -- "--max-error" && "$RT" receive --help | grep -q -- "--report-wait" &&
    "$RT" receive --help | grep -q -- "--report-only" &&
    "$SCENEC" --help | grep -q -- "--header" && ok "each usage text names its command's options" || bad "a usage text misses its options"

rm -f "$OUT/eq-a.png" "$OUT/eq-b.png"
if "$RT" $S -o "$OUT/eq-a.png" --size=24x16 --quiet && "$RT" --size 24x16 --quiet $S --output="$OUT/eq-b.png" &&
   "$RT" compare "$OUT/eq-a.png" "$OUT/eq-b.png" --max-error=0 >/dev/null &&
   "$RT" $S -o "$OUT/eq-c.png" --size 24x17 --quiet && ! "$RT" compare "$OUT/eq-a.png" "$OUT/eq-c.png" 2>/dev/null; then
    ok "--size=24x16 and --size 24x16 give the same 24x16 image (options before or after the scene)"
else
    bad "--size=WxH and --size WxH differ or failed"
fi
expect_cli "option value missing after =" 2 "--size: expected WxH, got ''" -- "$RT" $S -o "$OUT/out.png" --size=
expect_cli "flag given a value" 2 "option '--quiet=yes' takes no value" -- "$RT" $S -o "$OUT/out.png" --quiet=yes
expect_cli "--stats takes text or json" 2 "--stats: expected --stats, --stats=text or --stats=json, got 'xml'" -- "$RT" $S -o "$OUT/out.png" --stats=xml
"$RT" $S -o "$OUT/st.png" --size 8x8 --quiet --stats=text 2>"$OUT/st.txt" && grep -q "^eye_rays  *64$" "$OUT/st.txt" &&
    ok "--stats=text prints the statistics" || bad "--stats=text: $(cat "$OUT/st.txt")"
# --stats=json: one JSON object with the same keys and values as the text.
if "$RT" $S -o "$OUT/st.png" --size 8x8 --quiet --stats=json 2>"$OUT/st.json" &&
   python3 - "$OUT/st.txt" "$OUT/st.json" <<'PY'
import json, sys
text = dict(l.split(None, 1) for l in open(sys.argv[1]).read().splitlines())
obj = json.load(open(sys.argv[2]))
assert set(obj) == set(text), (set(obj) ^ set(text))
for k, v in obj.items():
    if k not in ("render_seconds", "threads_busy"):
        want = text[k].strip()
        assert (v == want) if isinstance(v, str) else (v == float(want)), (k, v, want)
assert obj["eye_rays"] == 64 and "sphere_tests" in obj and "bvh_nodes_visited" in obj
PY
then
    ok "--stats=json: valid JSON, the text's keys and values (eye_rays 64)"
else
    bad "--stats=json: $(head -c 300 "$OUT/st.json")"
fi

# '--' ends the options: a scene whose name starts with '-'.
cp $S "$OUT/-dash.nff"
rm -f "$OUT/dash.png"
if (cd "$OUT" && "$OLDPWD/$RT" -o dash.png --size 8x8 --quiet -- -dash.nff) && [ -f "$OUT/dash.png" ]; then
    ok "'--' ends the options: rt -o dash.png -- -dash.nff renders"
else
    bad "'--': rt -o dash.png -- -dash.nff failed"
fi
expect_cli "without '--' the name is an option" 2 "unknown option '-d'" -- sh -c "cd '$OUT' && '$PWD/$RT' -o out.png --size 8x8 -dash.nff"
expect_cli "after '--' an option is an argument" 2 "unexpected argument '--quiet'" -- "$RT" -o "$OUT/out.png" -- $S --quiet

# The output is checked before the render: a 4096x4096 double render takes
# many seconds, the refusal must not.
mkdir -p "$OUT/dir.png"
ms() { date +%s%N | cut -c1-13; }
for case in "no/such/dir/out.png|1|cannot open for writing: No such file or directory" "out.bmp|1|out.bmp: unknown image format (use .png or .ppm)" \
            "dir.png|1|dir.png: cannot open for writing: Is a directory"; do
    path="$OUT/${case%%|*}" rest=${case#*|}
    want_status=${rest%%|*} want=${rest#*|}
    t0=$(ms)
    got=$("$RT" $S -o "$path" --size 4096x4096 --double --quiet 2>&1); status=$?
    dt=$(($(ms) - t0))
    if [ $status -eq "$want_status" ] && [ $dt -lt 3000 ] && echo "$got" | grep -qF "rt: $path" && echo "$got" | grep -qF "$want" &&
       [ ! -e "$OUT/out.bmp" ]; then
        ok "output checked before the render: '$got' in $dt ms"
    else
        bad "output check: status $status, $dt ms, '$got' (want '$want')"
    fi
done

# rt receive: the board's stream (a QEMU run of rings-1, 8x8, kept as the
# receive fuzzer's seed) with noise before it, cut short, corrupted, and
# fed through a pipe that stays open after the frame.
ST=tests/fuzz/corpus-receive/rings-1-8x8.stream
"$RT" receive "$ST" -o "$OUT/rx.png" >"$OUT/rx.report" 2>"$OUT/rx.err"
if [ $? -eq 0 ] && [ ! -s "$OUT/rx.err" ] && grep -q "^instructions_per_pixel [0-9]*$" "$OUT/rx.report" &&
   grep -q "^stack_guard_intact 1$" "$OUT/rx.report"; then
    ok "receive: clean stream, $(wc -l <"$OUT/rx.report") report lines (the last after the frame end)"
else
    bad "receive: clean stream failed: $(cat "$OUT/rx.err")"
fi
{ printf 'Booting rt 1.0\r\nTest mode\r\n\000\377garbage RTF T\377\377 R'; cat "$ST"; } >"$OUT/noisy.stream"
rm -f "$OUT/noisy.png"
"$RT" receive "$OUT/noisy.stream" -o "$OUT/noisy.png" >"$OUT/noisy.report" 2>"$OUT/noisy.err"; status=$?
if [ $status -eq 0 ] && "$RT" compare "$OUT/noisy.png" "$OUT/rx.png" --max-error 0 >/dev/null &&
   cmp -s "$OUT/noisy.report" "$OUT/rx.report" && grep -q "skipped 46 byte(s) before the frame header" "$OUT/noisy.err"; then
    ok "receive: noise before the frame skipped: $(cat "$OUT/noisy.err" | sed 's/.*: note: //'), same image and report"
else
    bad "receive with leading noise: status $status, $(cat "$OUT/noisy.err")"
fi
n=$(wc -c <"$ST")
head -c $((n / 3)) "$ST" >"$OUT/cut.stream"
expect_cli "receive: truncated frame" 2 "stream truncated" -- "$RT" receive "$OUT/cut.stream" -o "$OUT/out.png"
python3 -c "import sys; d=bytearray(open(sys.argv[1],'rb').read()); d[40]^=0x01; open(sys.argv[2],'wb').write(d)" "$ST" "$OUT/flip.stream"
expect_cli "receive: one bit flipped in a band" 2 "band checksum mismatch" -- "$RT" receive "$OUT/flip.stream" -o "$OUT/out.png"
python3 -c "import sys; d=bytearray(open(sys.argv[1],'rb').read()); d[4]=7; open(sys.argv[2],'wb').write(d)" "$ST" "$OUT/hdr.stream"
expect_cli "receive: bad frame header" 2 "bad frame header (format 7, 8x8)" -- "$RT" receive "$OUT/hdr.stream" -o "$OUT/out.png"
expect_cli "receive: no frame" 2 "no frame in the stream" -- sh -c "printf 'just boot text' | '$RT' receive - -o '$OUT/out.png'"
# a capture that starts mid-frame (receive started after the reset): the
# report lines are still printed, then the error and the hint to start first
tail -c +30 "$ST" >"$OUT/midframe.stream"
rm -f "$OUT/out.png"
"$RT" receive "$OUT/midframe.stream" -o "$OUT/out.png" >"$OUT/midframe.report" 2>"$OUT/midframe.err"; status=$?
if [ $status -eq 2 ] && [ ! -e "$OUT/out.png" ] && grep -q "no frame in the stream" "$OUT/midframe.err" &&
   grep -q "hint: .* but no frame header: start rt receive (or the capture) before resetting or powering the board" \
       "$OUT/midframe.err" && [ -s "$OUT/midframe.report" ] &&
   [ "$(tail -1 "$OUT/midframe.report")" = "$(tail -1 "$OUT/rx.report")" ] &&
   ! printf '' | "$RT" receive - -o "$OUT/out.png" 2>&1 | grep -q hint; then
    ok "receive: a stream cut mid-frame: $(wc -l <"$OUT/midframe.report") report line(s), then the hint: $(sed -n 's/.*: hint: //p' "$OUT/midframe.err" | cut -c1-60)... (no hint for an empty stream)"
else
    bad "receive from mid-frame: status $status, $(cat "$OUT/midframe.err")"
fi
expect_cli "receive: output checked first" 1 "out.gif: unknown image format" -- "$RT" receive "$ST" -o "$OUT/out.gif"
# the writer keeps the pipe open 6 s after the stream; rt must return at
# the frame end plus the report's idle wait (0.5 s), image and report in
rm -f "$OUT/pipe.png"
t0=$(ms)
{ cat "$ST"; sleep 6; } | { "$RT" receive -o "$OUT/pipe.png" >"$OUT/pipe.report" 2>&1; echo $? >"$OUT/pipe.status"; ms >"$OUT/pipe.end"; }
dt=$(($(cat "$OUT/pipe.end") - t0))
if [ "$(cat "$OUT/pipe.status")" = 0 ] && [ $dt -lt 4500 ] && cmp -s "$OUT/pipe.report" "$OUT/rx.report" &&
   "$RT" compare "$OUT/pipe.png" "$OUT/rx.png" --max-error 0 >/dev/null; then
    ok "receive from a pipe kept open: returned after $dt ms with the image and all $(wc -l <"$OUT/pipe.report") report lines"
else
    bad "receive from a pipe kept open: status $(cat "$OUT/pipe.status"), $dt ms: $(head -3 "$OUT/pipe.report")"
fi

# rt receive --report-only: report lines and no frame (the UART of a board
# that draws on its own panel: an lm3s6965evb run, kept as a fuzz seed).
RS=tests/fuzz/corpus-receive/lm3s6965evb-reports.stream
out=$("$RT" receive --report-only "$RS" 2>"$OUT/ro.err"); status=$?
if [ $status -eq 0 ] && [ ! -s "$OUT/ro.err" ] && [ "$(echo "$out" | head -1)" = "frame_width 128" ] &&
   [ "$(echo "$out" | tail -1)" = "drawn 1" ] && [ "$(echo "$out" | wc -l)" -ge 10 ]; then
    ok "receive --report-only: $(echo "$out" | wc -l) report lines, no image"
else
    bad "receive --report-only: status $status, '$(echo "$out" | head -2)', $(cat "$OUT/ro.err")"
fi
out2=$({ printf 'boot\r\n\000T\377'; cat "$RS"; } | "$RT" receive --report-only 2>"$OUT/ro.err"); status=$?
[ $status -eq 0 ] && [ "$out2" = "$out" ] && grep -q "skipped 9 byte(s) before the first report line" "$OUT/ro.err" &&
    ok "receive --report-only: noise before the first line skipped, same lines" ||
    bad "receive --report-only with leading noise: status $status, $(cat "$OUT/ro.err")"
n=$(wc -c <"$RS")
head -c $((n - 3)) "$RS" >"$OUT/ro-cut.stream"
expect_cli "receive --report-only: truncated line" 2 "stream truncated in a report line" -- "$RT" receive --report-only "$OUT/ro-cut.stream"
{ cat "$RS"; printf 'x'; } >"$OUT/ro-junk.stream"
expect_cli "receive --report-only: a stray byte after the lines" 2 "unexpected byte 0x78 after a report line" -- "$RT" receive --report-only "$OUT/ro-junk.stream"
{ head -c 36 "$RS"; printf 'T\003\000a\001b'; } >"$OUT/ro-bin.stream"
expect_cli "receive --report-only: unprintable text" 2 "not printable" -- "$RT" receive --report-only "$OUT/ro-bin.stream"
expect_cli "receive --report-only: a frame stream" 2 "a frame header in a stream of report lines only" -- "$RT" receive --report-only "$ST"
expect_cli "receive --report-only: no line" 2 "no report line in the stream" -- sh -c "printf 'just boot text' | '$RT' receive --report-only"
expect_cli "receive --report-only with -o" 2 "--report-only writes no image" -- "$RT" receive --report-only "$RS" -o "$OUT/out.png"
# from a pipe kept open 4 s after the lines: back after the idle wait
t0=$(ms)
{ cat "$RS"; sleep 4; } | { "$RT" receive --report-only >"$OUT/ro-pipe.report" 2>&1; echo $? >"$OUT/ro-pipe.status"; ms >"$OUT/ro-pipe.end"; }
dt=$(($(cat "$OUT/ro-pipe.end") - t0))
if [ "$(cat "$OUT/ro-pipe.status")" = 0 ] && [ $dt -lt 3000 ] && [ "$(cat "$OUT/ro-pipe.report")" = "$out" ]; then
    ok "receive --report-only from a pipe kept open: returned after $dt ms with all $(wc -l <"$OUT/ro-pipe.report") lines"
else
    bad "receive --report-only from a pipe kept open: status $(cat "$OUT/ro-pipe.status"), $dt ms: $(head -3 "$OUT/ro-pipe.report")"
fi

# Inputs the fuzzer once broke: must now load and render, or fail cleanly.
for f in tests/fuzz/found/*.nff; do
    msg=$("$RT" "$f" -o "$OUT/found.png" --size 16x16 --quiet 2>&1); status=$?
    if [ $status -eq 0 ] || { [ $status -eq 2 ] && echo "$msg" | grep -q "^$f:[0-9]*: "; }; then
        ok "fuzz regression $(basename "$f"): status $status"
    else
        bad "fuzz regression $(basename "$f"): status $status: $msg"
    fi
done

# Capacities: every overflow names its capacity and how to raise it, and
# the scene compiler (board capacities) says it the same way as rt.
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

# --viewport X,Y,W,H: the output is that rectangle of the frame, pixel for
# pixel (normal and SPD mode; the crop of the whole frame is cut here).
crop_ppm() { python3 tests/lib/ppm.py crop "$@"; } # IN X Y W H OUT
for mode in "" --spd; do
    "$RT" scenes/spd/balls-1.nff -o "$OUT/vp-full.ppm" --size 41x29 $mode --quiet
    for vp in 0,0,1,1 40,28,1,1 7,3,13,11 0,5,41,7 20,0,1,29; do
        set -- $(echo $vp | tr , ' ')
        crop_ppm "$OUT/vp-full.ppm" "$@" "$OUT/vp-crop.ppm"
        if "$RT" scenes/spd/balls-1.nff -o "$OUT/vp.ppm" --size 41x29 $mode --viewport $vp --quiet &&
           cmp -s "$OUT/vp.ppm" "$OUT/vp-crop.ppm"; then
            ok "--viewport $vp ${mode:-normal}: byte-identical to the crop of the whole frame"
        else
            bad "--viewport $vp ${mode:-normal}: differs from the crop of the whole frame"
        fi
    done
done
expect_cli "viewport outside the frame" 2 "viewport outside the frame" -- "$RT" $S -o "$OUT/out.png" --size 8x8 --viewport 4,4,5,1
expect_cli "viewport malformed" 2 "--viewport: expected X,Y,W,H" -- "$RT" $S -o "$OUT/out.png" --viewport 1,2,3

summary cli-tests
