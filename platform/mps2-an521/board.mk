# board.mk - ARM MPS2 AN521 under QEMU: the SSE-200 subsystem, two
# Cortex-M33 at 20 MHz, run entirely Secure. Core 0 has neither the FPU
# nor the DSP extension (QEMU's SSE-200 gives them to core 1 only: MVFR0
# reads 0 on core 0, a VFP instruction faults NOCP there and a DSP one
# UNDEFINSTR), and both cores run one image, so every build is soft-float
# and without DSP instructions. Variables: app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    := ARM MPS2 AN521, an FPGA board (QEMU's model), with two Cortex-M33, built without FPU or DSP
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m33+nofp+nodsp -mthumb
BOARD_QEMU     := qemu-system-arm -M mps2-an521
# sleep=off: with two cores running, the round-robin switch points (and
# so the run) are the same every time; with sleep on they vary
BOARD_ICOUNT   := shift=0,sleep=off
BOARD_PACKAGES := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
BOARD_CLOCK_HZ ?= 20000000
# no FPU usable by both cores: float and double are soft-float
BOARD_BACKENDS := fixed float double
BOARD_SRC      := platform/mps2-an521/board.c
BOARD_LD       := platform/mps2-an521/link.ld
# both cores render (app/firmware/bands.c, with port.h's multi-core
# part); make CORES=1 renders on core 0 alone
BOARD_CORES    := 2
# bands of one line: the finest split between the cores. Critical path on
# the showpiece at 64x64, as a share of one core's instructions: 0.5018
# (1 line), 0.5132 (2), 0.5302 (4); each band costs its set-up (+0.3%)
# With adaptive anti-aliasing each band traces its top row of cell
# corners again, so bands of 4 lines (balls-2 at 64x64, AA=3: 0.531 of one
# core's instructions, against 0.614 with one line and 0.525 with 8)
BOARD_BAND_LINES = $(if $(filter-out 0,$(AA_LEVELS)),4,1)
