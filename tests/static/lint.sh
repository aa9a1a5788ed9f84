#!/bin/sh
# Static checks: cppcheck on the core (src/) and on both platforms must
# report nothing. Each tree is checked with the defines its builds use,
# once per numeric backend the Makefile and board.mk build it for.
# Inline suppressions (--inline-suppr) each say why at the line.
. tests/lib/check.sh
# cppcheck_clean WHAT CPPCHECK-ARGS...: cppcheck reports nothing on them
cppcheck_clean() {
    what=$1
    shift
    out=$(cppcheck --enable=warning,style,performance,portability --std=c11 --quiet --error-exitcode=1 \
        --inline-suppr --suppress=missingIncludeSystem --max-configs=32 -URT_CONFIG_FILE -URT_UDIV32_HEADER "$@" 2>&1)
    if [ $? -eq 0 ] && [ -z "$out" ]; then
        ok "cppcheck $what: no findings"
    else
        bad "cppcheck $what:"
        echo "$out"
    fi
}
DOUBLE=-DRT_BACKEND_DOUBLE=1 FLOAT=-DRT_BACKEND_FLOAT=1

cppcheck_clean "src/ (fixed)" -Iinclude -Isrc src/
cppcheck_clean "src/ (double)" -Iinclude -Isrc $DOUBLE src/
cppcheck_clean "src/ (float)" -Iinclude -Isrc $FLOAT src/
cppcheck_clean "src/ (double, fixed tolerances)" -Iinclude -Isrc $DOUBLE -DRT_TOLERANCES_FIXED=1 src/
# the host's builds also record and replay split decisions (RT_AA_REPLAY)
cppcheck_clean "src/tracer/render.c (fixed; RT_AA_REPLAY)" -Iinclude -Isrc -DRT_AA_REPLAY=1 src/tracer/render.c
cppcheck_clean "src/tracer/render.c (double; RT_AA_REPLAY)" -Iinclude -Isrc $DOUBLE -DRT_AA_REPLAY=1 src/tracer/render.c

# The hosted CLI and the scene compiler; backend.c is built once per backend.
HOSTED="-Iinclude -Isrc -Iapp/rt -D_POSIX_C_SOURCE=200809L -DRT_AA_REPLAY=1"
cppcheck_clean "app/rt/ and tools/ (fixed)" $HOSTED -DBACKEND_ID=fixed app/rt/ tools/
cppcheck_clean "app/rt/backend.c (double)" $HOSTED $DOUBLE -DBACKEND_ID=double app/rt/backend.c
cppcheck_clean "app/rt/backend.c (float)" $HOSTED $FLOAT -DBACKEND_ID=float app/rt/backend.c
cppcheck_clean "app/rt/backend.c (double, fixed tolerances)" $HOSTED $DOUBLE -DRT_TOLERANCES_FIXED=1 \
    -DBACKEND_ID=double_ftol app/rt/backend.c
# The scene compiler writes float and double tables when built for them.
cppcheck_clean "tools/ (float)" $HOSTED $FLOAT tools/
cppcheck_clean "tools/ (double)" $HOSTED $DOUBLE tools/

# The firmware: fixed (make run), double and float (the soft-float
# comparison builds), and main.c's RGB565 framebuffer.
# Every board folder and architecture folder with the common firmware.
BOARD="-Iinclude -Isrc -Iplatform -Iapp/firmware -DBOARD_WIDTH=64 -DBOARD_HEIGHT=64 -DBOARD_DEPTH=5 -DRT_USE_SPD=0"
PORTS="app/firmware/ platform/"
cppcheck_clean "app/firmware/ and every port (fixed)" $BOARD $PORTS
cppcheck_clean "app/firmware/main.c (fixed, rgb565)" $BOARD -DBOARD_FORMAT=RT_FB_RGB565 app/firmware/main.c
cppcheck_clean "app/firmware/ (double)" $BOARD $DOUBLE app/firmware/
cppcheck_clean "app/firmware/ (float)" $BOARD $FLOAT app/firmware/

# The embedding example (tests/host/consumer/): main.c sees only rt.h.
cppcheck_clean "tests/host/consumer/ (host)" -Iinclude -Isrc tests/host/consumer/main.c tests/host/consumer/out_host.c
cppcheck_clean "tests/host/consumer/ (board)" -Iinclude -Isrc -Iplatform -Iapp/firmware tests/host/consumer/out_mps2.c

summary lint
