# check.sh - sourced by the shell test scripts: pass/fail counters and
# check NAME COMMAND..., which runs the command and counts it, printing
# its output as the figures of that check.
pass=0 fail=0
check() {
    name=$1; shift
    if out=$("$@" 2>&1); then
        pass=$((pass + 1)); printf '  ok    %-28s %s\n' "$name" "$out"
    else
        fail=$((fail + 1)); printf '  FAIL  %-28s %s\n' "$name" "$out"
    fi
}
# ok MESSAGE, bad MESSAGE: count a check decided by the script itself.
ok() { pass=$((pass + 1)); printf '  ok    %s\n' "$*"; }
bad() { fail=$((fail + 1)); printf '  FAIL  %s\n' "$*"; }
# log NAME CMD...: run the command quietly into $out/NAME.log, and show
# the log's tail when it fails
log() {
    name=$1
    shift
    if "$@" >"$out/$name.log" 2>&1; then return 0; fi
    tail -20 "$out/$name.log"
    return 1
}
