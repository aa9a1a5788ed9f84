#!/bin/sh
# Line and branch coverage of the scene reader by a fuzz corpus
# (default: the seed corpus plus build/fuzz/corpus-fuzz_nff when it exists).
set -e
OUT=build/fuzz-cov
mkdir -p "$OUT"
clang -std=c11 -Wall -Wextra -Werror -g -O1 -fsanitize=fuzzer -fprofile-instr-generate -fcoverage-mapping -Iinclude -Isrc \
    -o "$OUT/fuzz_cov" tests/fuzz/fuzz_nff.c src/*.c src/*/*.c
dirs="tests/fuzz/corpus tests/fuzz/found"
[ -d build/fuzz/corpus-fuzz_nff ] && dirs="$dirs build/fuzz/corpus-fuzz_nff"
LLVM_PROFILE_FILE="$OUT/cov.profraw" "$OUT/fuzz_cov" -runs=0 $dirs >"$OUT/run.log" 2>&1
llvm-profdata merge -sparse "$OUT/cov.profraw" -o "$OUT/cov.profdata"
llvm-cov report "$OUT/fuzz_cov" -instr-profile="$OUT/cov.profdata" src/reader/nff.c src/reader/nff_solids.c
