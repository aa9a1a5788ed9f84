#!/bin/sh
# make-package.sh OUT PREFIX BINDIR LIBDIR INCLUDEDIR POINTER-BYTES
#
# `make install`'s CMake package, what CMakeLists.txt's install(EXPORT) and
# CMakePackageConfigHelpers write for `cmake --install` (Release build):
# OUT/rtConfig.cmake (from cmake/rtConfig.cmake.in: BINDIR/rt-scenec and
# INCLUDEDIR/rt/internal for rt_add_scene), rtConfigVersion.cmake (same
# major version), rtTargets.cmake and rtTargets-release.cmake (the
# imported target rt::core: LIBDIR/librt_core.a, INCLUDEDIR/rt), and a
# copy of cmake/rt_add_scene.cmake. The folders are absolute (no
# DESTDIR); those under PREFIX are written relative to the package's own
# folder, LIBDIR/cmake/rt, so the tree can move, as CMake's are.
set -e
out=$1 prefix=${2%/} bindir=$3 libdir=$4 includedir=$5 ptr=$6
here=$(dirname "$0")
version=$(sed -n 's/^#define RT_VERSION_STRING "\([0-9.]*\)".*/\1/p' "$here/../include/rt_version.h")
[ -n "$version" ] || { echo "make-package.sh: no RT_VERSION_STRING in include/rt_version.h" >&2; exit 1; }
mkdir -p "$out"

# rel DIR: DIR relative to the prefix ("${_IMPORT_PREFIX}/..."), or as it is
rel() { # rel VAR-OF-PREFIX DIR
    case $2 in
        "$prefix"/*) echo "\${$1}/${2#"$prefix"/}" ;;
        "$prefix") echo "\${$1}" ;;
        *) echo "$2" ;;
    esac
}
# the prefix from the package's folder: up one folder a component of
# LIBDIR/cmake/rt under PREFIX, else PREFIX itself
case $libdir in
    "$prefix"/*)
        up=$(echo "${libdir#"$prefix"/}/cmake/rt" | tr '/' '\n' | grep -c .)
        to_prefix=$(i=0; while [ $i -lt "$up" ]; do printf '/..'; i=$((i + 1)); done)
        prefix_dir="\${CMAKE_CURRENT_LIST_DIR}$to_prefix/" ;;
    *) prefix_dir=$prefix ;;
esac

{
    sed -n '1,/^@PACKAGE_INIT@$/p' "$here/rtConfig.cmake.in" | sed '$d'
    cat <<END
####### @PACKAGE_INIT@ as configure_package_config_file() expands it, by cmake/make-package.sh

get_filename_component(PACKAGE_PREFIX_DIR "$prefix_dir" ABSOLUTE)

macro(check_required_components _NAME)
  foreach(comp \${\${_NAME}_FIND_COMPONENTS})
    if(NOT \${_NAME}_\${comp}_FOUND)
      if(\${_NAME}_FIND_REQUIRED_\${comp})
        set(\${_NAME}_FOUND FALSE)
      endif()
    endif()
  endforeach()
endmacro()

####################################################################################
END
    # PATH_VARS as configure_package_config_file() expands them
    sed -e '1,/^@PACKAGE_INIT@$/d' \
        -e "s|@PACKAGE_RT_INSTALL_SCENEC@|$(rel PACKAGE_PREFIX_DIR "$bindir")/rt-scenec|" \
        -e "s|@PACKAGE_RT_INSTALL_INTERNAL_INCLUDE@|$(rel PACKAGE_PREFIX_DIR "$includedir")/rt/internal|" \
        "$here/rtConfig.cmake.in"
} >"$out/rtConfig.cmake"
left=$(grep -v '^#' "$out/rtConfig.cmake" | grep -o '@[A-Z_]*@' | head -1) || true
if [ -n "$left" ]; then
    echo "make-package.sh: rtConfig.cmake.in has a variable this script does not expand: $left" >&2
    exit 1
fi
cp "$here/rt_add_scene.cmake" "$out/"

cat >"$out/rtConfigVersion.cmake" <<END
# rt's version for find_package(rt [VERSION] CONFIG), by cmake/make-package.sh:
# compatible with a request of the same major version, not above this one
# (CMakePackageConfigHelpers' SameMajorVersion), and built for
# $((ptr * 8))-bit pointers.
set(PACKAGE_VERSION "$version")
if(PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE FALSE)
else()
  string(REGEX REPLACE "^([0-9]+).*" "\\\\1" _rt_major "\${PACKAGE_VERSION}")
  if(PACKAGE_FIND_VERSION_RANGE)
    math(EXPR _rt_major_next "\${_rt_major} + 1")
    if(PACKAGE_FIND_VERSION_MIN_MAJOR STREQUAL _rt_major
       AND ((PACKAGE_FIND_VERSION_RANGE_MAX STREQUAL "INCLUDE" AND PACKAGE_FIND_VERSION_MAX_MAJOR STREQUAL _rt_major
             AND PACKAGE_VERSION VERSION_LESS_EQUAL PACKAGE_FIND_VERSION_MAX)
         OR (PACKAGE_FIND_VERSION_RANGE_MAX STREQUAL "EXCLUDE" AND PACKAGE_FIND_VERSION_MAX VERSION_LESS_EQUAL _rt_major_next
             AND PACKAGE_VERSION VERSION_LESS PACKAGE_FIND_VERSION_MAX)))
      set(PACKAGE_VERSION_COMPATIBLE TRUE)
    else()
      set(PACKAGE_VERSION_COMPATIBLE FALSE)
    endif()
  else()
    if(PACKAGE_FIND_VERSION_MAJOR STREQUAL _rt_major)
      set(PACKAGE_VERSION_COMPATIBLE TRUE)
    else()
      set(PACKAGE_VERSION_COMPATIBLE FALSE)
    endif()
    if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
      set(PACKAGE_VERSION_EXACT TRUE)
    endif()
  endif()
  unset(_rt_major)
  unset(_rt_major_next)
endif()
if(NOT "\${CMAKE_SIZEOF_VOID_P}" STREQUAL "" AND NOT CMAKE_SIZEOF_VOID_P STREQUAL "$ptr")
  set(PACKAGE_VERSION "\${PACKAGE_VERSION} ($((ptr * 8))bit)")
  set(PACKAGE_VERSION_UNSUITABLE TRUE)
endif()
END

cat >"$out/rtTargets.cmake" <<END
# The imported target rt::core, as install(EXPORT) writes it; by
# cmake/make-package.sh for \`make install\`.
cmake_policy(PUSH)
cmake_policy(VERSION 3.16)
if(TARGET rt::core)
  cmake_policy(POP)
  return()
endif()

get_filename_component(_IMPORT_PREFIX "$prefix_dir" ABSOLUTE)
if(_IMPORT_PREFIX STREQUAL "/")
  set(_IMPORT_PREFIX "")
endif()

add_library(rt::core STATIC IMPORTED)
set_target_properties(rt::core PROPERTIES
  INTERFACE_COMPILE_FEATURES "c_std_11"
  INTERFACE_INCLUDE_DIRECTORIES "$(rel _IMPORT_PREFIX "$includedir")/rt"
)

# Load information for each installed configuration.
file(GLOB _rt_config_files "\${CMAKE_CURRENT_LIST_DIR}/rtTargets-*.cmake")
foreach(_rt_config_file IN LISTS _rt_config_files)
  include("\${_rt_config_file}")
endforeach()
unset(_rt_config_file)
unset(_rt_config_files)

foreach(_rt_file IN LISTS _rt_import_check_files)
  if(NOT EXISTS "\${_rt_file}")
    message(FATAL_ERROR "rt::core: \${_rt_file}, which \${CMAKE_CURRENT_LIST_FILE} names, does not exist")
  endif()
endforeach()
unset(_rt_file)
unset(_rt_import_check_files)
set(_IMPORT_PREFIX)
cmake_policy(POP)
END

cat >"$out/rtTargets-release.cmake" <<END
# rt::core for the configuration "Release" (make install: -O2), by
# cmake/make-package.sh.
set_property(TARGET rt::core APPEND PROPERTY IMPORTED_CONFIGURATIONS RELEASE)
set_target_properties(rt::core PROPERTIES
  IMPORTED_LINK_INTERFACE_LANGUAGES_RELEASE "C"
  IMPORTED_LOCATION_RELEASE "$(rel _IMPORT_PREFIX "$libdir")/librt_core.a"
)
list(APPEND _rt_import_check_files "$(rel _IMPORT_PREFIX "$libdir")/librt_core.a")
END
