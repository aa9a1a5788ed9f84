#!/bin/sh
# scenec-tables-tests.sh RT [OUT]: rt-scenec's tables for the float and
# double backends. For each, rt-scenec is built with that backend's flag
# and run on each scene; the generated scene_data.c must compile with
# -Werror, hold bit for bit what the reader builds (tests/host/scenec_tables.c
# compares every field), and render the image of
#   rt SCENE --float|--double --size 64x64
# byte for byte. Then the float tables on a Cortex-M4F (hard float,
# FPv4-SP) under QEMU (mps2-an386, the ports of platform/): the same
# image again, when arm-none-eabi-gcc and qemu-system-arm are there.
#
# The builds here are what a Makefile rule for a float (double) rt-scenec
# runs: the host cc, the core's flags plus -DRT_BACKEND_FLOAT=1
# (-DRT_BACKEND_DOUBLE=1), -ffp-contract=off, and -lm (the reader's tan,
# sin, cos, floor and the BVH builder's floor are host libm calls).
rt=${1:-build/host/rt} out=${2:-build/test-scenec-tables}
. tests/lib/check.sh

WARN="-std=c11 -Wall -Wextra -Werror"
# the Makefile's HOST_CAPS: rt's reader, so the same capacities (they do
# not change the tables' values, only what fits)
CAPS="-DRT_MAX_SPHERES=16384 -DRT_MAX_CONES=16384 -DRT_MAX_POLYGONS=16384 -DRT_MAX_VERTICES=65536
      -DRT_MAX_LIGHTS=32 -DRT_MAX_MATERIALS=1024"
SIZE=64x64
SCENES="scenes/showpiece.nff scenes/csg.nff scenes/quadrics.nff scenes/torus.nff scenes/boxes.nff
        scenes/transforms.nff scenes/spd/balls-1.nff scenes/spd/gears-1.nff scenes/spd/rings-1.nff
        scenes/spd/teapot-1.nff scenes/spd/tetra-2.nff scenes/textures.nff scenes/bench/card.nff
        scenes/bench/picolib.nff scenes/bench/whitted.nff"

rm -rf "$out"
mkdir -p "$out"

for b in float double; do
    flag=-DRT_BACKEND_$(echo $b | tr a-z A-Z)=1
    d="$out/$b"
    mkdir -p "$d"
    if ! log "$b-scenec" cc $WARN -D_POSIX_C_SOURCE=200809L -O2 -ffp-contract=off $CAPS $flag -Iinclude -Isrc -Iapp/rt \
        -o "$d/rt-scenec" tools/scenec.c app/rt/host_io.c src/*.c src/*/*.c -lm; then
        bad "$b: rt-scenec does not build"
        continue
    fi
    # the core once, as a library would be
    objs=""
    for c in src/*.c src/*/*.c; do
        o="$d/core-$(basename "$c" .c).o"
        log "$b-core" cc $WARN -ffreestanding -O2 -ffp-contract=off $CAPS $flag -Iinclude -Isrc -c "$c" -o "$o" ||
            bad "$b: $c does not compile"
        objs="$objs $o"
    done
    n=0 same=0
    for s in $SCENES; do
        name=$(basename "$s" .nff)
        n=$((n + 1))
        if ! log "$b-$name-scenec" "$d/rt-scenec" "$s" -o "$d/$name.c" --header "$d/$name.h"; then
            bad "$b, $name: rt-scenec failed"
            continue
        fi
        grep -q "^#if !RT_BACKEND_$(echo $b | tr a-z A-Z)\( \|\$\)" "$d/$name.c" ||
            bad "$b, $name: the tables do not refuse another backend"
        if ! log "$b-$name-build" cc $WARN -O2 -ffp-contract=off $CAPS $flag -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc \
            -o "$d/$name" tests/host/scenec_tables.c "$d/$name.c" $objs -lm; then
            bad "$b, $name: scene_data.c or the harness does not compile with -Werror"
            continue
        fi
        if ! "$d/$name" "$s" >"$d/$name.ppm" 2>"$d/$name.err"; then
            bad "$b, $name: tables differ from the reader's: $(head -3 "$d/$name.err" | tr '\n' ' ')"
            continue
        fi
        "$rt" "$s" --$b --size $SIZE --quiet -o "$d/$name-rt.ppm" 2>"$d/$name-rt.err" || { bad "$b, $name: rt failed"; continue; }
        if cmp -s "$d/$name.ppm" "$d/$name-rt.ppm"; then
            same=$((same + 1))
        else
            bad "$b, $name: the tables' image differs from rt --$b ($("$rt" compare "$d/$name.ppm" "$d/$name-rt.ppm" 2>&1))"
        fi
    done
    [ $same -eq $n ] &&
        ok "$b: $n scenes: tables bit for bit the reader's, image byte for byte rt --$b's at $SIZE"
done

# The float tables on a Cortex-M4F under QEMU: hard float, no libm.
if command -v arm-none-eabi-gcc >/dev/null && command -v qemu-system-arm >/dev/null; then
    M4="-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard"
    # mps2-an386's board.mk: the AN385's board.c and link.ld
    PORT="platform/arch/cortex-m/startup.c platform/arch/cortex-m/semihost.c platform/mps2-an385/board.c
          app/firmware/report.c app/firmware/stack.c app/firmware/libc_min.c"
    d="$out/m4f"
    mkdir -p "$d"
    # soft-float helpers (double arithmetic, conversions) and libm in an image
    float_helpers() {
        arm-none-eabi-nm "$1" | awk '$3 ~ /^(__aeabi_(d|f|[a-z]*2[df]$)|(sqrt|pow|tan|sin|cos|floor)f?$)/ { print $3 }' |
            tr '\n' ' '
    }
    # control: the check sees a double multiply
    printf 'volatile double a = 1.5;\nint main(void) { a = a * a; return 0; }\n' >"$d/control.c"
    if arm-none-eabi-gcc $M4 -O2 -nostdlib -nostartfiles -Wl,--entry=main -o "$d/control.elf" "$d/control.c" -lgcc &&
        [ -n "$(float_helpers "$d/control.elf")" ]; then :; else
        bad "Cortex-M4F: the control's double multiply is not seen as a soft-float helper"
    fi
    n=0 same=0
    for s in scenes/showpiece.nff scenes/spd/balls-1.nff scenes/spd/teapot-1.nff; do
        name=$(basename "$s" .nff)
        n=$((n + 1))
        elf="$d/$name.elf"
        if ! log "m4f-$name" arm-none-eabi-gcc $WARN $M4 -O2 -ffreestanding -fno-math-errno -ffp-contract=off \
            -ffunction-sections -fdata-sections -DRT_BACKEND_FLOAT=1 -DRT_USE_SPD=0 -DTABLES_BOARD=1 \
            -Iinclude -Isrc -Iplatform -Iapp/firmware -nostdlib -nostartfiles -Wl,--gc-sections \
            -T platform/mps2-an385/link.ld -Lapp/firmware -o "$elf" \
            tests/host/scenec_tables.c "$out/float/$name.c" src/*.c src/*/*.c $PORT -lgcc; then
            bad "Cortex-M4F, $name: does not build"
            continue
        fi
        # no libm and no soft-float helper in the image
        syms=$(arm-none-eabi-nm -u "$elf" | awk '{ print $2 }' | tr '\n' ' ')
        [ -z "$syms$(float_helpers "$elf")" ] || bad "Cortex-M4F, $name: links $syms$(float_helpers "$elf")"
        if timeout 300 qemu-system-arm -M mps2-an386 -nographic -monitor none \
            -semihosting-config enable=on,target=native -kernel "$elf" </dev/null >"$d/$name.ppm" 2>"$d/$name.err" &&
            cmp -s "$d/$name.ppm" "$out/float/$name-rt.ppm"; then
            same=$((same + 1))
        else
            bad "Cortex-M4F, $name: the image differs from rt --float or the run failed ($(head -c 200 "$d/$name.err"))"
        fi
    done
    [ $same -eq $n ] &&
        ok "Cortex-M4F (hard float, QEMU mps2-an386): $n scenes from float tables, byte for byte rt --float's"
else
    echo "  skip  Cortex-M4F: arm-none-eabi-gcc or qemu-system-arm missing"
fi

summary scenec-tables
