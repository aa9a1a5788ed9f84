#!/bin/sh
# The core's footprint as a library, per feature set, for a Cortex-M3 at
# -Os: every C file of src/ compiled with the set's switches, linked with
# --gc-sections from the entry points a user calls, plus the four memory
# functions GCC may emit (app/firmware/libc_min.c). Scene tables
# and the user's sink are not counted. Prints code (text + rodata) and
# static RAM (data + bss) per set.
OUT=build/lib-size
mkdir -p "$OUT"
CC=${ARM_CC:-arm-none-eabi-gcc}
ARCH="-mcpu=cortex-m3 -mthumb"
CFLAGS="-std=c11 -ffreestanding -Os -ffunction-sections -fdata-sections -fno-tree-loop-distribute-patterns -Iinclude -Isrc -DRT_USE_SPD=0"
sizes() { # set name, entry points, flags
    name=$1 entries=$2
    shift 2
    objs=""
    for c in src/*.c src/*/*.c app/firmware/libc_min.c; do
        o="$OUT/$name-$(basename "$c" .c).o"
        $CC $ARCH $CFLAGS "$@" -c "$c" -o "$o" || return 1
        objs="$objs $o"
    done
    undef=""
    for e in $entries; do undef="$undef -Wl,-u,$e"; done
    $CC $ARCH -nostdlib -Wl,--gc-sections -Wl,--entry=rt_render $undef -o "$OUT/$name.elf" $objs -lgcc || return 1
    arm-none-eabi-size -A "$OUT/$name.elf" | awk -v n="$name" '
        $1 == ".text" || $1 == ".rodata" { code += $2 } $1 == ".data" || $1 == ".bss" { ram += $2 }
        END { printf "%-40s %8d %12d\n", n, code, ram }'
}
printf '%-40s %8s %12s\n' "feature set (Cortex-M3, -Os)" "code" "static RAM"
# without anti-aliasing, dithering and progressive display (as firmware
# that streams its frame), then with them (the defaults)
NO_AA="-DRT_USE_AA=0 -DRT_USE_DITHER=0 -DRT_USE_PROGRESSIVE=0"
# planes, textures and the sky: left out of the sets but the last
NO_SURF="-DRT_USE_PLANES=0 -DRT_USE_CHECKER=0 -DRT_USE_MARBLE=0 -DRT_USE_SKY=0"
sizes spd-features rt_render -DRT_USE_OBJECTS=0 $NO_AA $NO_SURF
sizes spd-features-bvh-only rt_render -DRT_USE_OBJECTS=0 -DRT_USE_FLAT=0 $NO_AA $NO_SURF
sizes all-solids rt_render $NO_AA $NO_SURF
sizes spd-features-no-refraction rt_render -DRT_USE_OBJECTS=0 -DRT_USE_REFRACTION=0 -DRT_USE_PATCHES=0 -DRT_USE_CONES=0 $NO_AA $NO_SURF
sizes all-solids+nff-reader "rt_render rt_nff_load" $NO_AA $NO_SURF
sizes spd-features+aa+dither+progressive rt_render -DRT_USE_OBJECTS=0 $NO_SURF
sizes all-solids+aa+dither+progressive rt_render $NO_SURF
sizes spd-features+planes+textures+sky rt_render -DRT_USE_OBJECTS=0 $NO_AA
