#!/bin/sh
# Runs every test suite against one build variant (default build/asan) and
# closes with the totals: "N passed, M failed".
B=${1:-build/asan}
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
run "$B/test_fx"
run "$B/test_fx_soft"
run "$B/test_sphere_coarse"
run "$B/test_eye_box"
run "$B/test_footprint"
run "$B/test_geometry"
run "$B/test_tiles"
run "$B/test_bvh"
run "$B/test_hal"
run tests/image-tests.sh "$B/rt" "$B/test-images"
run tests/aa-tests.sh "$B/rt" "$B/test-aa"
run tests/same-samples-tests.sh "$B/rt" "$B/test-same-samples"
run tests/format-tests.sh "$B/rt" "$B/test-formats"
run tests/reference-tests.sh "$B/rt" "$B/test-reference"
run tests/surfaces-tests.sh "$B/rt" "$B/test-surfaces"
run tests/filter-tests.sh "$B/rt" "$B/test-filter"
run tests/cli-tests.sh "$B/rt" "$B/test-cli"
run tests/spelling-tests.sh "$B/rt" "$B/test-spelling"
run tests/far-tiles-tests.sh "$B/rt" "$B/test-far-tiles"
run tests/threads-tests.sh "$B/rt" "$B/test-threads"
run tests/progressive-tests.sh "$B/rt" "$B/test-progressive"
run tests/spd-tests.sh "$B/rt" "$B/test-spd"
run tests/report-tests.sh
run tests/board-tests.sh "$B/rt"
run tests/board-aa-tests.sh "$B/rt"
run tests/ports-tests.sh "$B/rt"
run tests/cores-tests.sh "$B/rt"
run tests/profile-tests.sh
run tests/board-oled-test.sh "$B/rt"
run tests/board-pico-tests.sh "$B/rt"
run tests/board-stm32f4-tests.sh "$B/rt"
run tests/speed-tests.sh "$B/rt"
run tests/specialise-tests.sh "$B/rt"
run tests/consumer-tests.sh "$B/rt" build/consumer
run tests/install-tests.sh "$B/rt" "$B/test-install"
run tests/scenec-tables-tests.sh "$B/rt" "$B/test-scenec-tables"
run tests/examples-tests.sh "$B/rt" "$B/test-examples"
run python3 tests/stress.py --quick
run tests/lint.sh
run tests/strict-flags.sh
run python3 tests/layers.py "$B/fixed"
run tests/symbols.sh "$B"
run tests/config-tests.sh "$B/test-config"
run tests/hygiene.sh
run tests/deps-tests.sh "$B/test-deps"
run python3 tests/docs-check.py "$B/rt"
run tests/fuzz-smoke.sh
echo
echo "$total_pass passed, $total_fail failed"
[ $total_fail -eq 0 ]
