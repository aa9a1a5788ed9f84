# arm-none-eabi.cmake - CMake toolchain file for GNU Arm Embedded (bare
# metal), Cortex-M3 by default:
#
#   cmake -B build -DCMAKE_TOOLCHAIN_FILE=path/to/rt/cmake/arm-none-eabi.cmake [-DRT_ARM_CPU=cortex-m4]
#         [-DRT_ARM_FPU=fpv5-d16] [-DRT_ARM_FLOAT_ABI=hard|softfp|soft]
#
# RT_ARM_CPU is -mcpu. A core with an FPU brings it: the Cortex-M4F, M7
# and M33 build hard float by default (the FPU of the table below,
# -mfloat-abi=hard), every other core soft float. RT_ARM_FPU names another
# FPU (an M7 with the double-precision fpv5-d16), RT_ARM_FLOAT_ABI=soft
# builds soft float (a Cortex-M4 or M33 without the FPU, or to link with
# soft-float libraries), softfp the FPU with the soft-float calling
# convention. Every object of a program must be built with the same ABI:
# these flags go to every C and assembly file and to the link (which
# picks the matching libgcc and C library).
#
# Compile flags only: the program's link options (linker script,
# -nostdlib or --specs=...) are the project's. Extra flags go in the CFLAGS
# environment variable at the first configure (a -DCMAKE_C_FLAGS=... on
# the command line would replace the flags set here); the flags are set
# at the first configure: another core needs a new build folder.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

# The FPU of each core that has one (the M4F's single precision; the M7's
# and M33's single precision, which every M7 and M33 with an FPU has).
set(_rt_arm_fpu_cortex-m4 fpv4-sp-d16)
set(_rt_arm_fpu_cortex-m7 fpv5-sp-d16)
set(_rt_arm_fpu_cortex-m33 fpv5-sp-d16)

if(NOT RT_ARM_CPU)
  set(RT_ARM_CPU cortex-m3)
endif()
set(RT_ARM_CPU "${RT_ARM_CPU}" CACHE STRING "-mcpu for arm-none-eabi-gcc")
if(NOT RT_ARM_FPU)
  if(DEFINED _rt_arm_fpu_${RT_ARM_CPU})
    set(RT_ARM_FPU ${_rt_arm_fpu_${RT_ARM_CPU}})
  else()
    set(RT_ARM_FPU none)
  endif()
endif()
set(RT_ARM_FPU "${RT_ARM_FPU}" CACHE STRING "-mfpu for arm-none-eabi-gcc (none: soft float)")
if(NOT RT_ARM_FLOAT_ABI)
  if(RT_ARM_FPU STREQUAL "none")
    set(RT_ARM_FLOAT_ABI soft)
  else()
    set(RT_ARM_FLOAT_ABI hard)
  endif()
endif()
set(RT_ARM_FLOAT_ABI "${RT_ARM_FLOAT_ABI}" CACHE STRING "-mfloat-abi for arm-none-eabi-gcc: hard, softfp or soft")
set_property(CACHE RT_ARM_FLOAT_ABI PROPERTY STRINGS hard softfp soft)
if(NOT RT_ARM_FLOAT_ABI MATCHES "^(hard|softfp|soft)$")
  message(FATAL_ERROR "RT_ARM_FLOAT_ABI must be hard, softfp or soft, not '${RT_ARM_FLOAT_ABI}'")
endif()
if(NOT RT_ARM_FLOAT_ABI STREQUAL "soft" AND RT_ARM_FPU STREQUAL "none")
  message(FATAL_ERROR "RT_ARM_FLOAT_ABI=${RT_ARM_FLOAT_ABI} needs an FPU, and ${RT_ARM_CPU} has none here: "
                      "give its -mfpu as RT_ARM_FPU, or RT_ARM_FLOAT_ABI=soft")
endif()

# -mthumb first, which every Cortex-M implies: CMake's compiler check
# drops the word after a -Werror in CFLAGS, and it must not be -mcpu
set(_rt_arm_flags "-mthumb -mcpu=${RT_ARM_CPU} -mfloat-abi=${RT_ARM_FLOAT_ABI}")
if(NOT RT_ARM_FLOAT_ABI STREQUAL "soft")
  string(APPEND _rt_arm_flags " -mfpu=${RT_ARM_FPU}")
endif()
# the same choice in every try_compile (which reads this file again)
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES RT_ARM_CPU RT_ARM_FPU RT_ARM_FLOAT_ABI)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar CACHE FILEPATH "")
set(CMAKE_RANLIB arm-none-eabi-ranlib CACHE FILEPATH "")
set(CMAKE_C_FLAGS_INIT "${_rt_arm_flags}")
set(CMAKE_ASM_FLAGS_INIT "${_rt_arm_flags}")

# No C library start-up to link a test program against: try-compile
# checks build a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Programs (a host C compiler for the scene compiler) from the host;
# libraries and headers only from the target's sysroot.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
