# board.mk - ARM MPS2 AN385 under QEMU: a Cortex-M3 at 25 MHz, no FPU.
# The port contract and the variables are in app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    := ARM MPS2 AN385, an FPGA board (QEMU's model), with a Cortex-M3 and no FPU
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m3 -mthumb
BOARD_QEMU     := qemu-system-arm -M mps2-an385
BOARD_PACKAGES := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
BOARD_CLOCK_HZ ?= 25000000
# no FPU: float and double are soft-float (libgcc's __aeabi_f*/__aeabi_d*)
BOARD_BACKENDS := fixed float double
BOARD_SRC      := platform/mps2-an385/board.c
BOARD_LD       := platform/mps2-an385/link.ld
