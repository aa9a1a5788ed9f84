# board.mk - Raspberry Pi Pico (RP2040): two Cortex-M0+ at 125 MHz from
# the 12 MHz crystal, both rendering (make CORES=1: core 0 alone; core 1
# launched through the boot ROM, board.c), 2 MiB of flash,
# 264 KiB of SRAM, no FPU, no divide instruction (the SIO divider
# instead: PICO_DIVIDER), and an ST7789 panel on SPI0 where the frame
# goes (st7789.c, by DMA). Report lines go over UART0 (GP0, 115200 8N1).
# The image is for the chip: boot2 (boot2.S) first, code copied to SRAM,
# clocks and resets brought up in board.c, cycles counted by SysTick,
# the run ended by sleeping; the build writes <backend>.uf2 beside the
# ELF (image.mk). tools/emu/pico/run.mjs boots that UF2 under rp2040js
# the way the chip does (rp2040js pinned in that folder's package.json,
# installed into its node_modules/ by npm ci, by tools/ensure-deps.sh). Variables: app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ),
# with the cores that render (CORES, set after this file: hence =)
BOARD_TITLE     = Raspberry Pi Pico (RP2040) with $(if $(filter 1,$(CORES)),one Cortex-M0+ core of its two (CORES=1),both Cortex-M0+ cores) and no FPU
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
# (the module on the panel's pins, for the runner's model of its glass)
BOARD_RUN       = node tools/emu/pico/run.mjs --module $(PANEL)$(if $(filter 1,$(PANEL_FLIP)),$(comma)flip)
# SysTick counts cycles (board.c); the M0+ has no instruction counter, so
# run.mjs counts instructions from outside the image; no semihosting: the
# run ends with the exit status as a report line, then the core sleeps
BOARD_CYCLES   := 1
BOARD_INSTR_COUNTER := 0
BOARD_ARCH_SKIP := semihost
# both cores render (app/firmware/bands.c, with port.h's multi-core
# part: board.c); make CORES=1 renders on core 0 alone
BOARD_CORES    := 2
# the LED on GP25 blinks as bands are drawn (port_heartbeat, board.c)
BOARD_CFLAGS   += -DBOARD_LED=1
# boot2 with its CRC, and the UF2 to copy onto the RPI-RP2 drive
BOARD_RULES    := platform/pico/image.mk
BOARD_OBJS     := $(FW_ROOT)/pico/boot2/boot2_crc.o
BOARD_IMAGES    = $(FW_DIR)/$(BACKEND).uf2
BOARD_IMAGE_SHOW := node tools/emu/pico/uf2.mjs check
BOARD_IMAGE_NOTE = copy it onto the RPI-RP2 drive (hold BOOTSEL while plugging the Pico in): docs/boards.md, On a real Pico
# make run renders one sample a pixel: rp2040js runs 25 to 35 million
# cycles a second, and the default scene anti-aliased (AA=3) takes about
# three minutes of the host's time, one sample about forty seconds
BOARD_RUN_AA   := 0
# PICO_DISPLAY=st7789 (default): the frame on the panel, rgb565be;
# uart: the framed stream on UART0, as on the QEMU boards
PICO_DISPLAY   ?= st7789
# PANEL (st7789): 320x240 (Pimoroni's Pico Display Pack 2.0, default) or
# 240x240 (the square 1.3" modules); PANEL_FLIP=1 turns the picture by
# 180 degrees, for a module mounted the other way up (st7789.c). A frame
# (SIZE, else the scene's resolution) larger than the panel does not
# build; a smaller one is centred on the panel, cleared to black first.
PANEL          ?= 320x240
PANEL_FLIP     ?= 0
ifeq ($(PICO_DISPLAY),st7789)
ifeq ($(filter 320x240 240x240,$(PANEL)),)
$(error PANEL=$(PANEL): 320x240 or 240x240)
endif
ifeq ($(filter 0 1,$(PANEL_FLIP)),)
$(error PANEL_FLIP=$(PANEL_FLIP): 0 or 1)
endif
BOARD_SINK     := platform/pico/st7789.c
BOARD_SINK_CALLBACKS := panel_begin,panel_flush,transfer_wait,panel_end,panel_pass_end
# the panel keeps its frame: the core's interlaced passes by default
# (PROGRESSIVE=0: scanline order), the whole picture after 1/64 of the rays
BOARD_PROGRESSIVE := 1
BOARD_CFLAGS   += -DPANEL_WIDTH=$(word 1,$(subst x, ,$(PANEL))) -DPANEL_HEIGHT=$(word 2,$(subst x, ,$(PANEL))) -DPANEL_FLIP=$(PANEL_FLIP)
BOARD_PANEL    := $(PANEL)
BOARD_PANEL_NAME := $(PANEL) panel (PANEL=$(PANEL))
FW_FORMAT      := rgb565be
# the panel gets bands of 4 lines either way: on two cores (bands.c)
# each core has two band buffers of its own; 4 lines gave a shorter
# critical path than 8 on 7 of bench/cores.md's 10 scenes at 64x64 (the
# showpiece 0.529 of one core's cycles against 0.548) and on the card at
# 320x240 (0.5044 against 0.5061), a longer one on 3 and on picolib
# (0.5087 against 0.5049). On one core (CORES=1) st7789.c splits the
# buffer of 8 lines main.c gives it into two.
BOARD_BAND_LINES = $(if $(filter 1,$(CORES)),8,4)
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
# the build folder's name says the choices that are not the defaults
BOARD_TAG      := $(if $(filter uart,$(PICO_DISPLAY)),-uart,$(if $(filter-out 320x240,$(PANEL)),-panel$(PANEL))$(if $(filter 1,$(PANEL_FLIP)),-flip))$(if $(filter 0,$(PICO_DIVIDER)),-nodiv)
ifneq ($(filter profile,$(MAKECMDGOALS)),)
$(error make profile traces under QEMU, which has no RP2040: BOARD=microbit profiles the same ARMv6-M code)
endif
