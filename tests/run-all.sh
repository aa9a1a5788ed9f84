#!/bin/sh
# Runs every suite of tests/suites.list against one build variant (default
# build/asan; $B in the list) and closes with the totals: "N passed, M failed".
B=${1:-build/asan}
LIST=$(dirname "$0")/suites.list
total_pass=0 total_fail=0
run() {
    t0=$(date +%s)
    log=$("$@" 2>&1)
    printf '%s\n' "$log"
    echo "  ($* took $(($(date +%s) - t0)) s)"
    line=$(printf '%s\n' "$log" | grep -E '^[a-z0-9_-]+: [0-9]+ passed, [0-9]+ failed$' | tail -1)
    if [ -z "$line" ]; then
        echo "  FAIL  $* printed no summary (crashed?)"
        total_fail=$((total_fail + 1))
        return
    fi
    p=$(echo "$line" | sed -E 's/.*: ([0-9]+) passed.*/\1/')
    f=$(echo "$line" | sed -E 's/.* ([0-9]+) failed$/\1/')
    total_pass=$((total_pass + p))
    total_fail=$((total_fail + f))
}
[ -r "$LIST" ] || { echo "run-all: $LIST not found"; echo "0 passed, 1 failed"; exit 1; }
# the list on descriptor 3, so the suites keep run-all's input; each line's
# words split after $B is put in, not globbed
set -f
while IFS= read -r suite <&3; do
    suite=${suite#"${suite%%[![:space:]]*}"} # (leading blanks)
    case "$suite" in '' | '#'*) continue ;; esac
    eval "run $suite" 3<&-
done 3<"$LIST"
set +f
echo
echo "$total_pass passed, $total_fail failed"
[ $total_fail -eq 0 ]
