# arm-none-eabi.cmake - CMake toolchain file for GNU Arm Embedded (bare
# metal), Cortex-M3 by default:
#
#   cmake -B build -DCMAKE_TOOLCHAIN_FILE=path/to/rt/cmake/arm-none-eabi.cmake [-DRT_ARM_CPU=cortex-m4]
#
# Compile flags only: the program's link options (linker script,
# -nostdlib or --specs=...) are the project's. Extra flags go in the CFLAGS
# environment variable at the first configure (a -DCMAKE_C_FLAGS=... on
# the command line would replace the -mcpu/-mthumb set here).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

if(NOT RT_ARM_CPU)
  set(RT_ARM_CPU cortex-m3)
endif()
set(RT_ARM_CPU "${RT_ARM_CPU}" CACHE STRING "-mcpu for arm-none-eabi-gcc")

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar CACHE FILEPATH "")
set(CMAKE_RANLIB arm-none-eabi-ranlib CACHE FILEPATH "")
set(CMAKE_C_FLAGS_INIT "-mcpu=${RT_ARM_CPU} -mthumb")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=${RT_ARM_CPU} -mthumb")

# No C library start-up to link a test program against: try-compile
# checks build a static library instead.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Programs (a host C compiler for the scene compiler) from the host;
# libraries and headers only from the target's sysroot.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
