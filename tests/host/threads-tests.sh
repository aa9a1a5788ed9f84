#!/bin/sh
# rt --threads N (app/rt/bands.c: one thread renders the frame or
# viewport in one call of the core; two or more start on equal runs of
# lines and split what is left when one runs out): the same image, byte
# for byte, for N = 1, 2 and 3,
#   - on every scene of scenes/ and scenes/spd/ at 48x40, the backend and
#     mode rotating over fixed/double/float and normal, --spd, --viewport,
#     --format rgb565 and --spd with --viewport (3 and 5 rotations: the
#     first 15 scenes give every pair), and adaptive and uniform
#     anti-aliasing on six scenes (viewports and packed formats too);
#   - --stats (text and JSON): `threads` is N and `threads_busy` a share;
#     in normal mode eye_rays is W*H and every ray count the same for all
#     N (BVH nodes and intersection tests depend on where runs start,
#     each with the core's shadow-ray caches afresh); in SPD mode one
#     thread traces (W+1)*(H+1) corners and N threads whole rows of W+1
#     more, at least N - 1 (one per run start after the first);
#     the stress build's saturations the same for all N;
#   - the progress indicator (stderr on a terminal) rises to 100%;
#   - bad --threads values fail with exit 2 and a clear message;
#   - with the ThreadSanitizer build (build/tsan/rt, if built): four
#     threads, each backend and SPD mode, and the fixed build's split
#     decisions recorded and replayed (--same-samples: the threads write
#     and read the pixels of their own lines), and no report (the core's
#     workers share no written byte).
# No wall-clock time is asserted.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-threads}
TSAN=${TSAN:-build/tsan/rt}
STRESS=${STRESS:-build/stress/rt}
mkdir -p "$OUT"
. tests/lib/check.sh
W=48 H=40
max=$(sed -n 's/.*-DRT_MAX_WORKERS=\([0-9]*\).*/\1/p' Makefile | head -1)

# same_for_threads NAME ARGS...: threads 1, 2, 3 give one image
same_for_threads() {
    name=$1; shift
    for n in 1 2 3; do
        rm -f "$OUT/t$n.ppm"
        if ! "$RT" "$@" -o "$OUT/t$n.ppm" --quiet --threads $n 2>"$OUT/t.err"; then
            bad "$name: --threads $n failed: $(cat "$OUT/t.err")"
            return
        fi
    done
    if cmp -s "$OUT/t1.ppm" "$OUT/t2.ppm" && cmp -s "$OUT/t1.ppm" "$OUT/t3.ppm"; then
        ok "$name: --threads 1, 2, 3 byte-identical ($(wc -c <"$OUT/t1.ppm") bytes)"
    else
        bad "$name: images differ between --threads 1, 2, 3"
    fi
}

echo "threads tests: --threads 1, 2, 3 give the same image and ray counts"
modes="normal spd viewport rgb565 spd-viewport"
mode_args() {
    case $1 in
    normal) ;;
    spd) echo --spd ;;
    viewport) echo --viewport 5,3,37,29 ;;
    rgb565) echo --format rgb565 ;;
    spd-viewport) echo --spd --viewport 0,17,48,20 ;;
    esac
}
i=0
for f in scenes/*.nff scenes/spd/*.nff; do
    b=$(echo "fixed double float" | cut -d' ' -f$((i % 3 + 1)))
    m=$(echo $modes | cut -d' ' -f$((i % 5 + 1)))
    same_for_threads "$(basename "$f" .nff) --$b $m" "$f" --size ${W}x$H --$b $(mode_args $m)
    i=$((i + 1))
done

# Anti-aliasing: adaptive (corner rows traced again at each run start:
# the same pixels) and uniform, with a viewport and a packed format.
i=0
for f in scenes/showpiece.nff scenes/csg.nff scenes/spd/balls-1.nff scenes/spd/rings-1.nff scenes/spd/teapot-1.nff \
         scenes/spd/tetra-2.nff; do
    b=$(echo "fixed double float" | cut -d' ' -f$((i % 3 + 1)))
    for a in "--aa 3" "--aa 2,20 --viewport 5,3,37,29" "--spp 2 --format rgb565" "--aa 4,4 --format l4 --viewport 0,9,48,20"; do
        same_for_threads "$(basename "$f" .nff) --$b $a" "$f" --size ${W}x$H --$b $a
    done
    i=$((i + 1))
done

# --stats (render_seconds and threads_busy, times, left out)
counter() { sed -n "s/^ *\"*$1\"*[: ] *\([0-9]*\),*\$/\1/p" "$2"; }
stats_case() { # NAME FORMAT SPD(0/1) W H ARGS...
    name=$1 fmt=$2 spd=$3 w=$4 h=$5; shift 5
    for n in 1 2 3; do
        if ! "$RT" "$@" -o "$OUT/st.ppm" --quiet --threads $n --stats=$fmt 2>"$OUT/st$n.$fmt"; then
            bad "$name --stats=$fmt: --threads $n failed: $(cat "$OUT/st$n.$fmt")"
            return
        fi
        th=$(counter threads "$OUT/st$n.$fmt")
        busy=$(sed -n 's/^ *"*threads_busy"*[: ] *\([0-9.]*\),*$/\1/p' "$OUT/st$n.$fmt")
        if [ "$th" != $n ] || ! awk -v b="$busy" 'BEGIN { exit !(b > 0 && b <= 1) }' ||
           ! grep -q "_tests" "$OUT/st$n.$fmt"; then
            bad "$name --stats=$fmt --threads $n: threads '$th', threads_busy '$busy' (want $n and a share in (0, 1]), or no *_tests"
            return
        fi
    done
    e1=$(counter eye_rays "$OUT/st1.$fmt") e2=$(counter eye_rays "$OUT/st2.$fmt") e3=$(counter eye_rays "$OUT/st3.$fmt")
    if [ "$spd" = 1 ]; then
        # one more row of W+1 corners per run start after the first: at
        # least N - 1 of them, at most one a line
        grid=$(((w + 1) * (h + 1)))
        if [ "$e1" = $grid ] && awk -v e2="$e2" -v e3="$e3" -v g=$grid -v r=$((w + 1)) -v h=$h 'BEGIN {
               k2 = (e2 - g) / r; k3 = (e3 - g) / r
               exit !(k2 == int(k2) && k3 == int(k3) && k2 >= 1 && k3 >= 2 && k2 <= h - 1 && k3 <= h - 1) }'; then
            ok "$name --stats=$fmt: eye_rays $e1 (1 thread), $e2 and $e3 (2, 3: $(((e2 - grid) / (w + 1))) and $(((e3 - grid) / (w + 1))) rows of corners again)"
        else
            bad "$name --stats=$fmt: eye_rays $e1, $e2, $e3 (want $grid, then whole extra rows of $((w + 1)), at least N - 1)"
        fi
        return
    fi
    same_rays=1
    for k in eye_rays eye_hits reflect_rays refract_rays shadow_rays; do
        v=$(counter $k "$OUT/st1.$fmt")
        [ -n "$v" ] && [ "$v" = "$(counter $k "$OUT/st2.$fmt")" ] && [ "$v" = "$(counter $k "$OUT/st3.$fmt")" ] || same_rays=0
    done
    if [ "$e1" = $((w * h)) ] && [ $same_rays = 1 ]; then
        ok "$name --stats=$fmt: eye_rays $e1 and every ray count the same for 1, 2, 3 threads"
    else
        bad "$name --stats=$fmt: eye_rays $e1 (want $((w * h))), ray counts the same for 1, 2, 3: $same_rays"
    fi
}
for f in scenes/showpiece.nff scenes/spd/rings-1.nff scenes/spd/teapot-1.nff; do
    s=$(basename "$f" .nff)
    stats_case "$s" text 0 $W $H "$f" --size ${W}x$H
    stats_case "$s --spd" text 1 $W $H "$f" --size ${W}x$H --spd
done
stats_case "balls-2 --double" json 0 $W $H scenes/spd/balls-2.nff --size ${W}x$H --double
stats_case "balls-2 --float --spd" json 1 $W $H scenes/spd/balls-2.nff --size ${W}x$H --float --spd
stats_case "tetra-2 --spd --viewport 3,20,40,19" text 1 40 19 scenes/spd/tetra-2.nff --size ${W}x$H --spd --viewport 3,20,40,19

# The stress build counts fixed-point saturations in one counter for all
# threads (an atomic add, src/numeric/fx.h): the same total for every N.
if [ -x "$STRESS" ]; then
    for n in 1 2 3; do
        "$STRESS" scenes/showpiece.nff -o "$OUT/sat.ppm" --size ${W}x$H --quiet --threads $n --stats 2>"$OUT/sat$n.txt"
    done
    s1=$(sed -n 's/^saturations  *//p' "$OUT/sat1.txt")
    if [ -n "$s1" ] && [ "$s1" -gt 0 ] && [ "$s1" = "$(sed -n 's/^saturations  *//p' "$OUT/sat2.txt")" ] &&
       [ "$s1" = "$(sed -n 's/^saturations  *//p' "$OUT/sat3.txt")" ]; then
        ok "stress build: showpiece saturations $s1 for --threads 1, 2, 3"
    else
        bad "stress build: saturations differ or missing: $(grep -h saturations "$OUT"/sat?.txt | tr '\n' ' ')"
    fi
else
    echo "  (no $STRESS: saturation count not checked)"
fi

# The progress indicator on a terminal: the lines of all threads, never
# going back, ending at 100%.
if msg=$(python3 - "$RT" "$OUT/pr.ppm" <<'PY'
import os, pty, re, subprocess, sys
master, slave = pty.openpty()
p = subprocess.Popen([sys.argv[1], "scenes/spd/balls-1.nff", "-o", sys.argv[2], "--size", "64x200", "--threads", "3"],
                     stderr=slave, stdout=subprocess.DEVNULL)
os.close(slave)
data = b""
while True:
    try:
        chunk = os.read(master, 4096)
    except OSError:
        break
    if not chunk:
        break
    data += chunk
assert p.wait() == 0, "exit status %d" % p.returncode
pcts = [int(x) for x in re.findall(rb"rendering: *(\d+)%", data)]
assert pcts and pcts == sorted(pcts) and pcts[-1] == 100, pcts
assert len(set(pcts)) == len(pcts), pcts
print("%d updates: %s" % (len(pcts), " ".join(map(str, pcts))))
PY
); then
    ok "progress on a terminal with --threads 3 rises to 100%: $msg"
else
    bad "progress indicator: $msg"
fi

# Bad values: exit 2, the range in the message, no image.
expect_bad() { # NAME MESSAGE ARGS...
    name=$1 want=$2; shift 2
    rm -f "$OUT/bad.png"
    got=$("$RT" scenes/spd/tetra-1.nff -o "$OUT/bad.png" --size 8x8 "$@" 2>&1 >/dev/null); status=$?
    case "$got" in
    *"$want"*) matched=1 ;;
    *) matched=0 ;;
    esac
    if [ $status -eq 2 ] && [ $matched -eq 1 ] && [ ! -e "$OUT/bad.png" ]; then
        ok "$name: $(echo "$got" | head -1)"
    else
        bad "$name: status $status, '$got' (want '*$want*')"
    fi
}
for v in 0 -1 $((max + 1)) 1000000000000 x 2x ""; do
    expect_bad "--threads '$v'" "rt: --threads: expected a number from 1 to $max, got '$v'" --threads="$v"
done
expect_bad "--threads without a value" "--threads needs a number" --threads
out=$("$RT" scenes/spd/tetra-1.nff -o "$OUT/max.ppm" --size 8x8 --quiet --threads $max 2>&1) &&
    ok "--threads $max (the cap; one band, so one thread): renders" || bad "--threads $max: $out"
"$RT" --help | grep -q -- "--threads N" && ok "--help names --threads" || bad "--help does not name --threads"

# ThreadSanitizer: nothing the threads write is shared.
if [ -x "$TSAN" ]; then
    for args in "--fixed" "--double" "--float" "--fixed --spd" "--fixed --format l4 --viewport 3,5,41,30" "--fixed --aa 3" \
                "--float --spp 2" "--double --aa 3 --same-samples fixed"; do
        for f in scenes/showpiece.nff scenes/spd/rings-1.nff; do
            s=$(basename "$f" .nff)
            "$TSAN" "$f" -o "$OUT/tsan.ppm" --size ${W}x$H --quiet --threads 4 $args 2>"$OUT/tsan.err"
            status=$?
            if [ $status -eq 0 ] && ! grep -q "ThreadSanitizer" "$OUT/tsan.err"; then
                ok "ThreadSanitizer, $s $args --threads 4: no report"
            else
                bad "ThreadSanitizer, $s $args: status $status: $(grep -m1 -A4 ThreadSanitizer "$OUT/tsan.err")"
            fi
        done
    done
else
    echo "  (no $TSAN: ThreadSanitizer run skipped; make $TSAN)"
fi

summary threads-tests
