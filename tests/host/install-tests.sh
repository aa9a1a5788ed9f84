#!/bin/sh
# install-tests.sh RT [OUT]: `make install` and `cmake --install`.
#   - make install DESTDIR=OUT/destdir PREFIX=/usr/local lays out exactly
#     bin/rt, bin/rt-scenec, lib/librt_core.a, include/rt/ (the public
#     headers), include/rt/internal/ (every header of src/, its folders
#     kept) and lib/cmake/rt/ (the CMake package and rt_add_scene.cmake);
#   - the installed rt renders balls-1 byte for byte as RT does, and the
#     installed rt-scenec compiles it into tables;
#   - a consumer project finds the package with find_package(rt CONFIG)
#     through CMAKE_PREFIX_PATH (in the DESTDIR tree, so the package is
#     relocatable), links rt::core and renders the same pixels as RT;
#   - an outside project on the package alone (tests/host/consumer/main.c, the
#     scene in flash) calls rt_add_scene on balls-1 and renders RT's
#     --fixed pixels byte for byte; so does the same program built with
#     cc from the installed rt-scenec's tables, the installed headers
#     (-I include/rt -I include/rt/internal) and librt_core.a; and
#     rt_add_scene(... PRUNE ON) is a configure error naming PRUNE OFF;
#   - make uninstall removes every file;
#   - cmake --install (RT_BUILD_TOOLS on, its default) lays out the same
#     files, and its rt, rt-scenec and package give the same results.
rt=${1:-build/host/rt} out=${2:-build/test-install}
SCENE=scenes/spd/balls-1.nff
. tests/lib/check.sh
rm -rf "$out"
mkdir -p "$out"
out=$(cd "$out" && pwd)
"$rt" $SCENE --size 32x32 --fixed -o "$out/ref.ppm" --quiet || bad "rt: reference render"
"$rt" $SCENE --size 64x64 --fixed -o "$out/ref64.ppm" --quiet || bad "rt: reference render, 64x64"

# the internal headers from the tree (their list is src/'s), the rest by name
expected=$({ echo "bin/rt
bin/rt-scenec
include/rt/rt.h
include/rt/rt_config.h
include/rt/rt_error.h
include/rt/rt_fb.h
include/rt/rt_render.h
include/rt/rt_stats.h
include/rt/rt_version.h
lib/cmake/rt/rtConfig.cmake
lib/cmake/rt/rtConfigVersion.cmake
lib/cmake/rt/rtTargets-release.cmake
lib/cmake/rt/rtTargets.cmake
lib/cmake/rt/rt_add_scene.cmake
lib/librt_core.a"
    (cd src && find . -name '*.h') | sed 's|^\./|include/rt/internal/|'; } | LC_ALL=C sort)
[ "$(echo "$expected" | grep -c '^include/rt/internal/geometry/scene.h$')" = 1 ] || bad "no src/geometry/scene.h?"
files() { (cd "$1" && find . -type f -o -type l | sed 's|^\./||' | LC_ALL=C sort); }
# same_pixels IMAGE REF: IMAGE has REF's pixels, byte for byte
same_pixels() { "$rt" compare "$1" "$2" --max-error 0 >/dev/null; }
# cmake_project NAME SRC PREFIX: configure and build the CMake project SRC
# against the package installed under PREFIX, into $out/NAME (logs
# $out/NAME.log and $out/NAME-build.log)
cmake_project() { log "$1" cmake -S "$2" -B "$out/$1" -DCMAKE_PREFIX_PATH="$3" && log "$1-build" cmake --build "$out/$1"; }

# tools PREFIX WHAT: the installed rt and rt-scenec work
tools() {
    p=$1 what=$2
    if "$p/bin/rt" $SCENE --size 32x32 -o "$out/$what.png" --quiet && same_pixels "$out/$what.png" "$out/ref.ppm"; then
        ok "$what: the installed rt renders $SCENE as $rt does, byte for byte"
    else
        bad "$what: the installed rt failed or differs ($("$rt" compare "$out/$what.png" "$out/ref.ppm" 2>&1))"
    fi
    mkdir -p "$out/$what-tables"
    if "$p/bin/rt-scenec" $SCENE -o "$out/$what-tables/scene_data.c" --header "$out/$what-tables/scene_data.h" &&
        grep -q 'rt_scene' "$out/$what-tables/scene_data.c" && [ -s "$out/$what-tables/scene_data.h" ]; then
        ok "$what: the installed rt-scenec compiles $SCENE ($(wc -c <"$out/$what-tables/scene_data.c") bytes of tables)"
    else
        bad "$what: the installed rt-scenec failed on $SCENE"
    fi
}

# consumer PREFIX WHAT: find_package(rt CONFIG) from PREFIX, rt::core, an example
consumer() {
    p=$1 what=$2 src=$out/consumer-src
    mkdir -p "$src"
    cp examples/zephyr_display.c examples/common.h "$src/"
    cat >"$src/CMakeLists.txt" <<'END'
cmake_minimum_required(VERSION 3.16)
project(installed_consumer C)
find_package(rt 0.1 CONFIG REQUIRED)
add_executable(consumer zephyr_display.c)
target_link_libraries(consumer PRIVATE rt::core)
get_target_property(inc rt::core INTERFACE_INCLUDE_DIRECTORIES)
message(STATUS "rt ${rt_VERSION} from ${rt_DIR}, rt::core includes ${inc}")
END
    b="$out/consumer-$what"
    if cmake_project "consumer-$what" "$src" "$p"; then
        if grep -q "from $p/lib/cmake/rt, rt::core includes $p/include/rt" "$out/consumer-$what.log"; then
            ok "$what: find_package(rt CONFIG) finds $(sed -n 's/.*-- rt \([0-9.]*\) from.*/\1/p' "$out/consumer-$what.log") in the installed tree; rt::core links"
        else
            bad "$what: find_package(rt) found another tree: $(grep -- '-- rt ' "$out/consumer-$what.log")"
        fi
        if "$b/consumer" $SCENE "$out/consumer-$what.ppm" >/dev/null && same_pixels "$out/consumer-$what.ppm" "$out/ref64.ppm"; then
            ok "$what: the consumer on rt::core renders the same pixels as rt"
        else
            bad "$what: the consumer failed or differs from rt"
        fi
    else
        bad "$what: the consumer did not configure or build against the package"
    fi
}

# scene_consumer PREFIX WHAT: an outside project on the installed package
# alone: rt_add_scene with CMake, then cc with the installed files
scene_consumer() {
    p=$1 what=$2 src=$out/scene-consumer-src
    mkdir -p "$src"
    cp tests/host/consumer/main.c tests/host/consumer/out_host.c "$src/"
    # main.c renders the scene's resolution: RT's reference size
    sed 's/^resolution .*/resolution 32 32/' $SCENE >"$src/balls-1.nff"
    cat >"$src/CMakeLists.txt" <<'END'
cmake_minimum_required(VERSION 3.16)
project(installed_scene_consumer C)
find_package(rt CONFIG REQUIRED)
add_executable(consumer main.c out_host.c)
target_link_libraries(consumer PRIVATE rt::core)
rt_add_scene(consumer balls-1.nff ${SCENE_ARGS})
END
    b="$out/scene-consumer-$what"
    if cmake_project "scene-consumer-$what" "$src" "$p"; then
        if "$b/consumer" >"$out/scene-consumer-$what.ppm" && same_pixels "$out/scene-consumer-$what.ppm" "$out/ref.ppm"; then
            ok "$what: an outside project's rt_add_scene (find_package, the installed rt-scenec) renders $SCENE as rt --fixed, byte for byte"
        else
            bad "$what: the rt_add_scene consumer failed or differs from rt --fixed"
        fi
    else
        bad "$what: an outside project with find_package(rt) and rt_add_scene did not configure or build"
    fi
    if cmake -S "$src" -B "$b-prune" -DCMAKE_PREFIX_PATH="$p" -DSCENE_ARGS="PRUNE;ON" \
        >"$out/scene-consumer-$what-prune.log" 2>&1; then
        bad "$what: rt_add_scene(... PRUNE ON) on the installed library configured"
    elif tr -s ' \n' '  ' <"$out/scene-consumer-$what-prune.log" | grep -q "PRUNE ON recompiles rt_core .* give PRUNE OFF"; then
        ok "$what: rt_add_scene(... PRUNE ON) on the prebuilt library is a configure error naming PRUNE OFF"
    else
        bad "$what: rt_add_scene(... PRUNE ON) failed without the PRUNE message: $(grep -m1 Error "$out/scene-consumer-$what-prune.log")"
    fi
    c="$out/scene-cc-$what"
    mkdir -p "$c"
    if "$p/bin/rt-scenec" "$src/balls-1.nff" -o "$c/scene_data.c" --header "$c/scene_data.h" &&
        log "scene-cc-$what" ${CC:-cc} -std=c11 -Wall -Wextra -Wundef -Werror -I"$p/include/rt" -I"$p/include/rt/internal" -I"$c" \
            -o "$c/consumer" "$c/scene_data.c" "$src/main.c" "$src/out_host.c" "$p/lib/librt_core.a" &&
        "$c/consumer" >"$c/out.ppm" && same_pixels "$c/out.ppm" "$out/ref.ppm"; then
        ok "$what: the installed rt-scenec's tables compile with cc against the installed headers alone and render as rt --fixed"
    else
        bad "$what: the installed rt-scenec's tables did not compile, link or render as rt --fixed with the installed files ($(tail -3 "$out/scene-cc-$what.log" 2>/dev/null))"
    fi
}

# make install
dest="$out/destdir"
if log make-install make -s -j2 install DESTDIR="$dest" PREFIX=/usr/local; then
    got=$(files "$dest/usr/local")
    if [ "$got" = "$expected" ]; then
        ok "make install: $(echo "$got" | wc -l) files under DESTDIR/usr/local, as expected"
    else
        bad "make install: files differ from the expected ones: $(echo "$got" | tr '\n' ' ')"
    fi
    modes=$(cd "$dest/usr/local" && for f in $got; do
        case $f in bin/*) want=755 ;; *) want=644 ;; esac
        [ "$(stat -c %a "$f")" = $want ] || printf ' %s' "$f"
    done)
    if [ -z "$modes" ]; then
        ok "make install: programs 755, the other files 644"
    else
        bad "make install: wrong modes:$modes"
    fi
    tools "$dest/usr/local" "make install"
    consumer "$dest/usr/local" "make install"
    scene_consumer "$dest/usr/local" "make install"
else
    bad "make install failed"
    got=""
fi

if [ -n "$got" ] && log make-uninstall make -s uninstall DESTDIR="$dest" PREFIX=/usr/local; then
    left=$(files "$dest/usr/local")
    if [ -z "$left" ]; then
        ok "make uninstall: removes every installed file"
    else
        bad "make uninstall: left $(echo "$left" | tr '\n' ' ')"
    fi
fi

# cmake --install
if log cmake-configure cmake -S . -B "$out/b" && log cmake-build cmake --build "$out/b" -j2 &&
    log cmake-install cmake --install "$out/b" --prefix "$out/c"; then
    cgot=$(files "$out/c")
    if [ -n "$got" ] && [ "$cgot" = "$got" ]; then
        ok "cmake --install: the same $(echo "$cgot" | wc -l) files as make install"
    else
        bad "cmake --install: files differ from make install's: $(echo "$cgot" | tr '\n' ' ')"
    fi
    tools "$out/c" "cmake --install"
    if cmp -s "$out/make install-tables/scene_data.c" "$out/cmake --install-tables/scene_data.c" &&
        cmp -s "$out/make install-tables/scene_data.h" "$out/cmake --install-tables/scene_data.h"; then
        ok "the two rt-scenec write the same tables"
    else
        bad "the rt-scenec of make install and cmake --install write different tables"
    fi
    consumer "$out/c" "cmake --install"
    scene_consumer "$out/c" "cmake --install"
else
    bad "cmake configure, build or install failed"
fi

summary install-tests
