# board.mk - BBC micro:bit (nRF51822) under QEMU: a Cortex-M0 at 16 MHz,
# 256 KiB flash, 16 KiB RAM, no FPU and no 32x32->64 multiply (the fixed
# layer's ARMv6-M path, src/numeric/fx_wide.h). Variables: app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    := BBC micro:bit (nRF51822) with a Cortex-M0, no FPU and 16 KiB of RAM
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m0 -mthumb
BOARD_QEMU     := qemu-system-arm -M microbit
BOARD_PACKAGES := gcc-arm-none-eabi qemu-system-arm
BOARD_CLOCK_HZ ?= 16000000
BOARD_BACKENDS := fixed
BOARD_SRC      := platform/microbit/board.c
BOARD_LD       := platform/microbit/link.ld

# 16 KiB of RAM: make run renders one sample a pixel (AA=1 fits at 128
# pixels wide: two rows of 257 cell corners)
BOARD_RUN_AA   := 0
