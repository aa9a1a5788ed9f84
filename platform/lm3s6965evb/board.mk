# board.mk - TI (Luminary Micro) Stellaris LM3S6965 evaluation board under
# QEMU: a Cortex-M3 (no FPU) set to 50 MHz, 256 KiB flash, 64 KiB SRAM,
# and an SSD0323 128x64 OLED with 4-bit grey pixels on SSI0, where the
# frame goes (oled.c, band by band, no frame buffer). Only the report
# lines go over UART0; tools/emu/lm3s6965evb/run.sh captures the panel through QEMU's monitor.
# The port contract and the variables are in app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    := TI Stellaris LM3S6965 evaluation board with a Cortex-M3, no FPU and a 128x64 OLED
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m3 -mthumb
BOARD_QEMU     := qemu-system-arm -M lm3s6965evb
BOARD_PACKAGES := gcc-arm-none-eabi qemu-system-arm socat
BOARD_CLOCK_HZ ?= 50000000
# fixed only: the float and double builds parse the NFF text at boot and
# link with a 64 KiB stack, which is all of this board's RAM
BOARD_BACKENDS := fixed
BOARD_SRC      := platform/lm3s6965evb/board.c
BOARD_LD       := platform/lm3s6965evb/link.ld
BOARD_SINK     := platform/lm3s6965evb/oled.c
BOARD_SINK_CALLBACKS := oled_begin,oled_flush,oled_end
BOARD_RUN      := tools/emu/lm3s6965evb/run.sh
BOARD_CFLAGS   += -DSINK_HOLDS_FRAME=1
# the panel's pixel format, whatever FORMAT says
FW_FORMAT      := l4
# the panel's size unless SIZE is given; a smaller frame is drawn at the
# panel's top left, a larger one does not build
BOARD_SIZE     := 128x64
BOARD_PANEL    := 128x64
BOARD_PANEL_NAME := 128x64 OLED
# 16 grey levels: make run dithers (DITHER=0 rounds to nearest)
BOARD_RUN_DITHER := 1
