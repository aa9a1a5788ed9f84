#!/bin/sh
# consumer-tests.sh RT [OUT]: the core as a user embeds it (tests/host/consumer/):
# configured and built with CMake for the host and cross compiled with
# cmake/arm-none-eabi.cmake, and with GNU make from rt.mk
# (examples/make/Makefile, the example docs/embedding.md shows). Each host
# program, and the firmware under QEMU, must write the image of
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
        -semihosting-config enable=on,target=native -kernel "$elf" </dev/null >"$out/arm.ppm"; then
        same_image "CMake, Cortex-M3 under QEMU" "$out/arm.ppm"
    else
        bad "CMake, Cortex-M3: the firmware failed under QEMU"
    fi
else
    bad "CMake, Cortex-M3: configure, build or link failed"
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
