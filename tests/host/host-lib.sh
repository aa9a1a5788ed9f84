# host-lib.sh - what the host suites that render references share, sourced
# with the suite's arguments (RT [OUT]); it sources tests/lib/check.sh:
#   RT                 $1, the rt under test (default build/asan/rt)
#   OUT                $2, the suite's folder (default
#                      build/asan/test-NAME for NAME-tests.sh), made here
#   RT_FAST            the optimised build of the same source (build/host/rt,
#                      or RT where that is not built), for the heavy renders
#                      the suite does not check (references, figures)
#   build_ref_tracer   compile tests/host/ref_tracer.c, the independent
#                      tracer written from docs/shading-model.md alone, into
#                      REF ($OUT/ref_tracer); when it does not compile,
#                      count one failure and return 1
RT=${1:-build/asan/rt}
OUT=${2:-build/asan/test-$(basename "$0" -tests.sh)}
mkdir -p "$OUT"
. tests/lib/check.sh
RT_FAST=${RT_FAST:-build/host/rt}
[ -x "$RT_FAST" ] || RT_FAST=$RT
REF=$OUT/ref_tracer
build_ref_tracer() {
    ${CC:-cc} -std=c11 -Wall -Wextra -Werror -O2 -o "$REF" tests/host/ref_tracer.c -lm && return 0
    bad "ref_tracer does not compile"
    return 1
}
