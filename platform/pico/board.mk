# board.mk - Raspberry Pi Pico (RP2040) under rp2040js (Node.js), not
# QEMU: one Cortex-M0+ at 125 MHz (the second core is not emulated), 2 MiB
# of flash, 256 KiB of SRAM, no FPU, no divide instruction (the SIO
# divider instead: PICO_DIVIDER), and an ST7789 320x240 panel on SPI0
# where the frame goes (st7789.c, by DMA). Report lines go over UART0.
# run.mjs runs it, with rp2040js pinned in package.json (npm ci, by
# platform/ensure-deps.sh). Variables: platform/firmware/firmware.mk.
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m0plus -mthumb
# no QEMU: run.mjs runs it (make profile, which traces under QEMU, is
# not offered: BOARD=microbit profiles the same ARMv6-M code)
BOARD_QEMU     :=
BOARD_PACKAGES := gcc-arm-none-eabi nodejs
BOARD_CLOCK_HZ ?= 125000000
# fixed, and float in software (libgcc's ARMv6-M soft float: the
# comparison with float demos); double works too (soft, 331,496 cycles a
# pixel on balls-2), but a 320x240 benchmark frame takes 13 minutes of
# the emulator's time, so it is not offered
BOARD_BACKENDS := fixed float
BOARD_SRC      := platform/pico/board.c
BOARD_LD       := platform/pico/link.ld
BOARD_RUN      := node platform/pico/run.mjs
# the emulator counts cycles: the report gives them beside instructions
BOARD_CYCLES   := 1
# make run renders one sample a pixel: rp2040js runs 25 to 35 million
# cycles a second, and the default scene anti-aliased (AA=3) takes about
# three minutes of the host's time, one sample about forty seconds
BOARD_RUN_AA   := 0
# PICO_DISPLAY=st7789 (default): the frame on the panel, rgb565be;
# uart: the framed stream on UART0, as on the QEMU boards
PICO_DISPLAY   ?= st7789
ifeq ($(PICO_DISPLAY),st7789)
BOARD_SINK     := platform/pico/st7789.c
BOARD_SINK_CALLBACKS := panel_begin,panel_flush,transfer_wait,panel_end
FW_FORMAT      := rgb565be
# two band buffers of 4 lines (st7789.c splits the one main.c gives it)
BAND_LINES     ?= 8
else ifneq ($(PICO_DISPLAY),uart)
$(error PICO_DISPLAY=$(PICO_DISPLAY): st7789 or uart)
endif
# PICO_DIVIDER=1 (default): the core's 32-bit divisions on the SIO
# divider (sio_div.h); 0: libgcc's __aeabi_uidiv
PICO_DIVIDER   ?= 1
ifeq ($(PICO_DIVIDER),1)
BOARD_CFLAGS   += -DRT_UDIV32_HEADER='"sio_div.h"' -DRT_UDIV32=sio_udiv32 -Iplatform/pico
else ifneq ($(PICO_DIVIDER),0)
$(error PICO_DIVIDER=$(PICO_DIVIDER): 1 or 0)
endif
# make bench measures libgcc's division too (fixed backend: the divider
# serves the fixed layer)
BOARD_BENCH_VARIANTS := PICO_DIVIDER=0
# the build folder's name says both choices when they are not the defaults
BOARD_TAG      := $(if $(filter uart,$(PICO_DISPLAY)),-uart)$(if $(filter 0,$(PICO_DIVIDER)),-nodiv)
ifneq ($(filter profile,$(MAKECMDGOALS)),)
$(error make profile traces under QEMU, which has no RP2040: BOARD=microbit profiles the same ARMv6-M code)
endif
