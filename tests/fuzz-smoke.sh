#!/bin/sh
# Smoke fuzz: the libFuzzer harness over the reader and a tiny render,
# under ASan and UBSan, for FUZZ_SMOKE seconds (default 60) from the seed
# corpus. Any crash, hang (> 10 s) or sanitizer report fails it; the input
# is left in build/fuzz-smoke/ to be added to tests/fuzz-found/.
FUZZER=${1:-build/fuzz/fuzz_nff}
SECONDS_=${FUZZ_SMOKE:-60}
OUT=build/fuzz-smoke
rm -rf "$OUT" && mkdir -p "$OUT/corpus"
if (cd "$OUT" && ../../"$FUZZER" corpus ../../tests/fuzz-corpus -max_total_time="$SECONDS_" -timeout=10 \
        -max_len=4096 -print_final_stats=1 >log 2>&1); then
    runs=$(awk '/number_of_executed_units/ { print $2 }' "$OUT/log")
    echo "  ok    $runs executions in ${SECONDS_} s, no crash, hang or sanitizer report"
    echo "fuzz-smoke: 1 passed, 0 failed"
else
    echo "  FAIL  the fuzzer found a problem:"
    grep -E "ERROR|runtime error|SUMMARY|Test unit written" "$OUT/log" | head -8
    echo "fuzz-smoke: 0 passed, 1 failed"
    exit 1
fi
