# board-case.sh - the steps the board suites share: build a firmware, run
# it on its board, compare what it drew and reported with rt's. Sourced
# with RT (the host rt) and OUT (the suite's folder) set: it makes OUT and
# sources tests/lib/check.sh. NAME names a case's files in $OUT.
#   board_build NAME MAKE-VARS...  make firmware (log $OUT/NAME.build)
#   board_run NAME MAKE-VARS...    make board-run (image $OUT/NAME-board.png,
#                                  report $OUT/NAME.report)
#       each counts one failure naming the step, and returns 1, when the
#       step fails; nothing when it passes (the checks below count that)
#   board_fw NAME MAKE-VARS...     both, counting nothing: for a caller
#                                  that counts its own check (1: either failed)
#   board_vs_host NAME WHAT NOTE RT-ARGS...
#       render the host's image, rt RT-ARGS --threads 1 --quiet --stats
#       (one thread: the frame in one call of the core, as on the board;
#       with more each band's caches start afresh and the counts differ),
#       and count two checks: the board's image equal to it byte for byte
#       ("board == host WHAT (figures), NOTE"), and the report's counters
#       equal to rt --stats (only the ray counts on a frame split between
#       cores: each band is a render of its own)
#   report_val KEY REPORT          the value of KEY in a report (its last)
mkdir -p "$OUT"
. tests/lib/check.sh
# the two steps, quiet: the make's status
make_fw() {
    _bc_n=$1
    shift
    make -s -j2 firmware "$@" >"$OUT/$_bc_n.build" 2>&1
}
run_fw() {
    _bc_n=$1
    shift
    rm -f "$OUT/$_bc_n-board.png"
    make -s board-run "$@" RUN_OUT="$OUT/$_bc_n-board.png" RUN_RT="$RT" >"$OUT/$_bc_n.report" 2>&1
}
board_fw() { make_fw "$@" && run_fw "$@"; }
board_build() {
    make_fw "$@" && return 0
    bad "$1: firmware build failed: $(tail -3 "$OUT/$1.build")"
    return 1
}
board_run() {
    run_fw "$@" && return 0
    bad "$1: board run failed: $(tail -3 "$OUT/$1.report")"
    return 1
}
board_vs_host() {
    _bc_n=$1 _bc_what=$2 _bc_note=$3
    shift 3
    "$RT" "$@" -o "$OUT/$_bc_n-host.png" --threads 1 --quiet --stats 2>"$OUT/$_bc_n-host.stats"
    if _bc_cmp=$("$RT" compare "$OUT/$_bc_n-board.png" "$OUT/$_bc_n-host.png" --max-error 0); then
        ok "$_bc_n: board == host $_bc_what ($_bc_cmp), $_bc_note"
    else
        bad "$_bc_n: board and host $_bc_what differ: $_bc_cmp"
    fi
    _bc_only=$(awk '$1 == "cores" && $2 > 1 { print "rays" }' "$OUT/$_bc_n.report")
    if _bc_same=$(sh tests/boards/same-counters.sh "$OUT/$_bc_n-host.stats" "$OUT/$_bc_n.report" $_bc_only); then
        ok "$_bc_n: board report and rt --stats: $_bc_same"
    else
        bad "$_bc_n: board report and rt --stats: $_bc_same"
    fi
}
report_val() { awk -v k="$1" '$1 == k { print $2 }' "$2" | tail -1; }
