#!/bin/sh
# Smoke fuzz: each libFuzzer harness (see the Makefile) for FUZZ_SMOKE
# seconds (default 15) from its seed corpus, under ASan and UBSan. Any
# crash, hang (> 10 s) or sanitizer report fails it; the input is left in
# build/fuzz-smoke/NAME/ (add it to tests/fuzz/found/ once fixed).
SECONDS_=${FUZZ_SMOKE:-15}
. tests/lib/check.sh
# Seeds: the corpus, and for the scene readers every input that once broke one.
nff_seeds=tests/fuzz/corpus+tests/fuzz/found
for spec in fuzz_nff:$nff_seeds fuzz_nff_double:$nff_seeds fuzz_nff_float:$nff_seeds fuzz_readers:$nff_seeds \
            fuzz_scenec:$nff_seeds fuzz_scenec_float:$nff_seeds fuzz_receive:tests/fuzz/corpus-receive; do
    name=${spec%%:*} seeds=${spec#*:}
    seed_dirs=$(echo "$seeds" | tr '+' '\n' | sed 's|^|../../../|' | tr '\n' ' ')
    out=build/fuzz-smoke/$name
    rm -rf "$out" && mkdir -p "$out/corpus"
    if [ ! -x "build/fuzz/$name" ]; then
        bad "$name: build/fuzz/$name not built"
        continue
    fi
    if (cd "$out" && "../../fuzz/$name" corpus $seed_dirs -max_total_time="$SECONDS_" -timeout=10 \
            -max_len=4096 -print_final_stats=1 >log 2>&1); then
        runs=$(awk '/number_of_executed_units/ { print $2 }' "$out/log")
        ok "$name: $runs executions in ${SECONDS_} s from $seeds, no crash, hang or sanitizer report"
    else
        bad "$name: the fuzzer found a problem:"
        grep -E "ERROR|runtime error|SUMMARY|Test unit written" "$out/log" | head -8
    fi
done
summary fuzz-smoke
