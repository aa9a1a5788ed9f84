#!/bin/sh
# consumer-tests.sh RT [OUT]: the core as a user embeds it (tests/host/consumer/):
# configured and built with CMake for the host and cross compiled with
# cmake/arm-none-eabi.cmake (a Cortex-M3, and a Cortex-M4F with the float
# backend: below), and with GNU make from rt.mk
# (examples/make/Makefile, the example docs/embedding.md shows). Each host
# program, and the Cortex-M3 firmware under QEMU, must write the image of
#   rt scenes/spd/balls-1.nff --size 32x32 --fixed
# byte for byte, from balls-1 with its resolution set to 32 32 (the
# program renders the scene's resolution, opts.width = 0, into a band sized
# from scene_data.h's SCENE_WIDTH); the scene prunes the core (no cone
# code linked).
rt=${1:-build/host/rt} out=${2:-build/consumer}
. tests/lib/check.sh
same_image() { # same_image WHAT IMAGE
    if "$rt" compare "$2" "$out/ref.ppm" --max-error 0 >/dev/null 2>&1; then
        ok "$1: the same image as rt --fixed, byte for byte"
    else
        bad "$1: image differs from rt --fixed ($("$rt" compare "$2" "$out/ref.ppm" 2>&1))"
    fi
}
pruned() { # pruned WHAT PROGRAM: the scene's sphere code linked, no cone code
    if nm "$2" | grep -q ray_hit_sphere && ! nm "$2" | grep -q ray_hit_cone; then
        ok "$1: pruned for the scene (sphere code linked, no cone code)"
    else
        bad "$1: not pruned for the scene (cone code linked, or no sphere code)"
    fi
}
rm -rf "$out"
mkdir -p "$out"
"$rt" scenes/spd/balls-1.nff --size 32x32 --fixed -o "$out/ref.ppm" --quiet || bad "rt: reference render"
scene=$out/balls-1-32x32.nff
sed 's/^resolution .*/resolution 32 32/' scenes/spd/balls-1.nff >"$scene"

# Host: configure, build, run.
if log host-configure cmake -S tests/host/consumer -B "$out/host" -DCMAKE_BUILD_TYPE=Release -DSCENE="$scene" &&
    log host-build cmake --build "$out/host" -j2; then
    ok "CMake, host: configured and built"
    # rt_add_scene's default: the core built for the scene, optimised whole
    f="$out/host/rt/CMakeFiles/rt_core.dir/flags.make"
    grep -q 'RT_CONST_SCENE=rt_scene' "$f" && grep -q -- '-flto' "$f" &&
        ok "CMake, host: rt_core built for the scene (RT_CONST_SCENE=rt_scene, -flto)" ||
        bad "CMake, host: rt_core not built for the scene: $(grep -E '^C_(FLAGS|DEFINES)' "$f" | cut -c1-200)"
    if "$out/host/consumer" >"$out/host.ppm"; then
        same_image "CMake, host" "$out/host.ppm"
    else
        bad "CMake, host: the consumer failed"
    fi
    pruned "CMake, host" "$out/host/consumer"
else
    bad "CMake, host: configure or build failed"
fi

# Cortex-M3: cross compiled with the toolchain file, then run under QEMU.
elf="$out/arm/consumer.elf"
if CFLAGS=-Werror log arm-configure cmake -S tests/host/consumer -B "$out/arm" -DCMAKE_BUILD_TYPE=MinSizeRel -DSCENE="$scene" \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/arm-none-eabi.cmake" && log arm-build cmake --build "$out/arm" -j2 &&
    arm-none-eabi-readelf -h "$elf" | grep -q 'Machine: *ARM'; then
    ok "CMake, Cortex-M3: cross compiled and linked ($(arm-none-eabi-size "$elf" | awk 'NR == 2 { print $1 " bytes of code" }'))"
    if grep -q 'RT_HOST_CC:FILEPATH=.*arm-none-eabi' "$out/arm/CMakeCache.txt"; then
        bad "CMake, Cortex-M3: the scene compiler was built with the cross compiler"
    fi
    if timeout 120 qemu-system-arm -M mps2-an385 -nographic -monitor none \
        -semihosting-config enable=on,target=native -kernel "$elf" </dev/null >"$out/arm.ppm" 2>"$out/arm.err"; then
        same_image "CMake, Cortex-M3 under QEMU" "$out/arm.ppm"
    else
        bad "CMake, Cortex-M3: the firmware failed under QEMU"
    fi
else
    bad "CMake, Cortex-M3: configure, build or link failed"
fi

# Cortex-M4F, float: the toolchain file with -DRT_ARM_CPU=cortex-m4, as
# docs/embedding.md has it, which brings the FPU and the hard-float ABI;
# rt_add_scene specialises the core (link-time optimisation, checked with
# these flags and no start-up code: a configure that says nothing beyond
# CMake's "-- " status lines). Run under QEMU's MPS2 AN386: the image of
# rt --float, and the render's instructions (out_mps2.c) within 3% of the
# board firmware's for the same scene, size and backend at one sample a
# pixel (make firmware BOARD=mps2-an386 BACKEND=float ... AA=0, as make
# run builds it).
"$rt" scenes/spd/balls-1.nff --size 32x32 --float -o "$out/ref-float.ppm" --quiet || bad "rt: float reference render"
m4=$out/m4f elf=$out/m4f/consumer.elf
if CFLAGS=-Werror log m4f-configure cmake -S tests/host/consumer -B "$m4" -DCMAKE_BUILD_TYPE=Release -DSCENE="$scene" \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/arm-none-eabi.cmake" -DRT_ARM_CPU=cortex-m4 -DRT_BACKEND=float &&
    log m4f-build cmake --build "$m4" -j2; then
    ok "CMake, Cortex-M4F float: cross compiled and linked ($(arm-none-eabi-size "$elf" | awk 'NR == 2 { print $1 " bytes of code" }'))"
    said=$(grep -v '^-- ' "$out/m4f-configure.log")
    [ -z "$said" ] && ok "CMake, Cortex-M4F float: the configure says nothing beyond its status lines" ||
        bad "CMake, Cortex-M4F float: the configure said $(echo "$said" | wc -l) lines: $(echo "$said" | head -2)"
    soft=$(arm-none-eabi-objdump -d "$elf" | grep -c '<__aeabi_f')
    fpu=$(arm-none-eabi-objdump -d "$elf" | grep -cE '\sv(add|sub|mul|div|sqrt)\.f32')
    if [ "$soft" = 0 ] && [ "$fpu" -gt 0 ] && arm-none-eabi-readelf -A "$elf" | grep -q 'Tag_ABI_VFP_args: VFP registers'; then
        ok "CMake, Cortex-M4F float: hard float (no __aeabi_f calls, $fpu FPU arithmetic instructions, VFP register arguments)"
    else
        bad "CMake, Cortex-M4F float: not hard float ($soft calls of __aeabi_f*, $fpu FPU arithmetic instructions)"
    fi
    f="$m4/rt/CMakeFiles/rt_core.dir/flags.make"
    grep -q 'RT_CONST_SCENE=rt_scene' "$f" && grep -q -- '-flto' "$f" &&
        ok "CMake, Cortex-M4F float: rt_core built for the scene (RT_CONST_SCENE=rt_scene, -flto)" ||
        bad "CMake, Cortex-M4F float: rt_core not built for the scene: $(grep -E '^C_(FLAGS|DEFINES)' "$f" | cut -c1-200)"
    if timeout 120 qemu-system-arm -M mps2-an386 -nographic -monitor none -icount shift=0 \
        -semihosting-config enable=on,target=native -kernel "$elf" </dev/null >"$out/m4f.ppm" 2>"$out/m4f.err"; then
        if "$rt" compare "$out/m4f.ppm" "$out/ref-float.ppm" --max-error 0 >/dev/null 2>&1; then
            ok "CMake, Cortex-M4F float under QEMU: the same image as rt --float, byte for byte"
        else
            bad "CMake, Cortex-M4F float under QEMU: image differs from rt --float ($("$rt" compare "$out/m4f.ppm" "$out/ref-float.ppm" 2>&1))"
        fi
        mine=$(awk '$1 == "render_instructions" { print $2 }' "$out/m4f.err")
        fw="BOARD=mps2-an386 BACKEND=float SCENE=scenes/spd/balls-1.nff SIZE=32x32 AA=0"
        # shellcheck disable=SC2086 # fw: make's variables, one word each
        if make -s -j2 firmware $fw >"$out/fw.log" 2>&1 &&
            make -s board-run $fw RUN_OUT="$out/fw.png" RUN_RT="$rt" >"$out/fw.report" 2>&1; then
            theirs=$(awk '$1 == "render_instructions" { print $2 }' "$out/fw.report")
            if [ -n "$mine" ] && [ -n "$theirs" ] &&
                awk -v a="$mine" -v b="$theirs" 'BEGIN { d = a / b - 1; exit !(d <= 0.03 && d >= -0.03) }'; then
                ok "CMake, Cortex-M4F float: $mine render instructions, the firmware's (make run's) $theirs, within 3%"
            else
                bad "CMake, Cortex-M4F float: '$mine' render instructions, the firmware's (make run's) '$theirs': not within 3%"
            fi
        else
            bad "CMake, Cortex-M4F float: the board firmware to compare with did not build or run: $(tail -2 "$out/fw.log" "$out/fw.report")"
        fi
    else
        bad "CMake, Cortex-M4F float: the firmware failed under QEMU: $(head -c 300 "$out/m4f.err")"
    fi
else
    bad "CMake, Cortex-M4F float: configure, build or link failed"
fi

# Without link-time optimisation (here a link option the linker does not
# know, which fails the check's link), rt_add_scene says so in one line.
if log nolto-configure cmake -S tests/host/consumer -B "$out/nolto" -DSCENE="$scene" \
    -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/arm-none-eabi.cmake" -DRT_ARM_CPU=cortex-m4 -DCMAKE_EXE_LINKER_FLAGS=-Wl,--no-such-option; then
    said=$(grep -v '^-- ' "$out/nolto-configure.log")
    case $(echo "$said" | wc -l):$said in
        "1:rt_add_scene(consumer ...): no link-time optimisation ("*) ok "CMake, no link-time optimisation: one line: $(echo "$said" | cut -c1-110)..." ;;
        *) bad "CMake, no link-time optimisation: not one line: $(echo "$said" | head -3)" ;;
    esac
else
    bad "CMake, no link-time optimisation: the configure failed"
fi

# The toolchain file's choices, each as docs/embedding.md gives it: the
# flags it sets for C and assembly (the file read alone, cmake -P).
printf 'include("%s")\nmessage("${CMAKE_C_FLAGS_INIT}")\n' "$PWD/cmake/arm-none-eabi.cmake" >"$out/flags.cmake"
arm_flags() { cmake "$@" -P "$out/flags.cmake" 2>&1; }
while IFS='|' read -r args want; do
    # shellcheck disable=SC2086 # args: -D options, one word each
    got=$(arm_flags $args)
    [ "$got" = "$want" ] && ok "arm-none-eabi.cmake ${args:-(no choice)}: $got" || bad "arm-none-eabi.cmake $args: '$got', not '$want'"
done <<'EOF'
|-mthumb -mcpu=cortex-m3 -mfloat-abi=soft
-DRT_ARM_CPU=cortex-m4|-mthumb -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16
-DRT_ARM_CPU=cortex-m7|-mthumb -mcpu=cortex-m7 -mfloat-abi=hard -mfpu=fpv5-sp-d16
-DRT_ARM_CPU=cortex-m33|-mthumb -mcpu=cortex-m33 -mfloat-abi=hard -mfpu=fpv5-sp-d16
-DRT_ARM_CPU=cortex-m7 -DRT_ARM_FPU=fpv5-d16|-mthumb -mcpu=cortex-m7 -mfloat-abi=hard -mfpu=fpv5-d16
-DRT_ARM_CPU=cortex-m4 -DRT_ARM_FLOAT_ABI=soft|-mthumb -mcpu=cortex-m4 -mfloat-abi=soft
-DRT_ARM_CPU=cortex-m4 -DRT_ARM_FLOAT_ABI=softfp|-mthumb -mcpu=cortex-m4 -mfloat-abi=softfp -mfpu=fpv4-sp-d16
EOF
for args in "-DRT_ARM_FLOAT_ABI=half" "-DRT_ARM_CPU=cortex-m3 -DRT_ARM_FLOAT_ABI=hard"; do
    # shellcheck disable=SC2086 # args: -D options, one word each
    if got=$(arm_flags $args); then
        bad "arm-none-eabi.cmake $args: accepted ($got)"
    else
        echo "$got" | grep -q 'RT_ARM_FLOAT_ABI' && ok "arm-none-eabi.cmake $args: refused, naming RT_ARM_FLOAT_ABI" ||
            bad "arm-none-eabi.cmake $args: refused without naming RT_ARM_FLOAT_ABI: $got"
    fi
done

# rt.mk's float core for a Cortex-M4F, with the CPU's flags
# docs/embedding.md gives a Make project: FPU arithmetic and the FPU's
# square root, no call of the soft-float routines or libm (a sphere's
# intersection, the core's square roots).
m4flags="-mthumb -mcpu=cortex-m4 -mfloat-abi=hard -mfpu=fpv4-sp-d16"
rtflags=$(printf 'include rt.mk\nall:\n\t@echo $(RT_CFLAGS)\n' | make -s -f - RT_DIR=. RT_BACKEND=float)
# shellcheck disable=SC2086 # flags, one word each
if arm-none-eabi-gcc $m4flags -O2 -Werror $rtflags -c src/geometry/sphere.c -o "$out/sphere-m4f.o"; then
    calls=$(arm-none-eabi-nm -u "$out/sphere-m4f.o" | awk '{ print $2 }' | grep -E '^(__aeabi_f|sqrt)' | tr '\n' ' ')
    if [ -z "$calls" ] && arm-none-eabi-objdump -d "$out/sphere-m4f.o" | grep -q 'vsqrt\.f32'; then
        ok "rt.mk, Cortex-M4F float: FPU arithmetic and vsqrt.f32, no soft-float or libm calls (src/geometry/sphere.c)"
    else
        bad "rt.mk, Cortex-M4F float: src/geometry/sphere.c calls $calls(or has no vsqrt.f32)"
    fi
else
    bad "rt.mk, Cortex-M4F float: src/geometry/sphere.c did not compile with $m4flags $rtflags"
fi

# GNU make with rt.mk: examples/make/Makefile, which docs/embedding.md
# shows, in a project of this consumer's main.c and out_host.c with
# that scene as its scene.nff, built with -Werror.
mk="$out/make"
mkdir -p "$mk"
cp tests/host/consumer/main.c tests/host/consumer/out_host.c "$mk/" && cp "$scene" "$mk/scene.nff"
if log make make -C "$mk" -f "$PWD/examples/make/Makefile" RT_DIR="$PWD" CC="${CC:-cc} -Werror" APP_SRC="main.c out_host.c" &&
    "$mk/app" >"$out/make.ppm"; then
    same_image "make with rt.mk (examples/make/Makefile), host" "$out/make.ppm"
    pruned "make with rt.mk" "$mk/app"
else
    bad "make with rt.mk: examples/make/Makefile did not build or run"
fi
shown=$(awk '/^```make$/ { on = 1; next } on && /^```$/ { exit } on' docs/embedding.md)
if [ -n "$shown" ] && [ "$shown" = "$(cat examples/make/Makefile)" ]; then
    ok "docs/embedding.md shows examples/make/Makefile as it is ($(echo "$shown" | wc -l) lines)"
else
    bad "docs/embedding.md's make example differs from examples/make/Makefile"
fi

summary consumer
