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
ok() { pass=$((pass + 1)); printf '  ok    %s\n' "$1"; }
bad() { fail=$((fail + 1)); printf '  FAIL  %s\n' "$1"; }
