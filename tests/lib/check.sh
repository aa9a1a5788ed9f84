# check.sh - the shell tests' one harness, sourced by every suite
# (. tests/lib/check.sh): the pass/fail counters and
#   check NAME COMMAND...  run the command and count it, printing its
#                          output as the figures of that check;
#   ok MESSAGE, bad MESSAGE  count a check the script decided itself;
#   count_pass             count a passed check that prints no line of
#                          its own (one line stands for many);
#   relay FILE             count the "  ok ..." lines of a C test's output
#                          as passes and every other line as a failure,
#                          printing each;
#   log NAME COMMAND...    run the command quietly into $out/NAME.log and
#                          show the log's tail when it fails;
#   summary NAME           the suite's last line, "NAME: N passed, M
#                          failed" (what tests/run-all.py reads), and its
#                          exit status: 0 only when nothing failed.
# (the functions' own variables start with _ so that no caller's is changed)
# tests/lib/check.py is the same harness for the Python tests: the same
# lines, the same summary.
pass=0 fail=0
check() {
    _check_name=$1; shift
    if _check_out=$("$@" 2>&1); then
        pass=$((pass + 1)); printf '  ok    %-28s %s\n' "$_check_name" "$_check_out"
    else
        fail=$((fail + 1)); printf '  FAIL  %-28s %s\n' "$_check_name" "$_check_out"
    fi
}
ok() { pass=$((pass + 1)); printf '  ok    %s\n' "$*"; }
bad() { fail=$((fail + 1)); printf '  FAIL  %s\n' "$*"; }
count_pass() { pass=$((pass + 1)); }
relay() {
    while IFS= read -r _relay_line; do
        case $_relay_line in
            "  ok "*) pass=$((pass + 1)) ;;
            *) fail=$((fail + 1)) ;;
        esac
        printf '%s\n' "$_relay_line"
    done <"$1"
}
log() {
    _log_name=$1
    shift
    if "$@" >"$out/$_log_name.log" 2>&1; then return 0; fi
    tail -20 "$out/$_log_name.log"
    return 1
}
summary() {
    echo "$1: $pass passed, $fail failed"
    [ "$fail" -eq 0 ]
}
