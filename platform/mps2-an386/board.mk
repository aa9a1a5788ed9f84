# board.mk - ARM MPS2 AN386 under QEMU: a Cortex-M4F at 25 MHz with the
# single-precision FPU. Memory map and peripherals are the AN385's, so it
# uses that port's board.c and link.ld; every build is hard-float (the
# reset handler enables the FPU first). Variables: app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    := ARM MPS2 AN386, an FPGA board (QEMU's model), with a Cortex-M4F and its single-precision FPU
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m4 -mthumb
BOARD_FPU      := -mfpu=fpv4-sp-d16 -mfloat-abi=hard
BOARD_QEMU     := qemu-system-arm -M mps2-an386
BOARD_PACKAGES := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
BOARD_CLOCK_HZ ?= 25000000
BOARD_BACKENDS := fixed float double
BOARD_SRC      := platform/mps2-an385/board.c
BOARD_LD       := platform/mps2-an385/link.ld
