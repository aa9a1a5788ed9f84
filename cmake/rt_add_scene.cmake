# rt_add_scene.cmake - rt_add_scene(), the same function for the source
# tree (CMakeLists.txt includes it) and for the installed package
# (rtConfig.cmake includes it from lib/cmake/rt/). Who includes it sets
# three cache variables first:
#   RT_SCENEC            the scene compiler (source tree: built by the
#                        target rt_scenec; installed: bin/rt-scenec)
#   RT_INTERNAL_INCLUDE  the core's internal headers the tables include
#                        (src/; installed: include/rt/internal/)
#   RT_SCENE_PRUNABLE    ON when rt_core is built here and can be pruned
#                        for a scene (source tree), OFF for the installed,
#                        prebuilt library
#
# rt_add_scene(<target> <scene.nff> [PRUNE ON|OFF] [SPECIALISE ON|OFF])
#
# Compiles the NFF scene into const tables (scene_data.c, in the section
# .scene.tables) and adds them to <target>, which then renders
#   extern const rt_scene_t rt_scene;
# and whose files may #include "scene_data.h", what the scene uses and its
# resolution (SCENE_WIDTH, SCENE_HEIGHT).
# PRUNE ON (the default in the source tree) builds rt_core for this scene
# alone: the RT_USE_* switches of the generated scene_data.h (primitive
# kinds and shading features the scene does not use) are forced into
# every core source with -include, as the board firmware does. rt_core is
# one library, so a pruned core renders that scene alone: to link several
# scenes, give them all PRUNE OFF. The installed library is already
# compiled: PRUNE is OFF there, and ON is an error.
# SPECIALISE ON (the default where PRUNE is ON) goes further, as the board
# firmware's SPECIALISE=1: the tracer reads the scene as the constant
# rt_scene (-DRT_CONST_SCENE=rt_scene on rt_core) and rt_core, the tables
# and <target> are optimised whole (INTERPROCEDURAL_OPTIMIZATION; with GCC
# also -O3 and the firmware's unrolling limits), so the scene's counts,
# materials and positions fold into the code. It needs PRUNE ON.
function(rt_add_scene target scene)
  cmake_parse_arguments(PARSE_ARGV 2 ARG "" "PRUNE;SPECIALISE" "")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "rt_add_scene: unexpected arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT DEFINED ARG_PRUNE)
    set(ARG_PRUNE ${RT_SCENE_PRUNABLE})
  endif()
  if(NOT DEFINED ARG_SPECIALISE)
    set(ARG_SPECIALISE ${ARG_PRUNE})
  endif()
  if(ARG_SPECIALISE AND NOT ARG_PRUNE)
    message(FATAL_ERROR "rt_add_scene(${target} ...): SPECIALISE ON compiles rt_core for the scene: it needs PRUNE ON")
  endif()
  if(ARG_PRUNE AND NOT RT_SCENE_PRUNABLE)
    message(FATAL_ERROR "rt_add_scene(${target} ...): PRUNE ON recompiles rt_core for the scene, and the installed "
                        "rt::core is a compiled library: give PRUNE OFF, or add rt's source tree with "
                        "add_subdirectory() to prune")
  endif()
  if(TARGET rt_scenec)
    set(scenec_deps "${RT_SCENEC}" rt_scenec) # built here
    if(NOT RT_HOST_CC)
      message(FATAL_ERROR "rt_add_scene: no host C compiler found; set RT_HOST_CC")
    endif()
  elseif(EXISTS "${RT_SCENEC}")
    set(scenec_deps "${RT_SCENEC}")
  else()
    message(FATAL_ERROR "rt_add_scene: the scene compiler ${RT_SCENEC} is not there (rt was installed "
                        "without its tools: -DRT_BUILD_TOOLS=OFF)")
  endif()
  get_filename_component(scene "${scene}" ABSOLUTE)
  set(out "${CMAKE_CURRENT_BINARY_DIR}/rt_scene_${target}")
  add_custom_command(
    OUTPUT "${out}/scene_data.c" "${out}/scene_data.h"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${out}"
    COMMAND "${RT_SCENEC}" "${scene}" -o "${out}/scene_data.c" --header "${out}/scene_data.h"
    DEPENDS "${scene}" ${scenec_deps}
    COMMENT "Compiling scene ${scene}"
    VERBATIM)
  add_custom_target(rt_scene_${target}_tables DEPENDS "${out}/scene_data.c" "${out}/scene_data.h")
  # The tables as an object library with rt_core's flags, added to the
  # target without target_link_libraries (whose plain and keyword
  # signatures may not be mixed on one target).
  add_library(rt_scene_${target} OBJECT "${out}/scene_data.c")
  target_link_libraries(rt_scene_${target} PRIVATE rt::core)
  target_include_directories(rt_scene_${target} PRIVATE "${RT_INTERNAL_INCLUDE}")  # geometry/scene.h
  add_dependencies(rt_scene_${target} rt_scene_${target}_tables)
  target_sources(${target} PRIVATE $<TARGET_OBJECTS:rt_scene_${target}>)
  # the target's files may include scene_data.h (SCENE_WIDTH, SCENE_HEIGHT:
  # the resolution opts.width = 0 renders, to size the band buffer)
  target_include_directories(${target} PRIVATE "${out}")
  add_dependencies(${target} rt_scene_${target}_tables)

  # A pruned core renders its own scene only.
  get_property(pruned GLOBAL PROPERTY RT_PRUNED_FOR)
  get_property(others GLOBAL PROPERTY RT_SCENE_TARGETS)
  set_property(GLOBAL APPEND PROPERTY RT_SCENE_TARGETS ${target})
  if(pruned OR (ARG_PRUNE AND others))
    if(NOT pruned)
      set(pruned ${target})
    endif()
    message(FATAL_ERROR "rt_add_scene(${target} ...): rt_core would be pruned for ${pruned}'s scene and "
                        "also render another; give every scene PRUNE OFF to link several")
  endif()
  if(ARG_PRUNE)
    if(NOT CMAKE_C_COMPILER_ID MATCHES "GNU|Clang")
      message(FATAL_ERROR "rt_add_scene: PRUNE ON needs a compiler with -include (GCC, Clang); use PRUNE OFF")
    endif()
    set_property(GLOBAL PROPERTY RT_PRUNED_FOR ${target})
    target_compile_definitions(rt_core PRIVATE SCENE_PRUNE=1)
    target_compile_options(rt_core PRIVATE "SHELL:-include \"${out}/scene_data.h\"")
    add_dependencies(rt_core rt_scene_${target}_tables)
  endif()
  if(ARG_SPECIALISE)
    target_compile_definitions(rt_core PRIVATE RT_CONST_SCENE=rt_scene)
    include(CheckIPOSupported)
    check_ipo_supported(RESULT ipo OUTPUT why LANGUAGES C)
    if(ipo)
      set_property(TARGET rt_core rt_scene_${target} ${target} PROPERTY INTERPROCEDURAL_OPTIMIZATION TRUE)
    else()
      message(WARNING "rt_add_scene(${target} ...): no link-time optimisation here (${why}): the scene is read "
                      "as a constant, but not folded into the code")
    endif()
    if(CMAKE_C_COMPILER_ID STREQUAL "GNU")
      set(opt -O3 --param=max-completely-peel-times=64 --param=max-completely-peeled-insns=1000
              --param=max-inline-insns-single=1000 --param=large-function-growth=1000)
      target_compile_options(rt_core PRIVATE ${opt})
      target_link_options(${target} PRIVATE ${opt})
    endif()
  endif()
endfunction()
