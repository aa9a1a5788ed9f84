# board.mk - STM32F4 (Cortex-M4F with the single-precision FPU): the
# STM32F405/F407 boards (STM32F4DISCOVERY, Adafruit Feather STM32F405,
# Netduino Plus 2), run under QEMU as netduinoplus2, and the Nucleo-64
# boards of the F401, F411 and F446 (STM32=nucleo64). The image is for
# the chip: clocks to 168 MHz (84 MHz on a Nucleo-64) from the crystal,
# or from the 16 MHz HSI when no crystal answers, flash wait states,
# prefetch and caches, the USART's pins, cycles from DWT's CYCCNT, the
# run ended by sleeping (board.c). Under QEMU, where RCC reads 0 and
# CYCCNT stays 0, the same image runs at the reset clock and counts
# instructions with TIM2, and says so. The build writes <backend>.bin
# and <backend>.hex beside the ELF (image.mk). Variables:
# app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    =  $(if $(filter f405,$(STM32)),an STM32F405/F407 board (STM32F4DISCOVERY and the like),a Nucleo-64 board (STM32F401/F411/F446)) with a Cortex-M4F and its single-precision FPU
BOARD_ARCH     := cortex-m
BOARD_CROSS    := arm-none-eabi-
BOARD_CPU      := -mcpu=cortex-m4 -mthumb
BOARD_FPU      := -mfpu=fpv4-sp-d16 -mfloat-abi=hard
BOARD_QEMU     := qemu-system-arm -M netduinoplus2
BOARD_PACKAGES := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
BOARD_BACKENDS := fixed float double
BOARD_SRC      := platform/stm32f4/board.c platform/stm32f4/clock.c
BOARD_LD       := platform/stm32f4/link.ld
# no semihosting: the run ends with the exit status as the last report
# line, then the core sleeps; tools/firmware/run.sh stops QEMU on that
# line
BOARD_ARCH_SKIP := semihost
# CYCCNT on the chip, TIM2's instruction count under QEMU: board.c finds
# out at run time which works, and the report names it
BOARD_CYCLES   := 1
BOARD_CFLAGS   += -DBOARD_COUNTERS_PROBED=1 -DBOARD_LED=1
BOARD_RULES    := platform/stm32f4/image.mk
BOARD_IMAGES    = $(FW_DIR)/$(BACKEND).bin $(FW_DIR)/$(BACKEND).hex
BOARD_IMAGE_SHOW := ls -l
# make flash [FLASHER=openocd|st-flash]: through the board's ST-LINK (the
# Discovery's and the Nucleo's own, or a probe on SWD)
FLASHER        ?= openocd
ifeq ($(FLASHER),openocd)
BOARD_FLASH     = openocd -f interface/stlink.cfg -f target/stm32f4x.cfg -c "program $(FW_DIR)/$(BACKEND).hex verify reset exit"
else ifeq ($(FLASHER),st-flash)
BOARD_FLASH     = st-flash --reset write $(FW_DIR)/$(BACKEND).bin 0x08000000
else
$(error FLASHER=$(FLASHER): openocd or st-flash)
endif
BOARD_FLASH_PACKAGE := $(if $(filter st-flash,$(FLASHER)),stlink-tools,openocd)
BOARD_IMAGE_NOTE = flash the .bin at 0x08000000 (st-flash write FILE.bin 0x08000000), or the .hex with OpenOCD; serial 115200 8N1: docs/boards.md, On a real STM32F4

# STM32=f405 (default): F405/F407 at 168 MHz, USART1 on PA9 (TX) and
# PA10 (RX), 1 MiB flash, 128 KiB SRAM; nucleo64: F401/F411/F446 on a
# Nucleo-64 at 84 MHz (the F401's most; 2 wait states on all three),
# USART2 on PA2/PA3 (the ST-LINK's virtual COM port), the crystal
# clock from the ST-LINK (HSE bypass), 512 KiB flash, 96 KiB SRAM
STM32          ?= f405
ifeq ($(STM32),f405)
STM32_CLOCK    := -DSTM32_SYSCLK_MHZ=168
STM32_USART    ?= 1
STM32_FLASH    := 1024K
STM32_RAM      := 128K
STM32_LED      ?= PD12
else ifeq ($(STM32),nucleo64)
STM32_CLOCK    := -DSTM32_SYSCLK_MHZ=84 -DSTM32_HSE_BYPASS=1
STM32_USART    ?= 2
STM32_FLASH    := 512K
STM32_RAM      := 96K
STM32_LED      ?= PA5
else
$(error STM32=$(STM32): f405 or nucleo64)
endif
# STM32_USART=1: USART1 on PA9/PA10; 2: USART2 on PA2/PA3 (QEMU's
# second serial port, so its first goes to null)
ifeq ($(filter 1 2,$(STM32_USART)),)
$(error STM32_USART=$(STM32_USART): 1 or 2)
endif
ifeq ($(STM32_USART),2)
BOARD_QEMU     += -serial null -serial stdio
endif
# the crystal (HSE) in MHz: 8 on the Discovery and the Nucleo (ST-LINK),
# 12 on the Feather, 25 on the Netduino; 0: none, run from the HSI
HSE_MHZ        ?= 8
ifeq ($(filter 0 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26,$(HSE_MHZ)),)
$(error HSE_MHZ=$(HSE_MHZ): a whole number of MHz, 4 to 26 (the crystal's range), or 0 for none)
endif
# the user LED, as port and pin: PD12 (the Discovery's green), PC1 (the
# Feather's red), PA5 (the Nucleo's green); none: no heartbeat
STM32_LED_PINS := $(foreach p,A B C D E F G H I,$(foreach n,0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15,P$(p)$(n)))
ifeq ($(STM32_LED),none)
STM32_LED_FLAGS := -DSTM32_LED_PORT=0
else ifneq ($(filter $(STM32_LED),$(STM32_LED_PINS)),)
STM32_LED_PORT := $(strip $(foreach p,A B C D E F G H I,$(if $(filter P$(p)%,$(STM32_LED)),$(p))))
STM32_LED_FLAGS := -DSTM32_LED_PORT="'$(STM32_LED_PORT)'" -DSTM32_LED_PIN=$(patsubst P$(STM32_LED_PORT)%,%,$(STM32_LED))
else
$(error STM32_LED=$(STM32_LED): a port letter and pin such as PD12, or none)
endif
BOARD_CFLAGS   += $(STM32_CLOCK) -DSTM32_USART=$(STM32_USART) -DSTM32_HSE_MHZ=$(HSE_MHZ) $(STM32_LED_FLAGS)
BOARD_LDFLAGS  := -Wl,--defsym=STM32_FLASH=$(STM32_FLASH) -Wl,--defsym=STM32_RAM=$(STM32_RAM)
BOARD_CLOCK_HZ ?= $(if $(filter f405,$(STM32)),168000000,84000000)
# the build folder's name says the choices that are not the defaults
BOARD_TAG      := $(if $(filter-out f405,$(STM32)),-$(STM32))$(if $(filter-out 8,$(HSE_MHZ)),-hse$(HSE_MHZ))$(if $(filter-out $(if $(filter f405,$(STM32)),PD12,PA5),$(STM32_LED)),-led$(STM32_LED))$(if $(filter-out $(if $(filter f405,$(STM32)),1,2),$(STM32_USART)),-usart$(STM32_USART))
