#!/bin/sh
# The numeric configurations (CONFIGS in the Makefile, make -s
# print-configs; their floors: docs/accuracy.md's table, read here):
#  - every configuration has a row in the table, and every row is one;
#    make stops at a CONFIG that is not one;
#  - each one's rt (build/cfg-NAME/rt, which make test builds) renders
#    the business-card scene, whose shadow rays skip spheres by the light
#    cones, within the row's floor of the exact build (PSNR, share of
#    pixels off by more than 8/255);
#  - each one's firmware on mps2-an385 draws that image byte for byte;
#  - make bench-quick's measurement (bench/run_bench.py --quick) at that
#    size, on that scene, into $OUT/bench: it runs, and its table has a
#    row for each of its configurations (it shares the firmware above).
RT=${1:-build/asan/rt}
OUT=build/test-configs
. tests/boards/board-case.sh
SCENE=scenes/bench/card.nff
SIZE=48x48
# the variables bench/run_bench.py's board column builds with, so that
# it finds the firmware built here
VARS="BOARD=mps2-an385 BACKEND=fixed SCENE=$SCENE SIZE=$SIZE DEPTH=5 AA=0"

configs=$(make -s print-configs)
awk -F'|' '/^\| `[a-z0-9]+` \|/ { gsub(/[` ]/, "", $2); print $2, $4 }' docs/accuracy.md |
    sed 's/ *dB *\/ */ /; s/% *$//' >"$OUT/floors.txt"
rows=$(awk '{ print $1 }' "$OUT/floors.txt" | tr '\n' ' ')
if [ -n "$configs" ] && [ "$(echo $configs)" = "$(echo $rows)" ]; then
    ok "docs/accuracy.md's table has a row for each configuration, in the Makefile's order: $configs"
else
    bad "the Makefile's configurations '$configs' and docs/accuracy.md's rows '$rows' differ"
fi

# a name that is not one stops make with the list
msg=$(make -s print-fwdir CONFIG=q24 2>&1) && bad "make CONFIG=q24 went on: $msg" ||
    case $msg in
        *"CONFIG=q24 is not a numeric configuration: $configs"*) ok "make CONFIG=q24: ${msg#*: }" ;;
        *) bad "make CONFIG=q24: $msg" ;;
    esac

"$RT" "$SCENE" --double --size $SIZE --depth 5 -o "$OUT/exact.png" --quiet ||
    bad "the exact build does not render $SCENE"
# floor NAME IMAGE DB PERCENT: IMAGE against the exact build
floor() {
    if cmp=$("$RT" compare "$2" "$OUT/exact.png" --psnr-min "$3" --max-over8 "$4"); then
        ok "$1: $cmp (floor $3 dB, $4%)"
    else
        bad "$1 below its floor ($3 dB, $4%): $cmp"
    fi
}
for c in $configs; do
    set -- $(awk -v c="$c" '$1 == c { print $2, $3 }' "$OUT/floors.txt")
    db=${1:-100} pct=${2:-0}
    if ! [ -x "build/cfg-$c/rt" ]; then
        bad "$c: no build/cfg-$c/rt (make test builds it)"
        continue
    fi
    "build/cfg-$c/rt" "$SCENE" --fixed --size $SIZE --depth 5 --threads 1 -o "$OUT/$c-host.png" --quiet ||
        bad "$c: build/cfg-$c/rt does not render $SCENE"
    floor "$c on the host" "$OUT/$c-host.png" "$db" "$pct"
    board_build "$c" $VARS CONFIG=$c && board_run "$c" $VARS CONFIG=$c || continue
    if cmp=$("$RT" compare "$OUT/$c-board.png" "$OUT/$c-host.png" --max-error 0); then
        ok "$c: mps2-an385 == build/cfg-$c/rt ($cmp)"
    else
        bad "$c: mps2-an385 and build/cfg-$c/rt differ: $cmp"
    fi
done

# bench-quick at the size above (one timed run; its results in $OUT/bench)
if python3 bench/run_bench.py --quick --scenes card --size $SIZE --out "$OUT/bench" >"$OUT/bench.log" 2>&1; then
    missing=
    for c in $(sed -n 's/^QUICK_CONFIGS = \[\(.*\)\]/\1/p' bench/run_bench.py | tr -d '",'); do
        grep -q "^| ${c}[ |].* dB | [0-9]" "$OUT/bench/results-quick.md" || missing="$missing $c"
    done
    [ -z "$missing" ] && ok "bench/run_bench.py --quick at $SIZE: $(tail -1 "$OUT/bench.log")" ||
        bad "bench/run_bench.py --quick at $SIZE: no row for$missing in $OUT/bench/results-quick.md"
else
    bad "bench/run_bench.py --quick at $SIZE failed: $(tail -3 "$OUT/bench.log")"
fi
summary configs-tests
