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
# materials and positions fold into the code. It needs PRUNE ON. Where
# the toolchain cannot optimise whole (_rt_ipo_check, below), the
# configure says so in one line and the core stays generic.
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
    _rt_ipo_check(ipo why)
    if(ipo)
      set_property(TARGET rt_core rt_scene_${target} ${target} PROPERTY INTERPROCEDURAL_OPTIMIZATION TRUE)
    else()
      message(NOTICE "rt_add_scene(${target} ...): no link-time optimisation (${why}): the scene is read "
                     "as a constant, but not folded into the code")
    endif()
    if(CMAKE_C_COMPILER_ID STREQUAL "GNU")
      set(opt -O3 --param=max-completely-peel-times=64 --param=max-completely-peeled-insns=1000
              --param=max-inline-insns-single=1000 --param=large-function-growth=1000)
      target_compile_options(rt_core PRIVATE ${opt})
      # the link compiles the whole program: with the core's own options
      # (the float backend's) as well
      get_property(core_opt TARGET rt_core PROPERTY RT_LINK_TIME_OPTIONS)
      target_link_options(${target} PRIVATE ${opt} ${core_opt})
    endif()
  endif()
endfunction()

# _rt_ipo_check(<ok> <why>): whether this compiler and linker optimise a
# program whole (CMake's INTERPROCEDURAL_OPTIMIZATION), tried on a static
# library and a program linked from it, built with the project's flags
# (a toolchain file's -mcpu, -mfpu and -mfloat-abi among them) and with
# neither start-up code nor C library, which a bare-metal program brings
# itself: CMake's check_ipo_supported links against both and fails there.
# Quiet; once per build folder and flags; <why> is the build's first error
# line (its whole output: CMakeFiles/rt_ipo_check/output.log).
function(_rt_ipo_check out_ok out_why)
  get_property(multi GLOBAL PROPERTY GENERATOR_IS_MULTI_CONFIG)
  set(config "${CMAKE_BUILD_TYPE}")
  if(multi OR NOT config)
    set(config Release)
  endif()
  string(TOUPPER "${config}" cfg)
  set(key "${CMAKE_C_COMPILER}|${CMAKE_C_FLAGS}|${CMAKE_C_FLAGS_${cfg}}|${CMAKE_EXE_LINKER_FLAGS}|${config}")
  if(NOT key STREQUAL "${RT_IPO_CHECK_KEY}")
    set(dir "${CMAKE_BINARY_DIR}/CMakeFiles/rt_ipo_check")
    file(REMOVE_RECURSE "${dir}")
    file(WRITE "${dir}/src/CMakeLists.txt"
         "cmake_minimum_required(VERSION 3.16)\n"
         "project(rt_ipo_check C)\n"
         "add_library(twice STATIC twice.c)\n"
         "add_executable(prog prog.c)\n"
         "target_link_libraries(prog PRIVATE twice)\n"
         "target_link_options(prog PRIVATE -nostdlib -nostartfiles)\n"
         "set_property(TARGET twice prog PROPERTY INTERPROCEDURAL_OPTIMIZATION TRUE)\n")
    file(WRITE "${dir}/src/twice.c" "int rt_ipo_twice(int x);\nint rt_ipo_twice(int x) { return 2 * x; }\n")
    # the entry point the linker looks for by default
    file(WRITE "${dir}/src/prog.c"
         "int rt_ipo_twice(int x);\nvoid _start(void);\nvolatile int rt_ipo_value;\n"
         "void _start(void)\n{\n    for (;;)\n        rt_ipo_value = rt_ipo_twice(rt_ipo_value);\n}\n")
    set(vars "")
    foreach(v RT_ARM_CPU RT_ARM_FPU RT_ARM_FLOAT_ABI)
      if(DEFINED ${v})
        list(APPEND vars "-D${v}=${${v}}")
      endif()
    endforeach()
    try_compile(ok PROJECT rt_ipo_check SOURCE_DIR "${dir}/src" BINARY_DIR "${dir}/bin"
                CMAKE_FLAGS "-DCMAKE_BUILD_TYPE=${config}" "-DCMAKE_C_FLAGS=${CMAKE_C_FLAGS}"
                            "-DCMAKE_C_FLAGS_${cfg}=${CMAKE_C_FLAGS_${cfg}}"
                            "-DCMAKE_EXE_LINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}" ${vars}
                OUTPUT_VARIABLE output)
    file(WRITE "${dir}/output.log" "${output}")
    set(why "")
    if(NOT ok)
      # the first line that says what failed (not make's or collect2's
      # summary of it), the tool's folder left out
      string(REPLACE ";" "," lines "${output}")
      string(REPLACE "\n" ";" lines "${lines}")
      foreach(line IN LISTS lines)
        if(line MATCHES "[Ee]rror|undefined reference|unrecogni[sz]ed|not supported|cannot find"
           AND NOT line MATCHES "^collect2|\\*\\*\\*")
          string(REGEX REPLACE "^[^ :]*/" "" why "${line}")
          string(STRIP "${why}" why)
          break()
        endif()
      endforeach()
      if(why STREQUAL "")
        set(why "the test program did not build")
      endif()
      set(why "${why}; see ${dir}/output.log")
    endif()
    set(RT_IPO_CHECK_KEY "${key}" CACHE INTERNAL "the flags _rt_ipo_check tried")
    set(RT_IPO_CHECK_OK "${ok}" CACHE INTERNAL "whether link-time optimisation works with them")
    set(RT_IPO_CHECK_WHY "${why}" CACHE INTERNAL "why not")
  endif()
  set(${out_ok} "${RT_IPO_CHECK_OK}" PARENT_SCOPE)
  set(${out_why} "${RT_IPO_CHECK_WHY}" PARENT_SCOPE)
endfunction()
