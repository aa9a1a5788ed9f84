# board.mk - STM32F4 (Cortex-M4F with the single-precision FPU), one
# variant a board (STM32=, the table below): the STM32F405/F407 boards
# (STM32F4DISCOVERY, Adafruit Feather STM32F405, Netduino Plus 2), run
# under QEMU as netduinoplus2; the Nucleo-64 boards of the F401, F411
# and F446; the WeAct BlackPill with an F411 or an F401. The image is
# for the chip: clocks from the crystal (or the 16 MHz HSI when no
# crystal answers) to the variant's SYSCLK, voltage scale, flash wait
# states, prefetch and caches, the USART's pins and BAUD, cycles from
# DWT's CYCCNT, the run ended by sleeping (board.c, clock.c). Under
# QEMU, where RCC reads 0 and CYCCNT stays 0, the same image runs at the
# reset clock and counts instructions with TIM2, and says so. The build
# writes <backend>.bin and <backend>.hex beside the ELF (image.mk).
# Variables: app/firmware/firmware.mk.
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
# The variants (STM32=NAME), one row each: every choice below defaults to
# its row, and the clock test (tests/boards/stm32f4_clock_test.c) is
# built from the same flags (make stm32-clock-flags). Fields:
#   name : chip whose limits apply (f405 F405/F407; f401 F401, also the
#          Nucleo-64's, whose image must run on the F401, F411 and F446
#          alike; f411 F411) : SYSCLK MHz : HSE MHz : HSE crystal|bypass :
#   LED pin : LED lit when the pin is high|low : console USART :
#   flash : RAM (link.ld) : the board in a phrase (_ for spaces)
STM32_VARIANTS := \
  f405:f405:168:8:crystal:PD12:high:1:1024K:128K:an_STM32F405/F407_board_(STM32F4DISCOVERY_and_the_like) \
  nucleo64:f401:84:8:bypass:PA5:high:2:512K:96K:a_Nucleo-64_board_(STM32F401/F411/F446) \
  blackpill-f411:f411:100:25:crystal:PC13:low:1:512K:128K:a_WeAct_BlackPill_(STM32F411CEU6) \
  blackpill-f401:f401:84:25:crystal:PC13:low:1:256K:64K:a_WeAct_BlackPill_(STM32F401CCU6)
STM32          ?= f405
STM32_NAMES    := $(foreach r,$(STM32_VARIANTS),$(firstword $(subst :, ,$(r))))
STM32_ROW      := $(subst :, ,$(filter $(STM32):%,$(STM32_VARIANTS)))
ifneq ($(words $(STM32_ROW)),11)
$(error STM32=$(STM32): one of $(STM32_NAMES))
endif
stm32_row       = $(word $(1),$(STM32_ROW))
STM32_CHIP     := $(call stm32_row,2)
STM32_MHZ      := $(call stm32_row,3)
STM32_FLASH    := $(call stm32_row,9)
STM32_RAM      := $(call stm32_row,10)
STM32_BOARD    := $(subst _, ,$(call stm32_row,11))
# HSE_MHZ: the crystal's (or the external clock's) frequency, 4 to 26
# MHz; 0: none, run from the 16 MHz HSI
HSE_MHZ        ?= $(call stm32_row,4)
ifeq ($(filter 0 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26,$(HSE_MHZ)),)
$(error HSE_MHZ=$(HSE_MHZ): a whole number of MHz, 4 to 26 (the crystal's range), or 0 for none)
endif
# HSE=crystal: a quartz crystal between OSC_IN and OSC_OUT, which the
# chip's oscillator drives; bypass: a clock signal into OSC_IN (a
# Nucleo's ST-LINK gives one). The wrong one never starts: a crystal in
# bypass mode does not oscillate, and the firmware falls back to the HSI.
HSE            ?= $(call stm32_row,5)
ifeq ($(filter crystal bypass,$(HSE)),)
$(error HSE=$(HSE): crystal (a quartz crystal on OSC_IN/OSC_OUT) or bypass (a clock signal into OSC_IN))
endif
# the user LED, as port and pin (PD12 the Discovery's green, PC1 the
# Feather's red, PA5 the Nucleo's green, PC13 the BlackPill's blue);
# none: no heartbeat. STM32_LED_ON: the pin level that lights it (high,
# or low where the LED hangs from 3.3 V, as on the BlackPill)
STM32_LED      ?= $(call stm32_row,6)
STM32_LED_ON   ?= $(call stm32_row,7)
STM32_LED_PINS := $(foreach p,A B C D E F G H I,$(foreach n,0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15,P$(p)$(n)))
ifeq ($(STM32_LED),none)
STM32_LED_FLAGS := -DSTM32_LED_PORT=0
else ifneq ($(filter $(STM32_LED),$(STM32_LED_PINS)),)
STM32_LED_PORT := $(strip $(foreach p,A B C D E F G H I,$(if $(filter P$(p)%,$(STM32_LED)),$(p))))
STM32_LED_FLAGS := -DSTM32_LED_PORT="'$(STM32_LED_PORT)'" -DSTM32_LED_PIN=$(patsubst P$(STM32_LED_PORT)%,%,$(STM32_LED))
else
$(error STM32_LED=$(STM32_LED): a port letter and pin such as PD12, or none)
endif
ifeq ($(filter high low,$(STM32_LED_ON)),)
$(error STM32_LED_ON=$(STM32_LED_ON): high or low (the pin level that lights the LED))
endif
# STM32_USART=1: USART1 on PA9 (TX) / PA10 (RX), on APB2; 2: USART2 on
# PA2/PA3, on APB1 (QEMU's second serial port, so its first goes to null)
STM32_USART    ?= $(call stm32_row,8)
ifeq ($(filter 1 2,$(STM32_USART)),)
$(error STM32_USART=$(STM32_USART): 1 (PA9/PA10) or 2 (PA2/PA3))
endif
ifeq ($(STM32_USART),2)
BOARD_QEMU     += -serial null -serial stdio
endif
# The buses at SYSCLK (clock.c sets the same dividers and checks them
# against these): APB2 at SYSCLK up to 100 MHz, else / 2; APB1 / 2 of that
STM32_APB2_MHZ := $(if $(filter 168,$(STM32_MHZ)),84,$(STM32_MHZ))
STM32_APB1_MHZ := $(shell echo $$(($(STM32_APB2_MHZ) / 2)))
STM32_USART_HZ := $(if $(filter 1,$(STM32_USART)),$(STM32_APB2_MHZ),$(STM32_APB1_MHZ))000000
# BAUD: the console's rate, 8N1. The USART divides its bus clock by
# BRR = clock / BAUD, rounded (16x oversampling: a whole part and 16ths);
# BRR must be 16 to 65535, and the rate it gives within 2% of BAUD
# (RM0090/RM0383: the receiver tolerates 3.41% with a fractional divider,
# both ends' errors together, so the adapter keeps its share)
BAUD           ?= 115200
STM32_BAUD_CHECK := $(shell awk -v f=$(STM32_USART_HZ) -v b='$(BAUD)' 'BEGIN { \
    if (b !~ /^[1-9][0-9]*$$/) { print "not a whole number"; exit } \
    brr = int((f + int(b / 2)) / b); \
    if (brr < 16) { printf "over the most USART$(STM32_USART) takes at %g MHz, %d (its clock / 16)", f / 1e6, f / 16; exit } \
    if (brr > 65535) { printf "under the least USART$(STM32_USART) takes at %g MHz, %d (its clock / 65535)", f / 1e6, int(f / 65535.5) + 1; exit } \
    err = (f / brr - b) / b * 100; if (err < 0) err = -err; \
    if (err > 2) printf "USART$(STM32_USART) at %g MHz gives %.0f baud (BRR %d = %d + %d/16), %.2f%% off, more than 2%%", \
        f / 1e6, f / brr, brr, int(brr / 16), brr % 16, err }')
ifneq ($(STM32_BAUD_CHECK),)
$(error BAUD=$(BAUD): $(STM32_BAUD_CHECK); 115200, 921600 and 2000000 fit every variant)
endif

BOARD_TITLE    := $(STM32_BOARD) with a Cortex-M4F and its single-precision FPU
STM32_CLOCK_FLAGS := -DSTM32_CHIP=$(STM32_CHIP:f%=%) -DSTM32_SYSCLK_MHZ=$(STM32_MHZ) -DSTM32_HSE_MHZ=$(HSE_MHZ) \
                     -DSTM32_HSE_BYPASS=$(if $(filter bypass,$(HSE)),1,0) -DSTM32_USART=$(STM32_USART) \
                     -DSTM32_BAUD=$(BAUD) -DSTM32_USART_HZ=$(STM32_USART_HZ)
BOARD_CFLAGS   += $(STM32_CLOCK_FLAGS) $(STM32_LED_FLAGS) -DSTM32_LED_ACTIVE_LOW=$(if $(filter low,$(STM32_LED_ON)),1,0)
BOARD_LDFLAGS  := -Wl,--defsym=STM32_FLASH=$(STM32_FLASH) -Wl,--defsym=STM32_RAM=$(STM32_RAM)
BOARD_CLOCK_HZ ?= $(STM32_MHZ)000000
BOARD_BAUD     := $(BAUD)
# the build folder's name says the choices that are not the variant's
stm32_tag       = $(if $(filter-out $(call stm32_row,$(2)),$(1)),-$(3)$(1))
BOARD_TAG      := $(if $(filter-out f405,$(STM32)),-$(STM32))$(call stm32_tag,$(HSE_MHZ),4,hse)$(call stm32_tag,$(HSE),5)$(call stm32_tag,$(STM32_LED),6,led)$(call stm32_tag,$(STM32_LED_ON),7,led)$(call stm32_tag,$(STM32_USART),8,usart)$(if $(filter-out 115200,$(BAUD)),-baud$(BAUD))
# make flash [FLASHER=openocd|st-flash|dfu-util]: through an ST-LINK (the
# Discovery's and the Nucleo's own, or a probe on SWD), or, on a board
# without one (the BlackPill), through the chip's ROM bootloader over USB
# (DFU: hold BOOT0 while pressing NRST first)
FLASHER        ?= $(if $(filter blackpill-%,$(STM32)),dfu-util,openocd)
ifeq ($(FLASHER),openocd)
BOARD_FLASH     = openocd -f interface/stlink.cfg -f target/stm32f4x.cfg -c "program $(FW_DIR)/$(BACKEND).hex verify reset exit"
else ifeq ($(FLASHER),st-flash)
BOARD_FLASH     = st-flash --reset write $(FW_DIR)/$(BACKEND).bin 0x08000000
else ifeq ($(FLASHER),dfu-util)
BOARD_FLASH     = dfu-util -a 0 -s 0x08000000:leave -D $(FW_DIR)/$(BACKEND).bin
else
$(error FLASHER=$(FLASHER): openocd, st-flash or dfu-util)
endif
BOARD_FLASH_PACKAGE := $(if $(filter st-flash,$(FLASHER)),stlink-tools,$(FLASHER))
BOARD_IMAGE_NOTE = flash the .bin at 0x08000000 (st-flash write FILE.bin 0x08000000; dfu-util -a 0 -s 0x08000000:leave -D FILE.bin), or the .hex with OpenOCD; serial $(BAUD) 8N1 on USART$(STM32_USART), rt receive started before the reset: docs/boards.md, On a real STM32F4

