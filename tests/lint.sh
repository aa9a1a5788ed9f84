#!/bin/sh
# Static checks: cppcheck on the core (src/) and on both platforms must
# report nothing. Each tree is checked with the defines its builds use,
# once per numeric backend the Makefile and board.mk build it for.
# Inline suppressions (--inline-suppr) each say why at the line.
pass=0 fail=0
check() { # check WHAT CPPCHECK-ARGS...
    what=$1
    shift
    out=$(cppcheck --enable=warning,style,performance,portability --std=c11 --quiet --error-exitcode=1 \
        --inline-suppr --suppress=missingIncludeSystem --max-configs=32 -URT_CONFIG_FILE -URT_UDIV32_HEADER "$@" 2>&1)
    if [ $? -eq 0 ] && [ -z "$out" ]; then
        pass=$((pass + 1))
        echo "  ok    cppcheck $what: no findings"
    else
        fail=$((fail + 1))
        echo "  FAIL  cppcheck $what:"
        echo "$out"
    fi
}
DOUBLE=-DRT_BACKEND_DOUBLE=1 FLOAT=-DRT_BACKEND_FLOAT=1

check "src/ (fixed)" -Iinclude -Isrc src/
check "src/ (double)" -Iinclude -Isrc $DOUBLE src/
check "src/ (float)" -Iinclude -Isrc $FLOAT src/
check "src/ (double, fixed tolerances)" -Iinclude -Isrc $DOUBLE -DRT_TOLERANCES_FIXED=1 src/
# the host's builds also record and replay split decisions (RT_AA_REPLAY)
check "src/tracer/render.c (fixed; RT_AA_REPLAY)" -Iinclude -Isrc -DRT_AA_REPLAY=1 src/tracer/render.c
check "src/tracer/render.c (double; RT_AA_REPLAY)" -Iinclude -Isrc $DOUBLE -DRT_AA_REPLAY=1 src/tracer/render.c

# The hosted CLI and the scene compiler; backend.c is built once per backend.
HOSTED="-Iinclude -Isrc -Iplatform/hosted -D_POSIX_C_SOURCE=200809L -DRT_AA_REPLAY=1"
check "platform/hosted/ and tools/ (fixed)" $HOSTED -DBACKEND_ID=fixed platform/hosted/ tools/
check "platform/hosted/backend.c (double)" $HOSTED $DOUBLE -DBACKEND_ID=double platform/hosted/backend.c
check "platform/hosted/backend.c (float)" $HOSTED $FLOAT -DBACKEND_ID=float platform/hosted/backend.c
check "platform/hosted/backend.c (double, fixed tolerances)" $HOSTED $DOUBLE -DRT_TOLERANCES_FIXED=1 \
    -DBACKEND_ID=double_ftol platform/hosted/backend.c
# The scene compiler writes float and double tables when built for them.
check "tools/ (float)" $HOSTED $FLOAT tools/
check "tools/ (double)" $HOSTED $DOUBLE tools/

# The firmware: fixed (make run), double and float (the soft-float
# comparison builds), and main.c's RGB565 framebuffer.
# Every board folder and architecture folder with the common firmware.
BOARD="-Iinclude -Isrc -Iplatform/firmware -DBOARD_WIDTH=64 -DBOARD_HEIGHT=64 -DBOARD_DEPTH=5 -DRT_USE_SPD=0"
PORTS="platform/firmware/ platform/arch/ $(ls -d platform/*/ | grep -v -e platform/firmware/ -e platform/arch/ -e platform/hosted/)"
check "platform/firmware/ and every port (fixed)" $BOARD $PORTS
check "platform/firmware/main.c (fixed, rgb565)" $BOARD -DBOARD_FORMAT=RT_FB_RGB565 platform/firmware/main.c
check "platform/firmware/ (double)" $BOARD $DOUBLE platform/firmware/
check "platform/firmware/ (float)" $BOARD $FLOAT platform/firmware/

# The embedding example (tests/consumer/): main.c sees only rt.h.
check "tests/consumer/ (host)" -Iinclude -Isrc tests/consumer/main.c tests/consumer/out_host.c
check "tests/consumer/ (board)" -Iinclude -Isrc -Iplatform/firmware tests/consumer/out_mps2.c

echo "lint: $pass passed, $fail failed"
[ $fail -eq 0 ]
