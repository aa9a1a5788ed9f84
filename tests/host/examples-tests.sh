#!/bin/sh
# The examples (examples/): each builds against rt.h alone (plus the core's
# sources, as a user's build would compile them), runs on the host and
# must give the same pixels as `rt` renders the same scene: the LVGL-style
# DMA sink in RGB565 big-endian stepping the frame, the Zephyr-style sink
# with a pitch, and the tiled render through a 16-line buffer; the Make
# project examples/make as shipped, built and run as docs/embedding.md
# says.
RT=${1:-build/asan/rt}
OUT=${2:-build/test-examples}
SCENE=scenes/spd/balls-1.nff
mkdir -p "$OUT"
. tests/lib/check.sh

# name, rt options giving the same frame
for spec in "lvgl_flush:--size 64x64 --format rgb565be" "zephyr_display:--size 64x64" "tiled:--size 96x80"; do
    name=${spec%%:*} opts=${spec#*:}
    if ! cc -std=c11 -Wall -Wextra -Werror -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined \
            -Iinclude -Isrc -Iexamples -o "$OUT/$name" "examples/$name.c" src/*.c src/*/*.c -lm 2>"$OUT/$name.build"; then
        bad "$name: build failed: $(head -3 "$OUT/$name.build")"
        continue
    fi
    if ! "$OUT/$name" $SCENE "$OUT/$name.ppm" >"$OUT/$name.log" 2>&1; then
        bad "$name: run failed: $(head -3 "$OUT/$name.log")"
        continue
    fi
    "$RT" $SCENE -o "$OUT/$name-ref.png" $opts --quiet
    if cmp=$("$RT" compare "$OUT/$name.ppm" "$OUT/$name-ref.png" --max-error 0); then
        ok "$name: same pixels as rt $opts ($(head -1 "$OUT/$name.log" | sed 's/^[a-z_]*: //'))"
    else
        bad "$name: differs from rt $opts: $cmp"
    fi
done
# examples/make as shipped, built as docs/embedding.md says (make in the
# project with RT_DIR set to rt's tree) into a folder of its own
# (BUILD=dir, which leaves the project's folder as it was): its program
# writes rt --fixed's image of its scene.nff byte for byte, 60 dB or more
# from the exact double reference, and the build warns of nothing.
mk=$(cd "$OUT" && pwd)/make
rm -rf "$mk"
before=$(ls -l --time-style=+%s.%N examples/make)
if make -C examples/make RT_DIR=../.. BUILD="$mk" >"$OUT/make.log" 2>&1 && "$mk/app" "$mk/scene.ppm" >>"$OUT/make.log" 2>&1; then
    "$RT" examples/make/scene.nff -o "$OUT/make-fixed.png" --fixed --quiet
    "$RT" examples/make/scene.nff -o "$OUT/make-double.png" --double --quiet
    check "examples/make: ./app == rt --fixed" "$RT" compare "$mk/scene.ppm" "$OUT/make-fixed.png" --max-error 0
    check "examples/make: ./app vs the exact double" "$RT" compare "$mk/scene.ppm" "$OUT/make-double.png" --psnr-min 60
    ! grep -q 'warning:' "$OUT/make.log" && [ "$(ls -l --time-style=+%s.%N examples/make)" = "$before" ] &&
        ok "examples/make: no warning; the project's folder as it was ($(ls examples/make | tr '\n' ' '))" ||
        bad "examples/make: warnings ($(grep -c 'warning:' "$OUT/make.log")) or the project's folder changed: $(ls examples/make | tr '\n' ' ')"
else
    bad "examples/make: make -C examples/make RT_DIR=../.. failed: $(grep -m3 'error\|No rule' "$OUT/make.log")"
fi

# rt_camera_from_view: another viewpoint for a const scene (tests/host/camera_view.c).
if cc -std=c11 -Wall -Wextra -Werror -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined \
      -Iinclude -Isrc -o "$OUT/camera_view" tests/host/camera_view.c src/*.c src/*/*.c -lm 2>"$OUT/camera_view.build"; then
    "$OUT/camera_view" >"$OUT/camera_view.log" 2>&1
    st=$?
    relay "$OUT/camera_view.log"
    [ $st -eq 0 ] || grep -q FAIL "$OUT/camera_view.log" || { bad "camera_view exited $st"; }
else
    bad "camera_view: build failed: $(head -3 "$OUT/camera_view.build")"
fi

# The installed library: `cmake --install` without the host tools
# (RT_BUILD_TOOLS=OFF; tests/host/install-tests.sh installs them) gives
# librt_core.a, the headers and the CMake package; an example builds
# against the public headers alone, nm on the library shows only rt_/RT_
# global symbols, and rt_add_scene from that package (no rt-scenec) is a
# configure error that says why.
inst="$OUT/install"
rm -rf "$OUT/cmake" "$inst"
if cmake -S . -B "$OUT/cmake" -DCMAKE_INSTALL_PREFIX="$inst" -DRT_BUILD_TOOLS=OFF >"$OUT/cmake.log" 2>&1 &&
   cmake --build "$OUT/cmake" -j2 >>"$OUT/cmake.log" 2>&1 && cmake --install "$OUT/cmake" >>"$OUT/cmake.log" 2>&1; then
    headers=$(cd "$inst/include/rt" && ls *.h | tr '\n' ' ')
    if cc -std=c11 -Wall -Wextra -Werror -I"$inst/include/rt" -Iexamples -o "$OUT/installed" \
          examples/zephyr_display.c "$inst/lib/librt_core.a" 2>"$OUT/installed.build" &&
       "$OUT/installed" $SCENE "$OUT/installed.ppm" >/dev/null &&
       "$RT" compare "$OUT/installed.ppm" "$OUT/zephyr_display-ref.png" --max-error 0 >/dev/null; then
        ok "installed library: an example built on $headers and librt_core.a renders the same pixels"
    else
        bad "installed library: the example did not build or differs: $(head -3 "$OUT/installed.build")"
    fi
    syms=$(nm -g --defined-only "$inst/lib/librt_core.a" | awk 'NF == 3 { n++; if ($3 !~ /^(rt_|RT_)/) bad = bad " " $3 }
                                                              END { print (bad ? "unprefixed:" bad : n " global symbols, all rt_/RT_") }')
    case $syms in
        unprefixed*) bad "nm librt_core.a: $syms" ;;
        *) ok "nm librt_core.a: $syms" ;;
    esac
    mkdir -p "$OUT/no-scenec" && : >"$OUT/no-scenec/main.c"
    printf '%s\n' 'cmake_minimum_required(VERSION 3.16)' 'project(no_scenec C)' 'find_package(rt CONFIG REQUIRED)' \
        'add_executable(app main.c)' 'rt_add_scene(app scene.nff)' >"$OUT/no-scenec/CMakeLists.txt"
    if cmake -S "$OUT/no-scenec" -B "$OUT/no-scenec/b" -DCMAKE_PREFIX_PATH="$(cd "$inst" && pwd)" >"$OUT/no-scenec.log" 2>&1; then
        bad "rt_add_scene from a package without rt-scenec configured"
    elif tr -s ' \n' '  ' <"$OUT/no-scenec.log" | grep -q "rt-scenec is not there (rt was installed without its tools"; then
        ok "rt_add_scene from a package without its tools: a configure error naming the missing rt-scenec"
    else
        bad "rt_add_scene without rt-scenec failed otherwise: $(grep -m1 -A2 'CMake Error' "$OUT/no-scenec.log")"
    fi
else
    bad "cmake build or install of the library failed: $(tail -3 "$OUT/cmake.log")"
fi
summary examples-tests
