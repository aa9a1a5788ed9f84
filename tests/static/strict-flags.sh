#!/bin/sh
# The core (src/) compiles without a warning under the strict flags a
# firmware project may use (docs/embedding.md), for each numeric backend:
# with the host's cc and clang (the hosted build's capacities, every
# feature on) and with arm-none-eabi-gcc (the firmware's feature macros;
# Cortex-M3 for every backend, the M4F's FPU for float, the M0+ for fixed).
# Object code only (-c -o /dev/null), at -O2 like the builds, so the
# optimiser's warnings count too. clang or arm-none-eabi-gcc missing is a
# skip (make test installs both); cc missing fails.
STRICT="-std=c11 -Wall -Wextra -Wpedantic -Wshadow -Wundef -Wcast-align -Wdouble-promotion -Werror"
COMMON="-ffreestanding -O2 -Iinclude -Isrc"
# the Makefile's HOST_CAPS, and app/firmware/firmware.mk's BOARD_CAPS
# and feature macros (RT_USE_* not given are on: rt_config.h)
HOST="-DRT_MAX_SPHERES=16384 -DRT_MAX_CONES=16384 -DRT_MAX_POLYGONS=16384 -DRT_MAX_VERTICES=65536
      -DRT_MAX_LIGHTS=32 -DRT_MAX_MATERIALS=1024 -DRT_MAX_WORKERS=64 -DRT_MAX_DEPTH=8"
BOARD="-DRT_MAX_SPHERES=1024 -DRT_MAX_CONES=1024 -DRT_MAX_POLYGONS=4096 -DRT_MAX_VERTICES=32768
       -DRT_MAX_LIGHTS=16 -DRT_MAX_MATERIALS=128 -DRT_MAX_WORKERS=1 -DRT_FB_ONLY_FORMAT=RT_FB_RGB888
       -DRT_USE_SPD=0"
# the backends' flags (Makefile BACKEND_FLAGS_*, firmware.mk FW_FLAGS_*)
FIXED="" FLOAT="-DRT_BACKEND_FLOAT=1 -ffp-contract=off" DOUBLE="-DRT_BACKEND_DOUBLE=1"
M3="-mcpu=cortex-m3 -mthumb" M0P="-mcpu=cortex-m0plus -mthumb"
M4F="-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
SOURCES=$(ls src/*.c src/*/*.c)
N=$(echo "$SOURCES" | wc -l)
. tests/lib/check.sh

# compiles_clean COMPILER WHAT FLAGS...: every source compiles with STRICT
# COMMON FLAGS, without a warning
compiles_clean() {
    cc=$1 what=$2
    shift 2
    # (the flags word-split on purpose; xargs appends one source a call)
    out=$(echo "$SOURCES" | xargs -n1 -P2 "$cc" $STRICT $COMMON "$@" -c -o /dev/null 2>&1)
    if [ $? -eq 0 ] && [ -z "$out" ]; then
        ok "$cc $what: $N files, no warnings"
    else
        bad "$cc $what:"
        printf '%s\n' "$out" | grep -E 'warning:|error:' | sort -u | head -20
    fi
}
# have COMPILER: present, else a skip line for it
have() {
    command -v "$1" >/dev/null 2>&1 && return 0
    echo "  skipped: $1 not found"
    return 1
}

CC=${CC:-cc}
if command -v "$CC" >/dev/null 2>&1; then
    compiles_clean "$CC" "fixed" $HOST $FIXED
    compiles_clean "$CC" "float" $HOST $FLOAT
    compiles_clean "$CC" "double" $HOST $DOUBLE
else
    bad "$CC not found"
fi
if have clang; then
    compiles_clean clang "fixed" $HOST $FIXED
    compiles_clean clang "float" $HOST $FLOAT
    compiles_clean clang "double" $HOST $DOUBLE
fi
if have arm-none-eabi-gcc; then
    compiles_clean arm-none-eabi-gcc "fixed (Cortex-M3)" $M3 $BOARD $FIXED
    compiles_clean arm-none-eabi-gcc "float (Cortex-M3, soft-float)" $M3 $BOARD $FLOAT -fno-math-errno
    compiles_clean arm-none-eabi-gcc "double (Cortex-M3, soft-float)" $M3 $BOARD $DOUBLE
    compiles_clean arm-none-eabi-gcc "float (Cortex-M4F, hard-float)" $M4F $BOARD $FLOAT -fno-math-errno
    compiles_clean arm-none-eabi-gcc "fixed (Cortex-M0+)" $M0P $BOARD $FIXED
fi

summary strict-flags
