# firmware.mk - the firmware of every board, built per (board, scene,
# size, depth, pixel format, backend). Included by the top-level Makefile;
# SCENE, SIZE, DEPTH, FORMAT and NAME come from there.
#
#   make run  [BOARD=<QEMU machine>] [BACKEND=fixed|float] [SCENE=..] [SIZE=WxH] [DEPTH=N] [FORMAT=..]
#   make image | uf2 | flash | firmware | size | board-run RUN_OUT=x.png   (the same variables)
#   make profile [PROFILE_JSON=x.json]   (the same variables; SIZE 64x64 unless given)
#
# Every goal builds the same firmware from the same variables, so make run
# runs exactly the ELF make image hands over:
#  - SIZE: the frame, unless given: the board's BOARD_SIZE if it sets one
#    (the OLED's panel), else the scene's `resolution` (every scene has
#    one: the reader requires it in the viewpoint), read by
#    scene-size.awk (tests/boards/board-tests.sh checks it against rt for every
#    scene of scenes/). A board with a panel (BOARD_PANEL) refuses a larger
#    frame at build time, naming both sizes.
#  - AA, SPP, DITHER: unless given, the board's BOARD_RUN_AA (3 levels, or
#    one sample on the 16 KiB boards and the Pico) and BOARD_RUN_DITHER
#    (the OLED's 1), for every goal; scripts that measure one sample say
#    AA=0 (and DITHER=0 on the OLED).
#  - out/ names (make run's PNG, make image's files) and the build folder
#    are made of one list of choices (FW_CHOICES below), each named only
#    when it is not its default: out/<scene>-<board>-<backend>[-choices];
#    make run's references of what changes them (RUN_REF, RUN_AREA);
#    OUT_DIR=dir instead of out/.
#
# The port contract (platform/port.h): a board folder platform/<BOARD>/
# holds board.mk, which sets the variables below: the first ten always,
# the others when the default does not fit (defaults are set just below,
# before board.mk is included). docs/boards.md, "Adding a board", points here.
#
# variable             | meaning                                                          | default                    | example
# ---------------------|------------------------------------------------------------------|----------------------------|-----------------------------------------------
# BOARD_TITLE          | the board in a phrase, for make run's report                     | (required)                 | ARM MPS2 AN385, an FPGA board (QEMU's model), ...
# BOARD_ARCH           | platform/arch/<arch>/: reset, fault handler and exit             | (required)                 | cortex-m, riscv
# BOARD_CROSS          | the cross toolchain's prefix                                     | (required)                 | arm-none-eabi-
# BOARD_CPU            | compiler flags for the core                                      | (required)                 | -mcpu=cortex-m3 -mthumb
# BOARD_QEMU           | QEMU and its machine; empty for a board another emulator runs    | (required)                 | qemu-system-arm -M mps2-an385
#                      | (it then brings its own BOARD_RUN)                               |                            |
# BOARD_PACKAGES       | the Debian packages it needs (make run installs them)            | (required)                 | gcc-arm-none-eabi qemu-system-arm
# BOARD_CLOCK_HZ       | the core's clock, for the time make run prints                   | (required)                 | 25000000
# BOARD_BACKENDS       | what BACKEND may be                                              | (required)                 | fixed float double
# BOARD_SRC            | its C files: port_init, port_write, port_icount_* (and           | (required)                 | platform/stm32f4/board.c platform/stm32f4/clock.c
#                      | port_cycles_read with BOARD_CYCLES 1)                            |                            |
# BOARD_LD             | its linker script: MEMORY, then INCLUDE sections.ld              | (required)                 | platform/mps2-an385/link.ld
# BOARD_FPU            | flags of a hard-float build                                      | empty: no FPU              | -mfpu=fpv4-sp-d16 -mfloat-abi=hard
# BOARD_ICOUNT         | QEMU's -icount option (two cores: sleep=off makes the run        | shift=0                    | shift=0,sleep=off
#                      | repeatable); make board-run QEMU_ACCEL="-accel tcg,thread=multi" |                            |
#                      | runs without it instead (cores in parallel, no counts)           |                            |
# BOARD_CFLAGS         | extra -D (and -I) for every firmware file                        | empty                      | -DSINK_HOLDS_FRAME=1
# BOARD_LDFLAGS        | extra linker flags                                               | empty                      | -Wl,--defsym=STM32_FLASH=1024K
# BOARD_CORES          | cores that render (2: bands.c and port.h's multi-core part)      | 1                          | 2
# BOARD_CYCLES         | 1: the port counts cycles (port_cycles_read)                     | 0                          | 1
# BOARD_INSTR_COUNTER  | 0: the chip has no instruction counter, the runner counts from   | 1                          | 0
#                      | outside (port.h)                                                 |                            |
# BOARD_ARCH_SKIP      | files of platform/arch/<arch>/ it replaces, by name without .c   | empty                      | semihost
#                      | (semihost: a board that ends its run without a debugger)         |                            |
# BOARD_SINK           | the display sink's C file (sink.h)                               | app/firmware/sink_stream.c | platform/lm3s6965evb/oled.c
# BOARD_SINK_CALLBACKS | the sink's begin, flush and end functions (make size's stack     | stream_begin,stream_flush, | oled_begin,oled_flush,oled_end
#                      | bound)                                                           | stream_end                 |
# BOARD_RUN            | the command that runs an ELF and writes its image and report     | tools/firmware/run.sh      | tools/emu/lm3s6965evb/run.sh
# FW_FORMAT            | a pixel format the board insists on, whatever FORMAT says        | empty                      | l4
# BOARD_SIZE           | the frame unless SIZE is given, instead of the scene's           | empty                      | 128x64
#                      | resolution                                                       |                            |
# BOARD_PANEL          | WxH of the panel the frame goes to: a larger frame is a build    | empty                      | 128x64
#                      | error                                                            |                            |
# BOARD_PANEL_NAME     | how that error names the panel                                   | $(BOARD_PANEL) panel       | 128x64 OLED
# BOARD_BAND_LINES     | the default of BAND_LINES                                        | 4                          | 1
# BOARD_PROGRESSIVE    | 1: its sink is a panel with frame memory of its own that takes   | 0                          | 1
#                      | any rectangle in whole-byte pixels: the default of PROGRESSIVE   |                            |
# BOARD_RUN_AA         | the default of AA (levels[,threshold])                           | 3                          | 0
# BOARD_RUN_DITHER     | the default of DITHER                                            | 0                          | 1
# BOARD_TAG            | a suffix of the build folder for the board's own choices         | empty                      | -nucleo64
# BOARD_RULES          | a makefile of its own build steps, included after these          | empty                      | platform/pico/image.mk
# BOARD_OBJS           | objects those steps make, linked into every image                | empty                      | $(FW_ROOT)/pico/boot2/boot2_crc.o
# BOARD_IMAGES         | files those steps make from $(FW_DIR)/<backend>.elf, built       | empty                      | $(FW_DIR)/$(BACKEND).uf2
#                      | with it: what a user flashes (make image copies them to out/)    |                            |
# BOARD_IMAGE_SHOW     | a command that prints what one image holds                       | empty (echo)               | ls -l
# BOARD_IMAGE_NOTE     | how to flash them                                                | empty                      | copy it onto the RPI-RP2 drive ...
# BOARD_FLASH          | the command of make flash                                        | empty: no make flash       | openocd -f interface/stlink.cfg ...
# BOARD_FLASH_PACKAGE  | the Debian package that has BOARD_FLASH's tool                   | empty                      | openocd
# BOARD_BENCH_VARIANTS | make variables of builds make bench measures too, one word       | empty                      | PICO_DIVIDER=0
#                      | each, commas for spaces                                          |                            |
#
# Each build (scene and FW_CHOICES, below) gets its own folder: the scene
# compiler turns the NFF into const tables in flash plus a header saying
# what the scene uses, and the firmware is built for exactly that.

BOARD   ?= mps2-an385
BACKEND ?= fixed
BOARDS  := $(patsubst platform/%/board.mk,%,$(wildcard platform/*/board.mk))
ifeq ($(filter $(BOARD),$(BOARDS)),)
$(error BOARD=$(BOARD) is not a board of platform/*/board.mk: $(BOARDS))
endif
BOARD_FPU  :=
BOARD_CORES := 1
BOARD_CYCLES := 0
BOARD_INSTR_COUNTER := 1
BOARD_ARCH_SKIP :=
BOARD_RULES :=
BOARD_LDFLAGS :=
BOARD_OBJS :=
# Where firmware is built and run (FW_DIR below): build/board, unless the
# caller gives another, as tests/run-all.py gives each suite its own so
# that suites run side by side never build into one folder.
FW_ROOT ?= build/board
BOARD_IMAGES :=
BOARD_IMAGE_NOTE :=
BOARD_IMAGE_SHOW :=
BOARD_FLASH :=
BOARD_FLASH_PACKAGE :=
BOARD_ICOUNT := shift=0
BOARD_SINK := app/firmware/sink_stream.c
BOARD_SINK_CALLBACKS := stream_begin,stream_flush,stream_end
BOARD_RUN  := tools/firmware/run.sh
BOARD_RUN_AA := 3
BOARD_RUN_DITHER := 0
BOARD_PROGRESSIVE := 0
BOARD_TAG :=
BOARD_BENCH_VARIANTS :=
BOARD_SIZE :=
BOARD_PANEL :=
BOARD_PANEL_NAME = $(BOARD_PANEL) panel
BOARD_BAND_LINES := 4
include platform/$(BOARD)/board.mk
ifeq ($(filter $(BACKEND),$(BOARD_BACKENDS)),)
$(error BACKEND=$(BACKEND) is not offered by BOARD=$(BOARD), which offers: $(BOARD_BACKENDS))
endif
ifneq ($(FW_FORMAT),)
override FORMAT := $(FW_FORMAT)
endif

FW_CC   = $(BOARD_CROSS)gcc
FW_NM   = $(BOARD_CROSS)nm
FW_SIZE = $(BOARD_CROSS)size
FW_OBJCOPY = $(BOARD_CROSS)objcopy

# Flash tables make these limits of the scene compiler, not of RAM.
BOARD_CAPS = -DRT_MAX_SPHERES=1024 -DRT_MAX_CONES=1024 -DRT_MAX_POLYGONS=4096 \
             -DRT_MAX_VERTICES=32768 -DRT_MAX_LIGHTS=16 -DRT_MAX_MATERIALS=128

# The frame: SIZE if given, else the board's BOARD_SIZE, else the scene's
# resolution (scene-size.awk; 128x128 if it finds none, and the reader
# then says what is wrong with the scene)
SCENE_SIZE := $(if $(wildcard $(SCENE)),$(shell awk -f tools/firmware/scene-size.awk '$(SCENE)'))
DEFAULT_SIZE := $(or $(BOARD_SIZE),$(SCENE_SIZE),128x128)
SIZE_IS := $(if $(filter-out undefined,$(origin SIZE)),SIZE=$(SIZE),$(if $(BOARD_SIZE),the board's default size,the resolution of $(SCENE)))
ifeq ($(origin SIZE),undefined)
SIZE := $(DEFAULT_SIZE)
endif
W := $(word 1,$(subst x, ,$(SIZE)))
H := $(word 2,$(subst x, ,$(SIZE)))
# SIZE is WxH, each side a whole number from 1 to the core's largest
# (rt_config.h's RT_MAX_WIDTH, RT_MAX_HEIGHT, as rt --size takes), checked
# here for every board before anything is built (no leading 0: C would
# read it as octal). The shell sees only digits.
no_digits = $(subst 0,,$(subst 1,,$(subst 2,,$(subst 3,,$(subst 4,,$(subst 5,,$(subst 6,,$(subst 7,,$(subst 8,,$(subst 9,,$(1)))))))))))
RT_MAX_SIDES := $(shell awk '$$1 ~ /define$$/ && ($$2 == "RT_MAX_WIDTH" || $$2 == "RT_MAX_HEIGHT") { printf "%s ", $$3 }' include/rt_config.h)
ifeq ($(and $(filter 1,$(words $(SIZE))),$(W),$(H),$(if $(call no_digits,$(W)$(H)),,digits),$(filter $(W)x$(H),$(SIZE)),\
            $(if $(filter 0%,$(W) $(H)),,no0),$(shell [ $(W) -le $(word 1,$(RT_MAX_SIDES)) ] 2>/dev/null && [ $(H) -le $(word 2,$(RT_MAX_SIDES)) ] && echo fits)),)
$(error SIZE=$(SIZE)$(if $(filter SIZE=%,$(SIZE_IS)),, ($(SIZE_IS))): expected WxH in whole pixels from 1x1 to $(word 1,$(RT_MAX_SIDES))x$(word 2,$(RT_MAX_SIDES)), such as SIZE=128x96)
endif
# A board whose frame goes to a panel (BOARD_PANEL, WxH) takes no larger frame
ifneq ($(BOARD_PANEL),)
ifneq ($(shell [ '$(W)' -le $(word 1,$(subst x, ,$(BOARD_PANEL))) ] 2>/dev/null && [ '$(H)' -le $(word 2,$(subst x, ,$(BOARD_PANEL))) ] 2>/dev/null && echo fits),fits)
$(error the frame is larger than the $(BOARD_PANEL_NAME): $(SIZE) ($(SIZE_IS)) against the panel's $(BOARD_PANEL); give SIZE=WxH of at most $(BOARD_PANEL))
endif
endif
# FORMAT: a name of RT_FB_FORMATS (include/rt_fb.h), lower case: rgb888 -> RT_FB_RGB888.
FMT_MACRO := RT_FB_$(shell echo '$(FORMAT)' | tr a-z A-Z)
# PRUNE=1 (default): code for primitive kinds and shading features the
# scene does not use is compiled out (RT_USE_* from scene_data.h).
PRUNE ?= 1
# CONFIG picks a numeric configuration of the fixed backend (CONFIGS and
# CFG_* in the Makefile; q20, Q11.20, by default; each one's accuracy:
# docs/accuracy.md).
CONFIG ?= q20
ifneq ($(words $(CONFIG)) $(filter $(CONFIGS),$(CONFIG)),1 $(CONFIG))
$(error CONFIG=$(CONFIG) is not a numeric configuration: $(CONFIGS))
endif
CFG_FLAGS := $(CFG_$(CONFIG))
# RAM: lines per band buffer (the firmware holds one band; on several
# cores, two per core) and the stack (each core's)
STACK_SIZE ?= 4096
BAND_LINES ?= $(BOARD_BAND_LINES)
# Cores that render: the board's (BOARD_CORES) unless CORES=1 asks for one.
CORES ?= $(BOARD_CORES)
ifeq ($(filter 1 $(BOARD_CORES),$(CORES)),)
$(error CORES=$(CORES): BOARD=$(BOARD) renders on 1 or $(BOARD_CORES) cores)
endif
# Anti-aliasing: AA=LEVELS[,THRESHOLD] adaptive (rt --aa), SPP=N uniform
# (rt --spp); AA=0: one sample a pixel, and the firmware links none of it
# (RT_USE_AA=0). Without AA or SPP every goal renders with the board's
# BOARD_RUN_AA (3 levels unless its board.mk says otherwise: the 16 KiB
# boards and the Pico render one sample), and without DITHER with its
# BOARD_RUN_DITHER (the OLED's 1).
comma := ,
ifeq ($(origin AA)$(origin SPP),undefinedundefined)
AA := $(BOARD_RUN_AA)
endif
ifeq ($(origin DITHER),undefined)
DITHER := $(BOARD_RUN_DITHER)
endif
AA ?= 0
SPP ?= 0
AA_LEVELS := $(word 1,$(subst $(comma), ,$(AA)))
AA_THRESHOLD := $(or $(word 2,$(subst $(comma), ,$(AA))),0)
AA_FLAGS := $(if $(filter-out 0,$(AA_LEVELS))$(filter-out 0 1,$(SPP)),-DBOARD_AA_LEVELS=$(AA_LEVELS) -DBOARD_AA_THRESHOLD=$(AA_THRESHOLD) -DBOARD_SPP=$(SPP),-DRT_USE_AA=0)
# the sampling as a word: $(1) levels, $(2) threshold, $(3) SPP
sampling_word = $(or $(if $(filter-out 0,$(1)),aa$(1)$(if $(filter-out 0,$(2)),_$(2)))$(if $(filter-out 0 1,$(3)),spp$(3)),aa0)
# PROGRESSIVE=1: the frame in the core's interlaced passes (progressive
# display, docs/hal.md; rt --progressive), the whole picture on the panel
# after 1/64 of the rays; the default on a board whose sink is a panel
# (BOARD_PROGRESSIVE), with one sample a pixel or SPP, on one core or
# several (app/firmware/bands.c). 0: scanline order, and the firmware links none of it
# (RT_USE_PROGRESSIVE=0). A stream sink sends whole lines top down.
ifeq ($(origin PROGRESSIVE),undefined)
PROGRESSIVE := $(if $(filter 1,$(BOARD_PROGRESSIVE)),$(if $(filter-out 0,$(AA_LEVELS)),0,1),0)
endif
ifeq ($(filter 0 1,$(PROGRESSIVE)),)
$(error PROGRESSIVE=$(PROGRESSIVE): 0 (scanline order) or 1 (interlaced passes))
endif
ifeq ($(PROGRESSIVE),1)
ifneq ($(BOARD_PROGRESSIVE),1)
$(error PROGRESSIVE=1: BOARD=$(BOARD)'s sink is not a panel that keeps its frame (BOARD_PROGRESSIVE): it gets scanline order)
endif
ifneq ($(filter-out 0,$(AA_LEVELS)),)
$(error PROGRESSIVE=1 needs one sample a pixel or SPP=N: adaptive anti-aliasing (AA=$(AA)) shares corners between pixels)
endif
endif
PROGRESSIVE_FLAGS := $(if $(filter 1,$(PROGRESSIVE)),-DBOARD_PROGRESSIVE=1,-DRT_USE_PROGRESSIVE=0)
# DITHER=1: ordered dithering of the packed formats (rt --dither); 0
# (the default) links none of it (RT_USE_DITHER=0).
DITHER ?= 0
DITHER_FLAGS := $(if $(filter 1,$(DITHER)),-DBOARD_DITHER=1,-DRT_USE_DITHER=0)
# TEXTURE_FILTER=0: textures sampled at the hit point (rt --texture-filter
# off), no ray cones linked; 1 (the default) filters them over the footprint.
TEXTURE_FILTER ?= 1
TEXTURE_FILTER_FLAGS := $(if $(filter 0,$(TEXTURE_FILTER)),-DRT_TEXTURE_FILTER=0)
# SPECIALISE=1 (the default): firmware built for its one scene by the
# compiler. The tracer reads the scene's const tables as the constant
# rt_scene (RT_CONST_SCENE, src/tracer/trace.h), and the program is
# optimised whole (-flto, -O3, loops over the scene's few primitives
# unrolled), so counts, materials and positions fold into the code: the
# same source and the same image, fewer instructions for more code
# (docs/performance.md). 0: the generic firmware, which reads any scene's
# tables. libc_min.c and the board's own files stay out of LTO (the
# compiler emits memset/memcpy calls after the IR is read; runners look
# board symbols up by name). The link writes the one partition's call
# graph (lto-ltrans0.ltrans.ci) for make size's stack bound; make profile
# keeps trace_ray, trace_segment, the ray counters and scene_occluded as
# calls (RT_KEEP_FRAMES: its own build folder), the frames profile.py
# sorts ray kinds by.
SPECIALISE ?= 1
ifeq ($(filter 0 1,$(SPECIALISE)),)
$(error SPECIALISE=$(SPECIALISE): 0 (generic) or 1 (built for the scene))
endif
KEEP_FRAMES ?= $(if $(filter profile,$(MAKECMDGOALS)),$(SPECIALISE),0)
SPEC_OPT := -O3 --param max-completely-peel-times=64 --param max-completely-peeled-insns=1000 \
            --param max-inline-insns-single=1000 --param large-function-growth=1000
SPEC_CFLAGS := $(if $(filter 1,$(SPECIALISE)),-flto -DRT_CONST_SCENE=rt_scene $(SPEC_OPT) $(if $(filter 1,$(KEEP_FRAMES)),-DRT_KEEP_FRAMES))
SPEC_LDFLAGS = $(if $(filter 1,$(SPECIALISE)),-flto $(SPEC_OPT) $(FW_FLAGS_$(1)) -ffunction-sections -fdata-sections \
               -fno-tree-loop-distribute-patterns -flto-partition=one -fstack-usage -fcallgraph-info=su \
               -dumpdir $(FW_DIR)/$(1)/lto-)
# Every choice that makes one firmware differ from another, as WORD/DEFAULT:
# the word that names it, and the word its default would have. The build
# folder and the out/ names (RUN_OUT, make image's files) carry each word
# that is not its default, then the board's own (BOARD_TAG: panel, flip,
# STM32 variant, crystal, LED, USART...), so two builds that differ never
# share a name and the defaults' names stay short.
FW_CHOICES := $(SIZE)/$(DEFAULT_SIZE) d$(DEPTH)/d5 $(FORMAT)/$(or $(FW_FORMAT),rgb888) \
              $(call sampling_word,$(AA_LEVELS),$(AA_THRESHOLD),$(SPP))/$(call sampling_word,$(word 1,$(subst $(comma), ,$(BOARD_RUN_AA))),$(or $(word 2,$(subst $(comma), ,$(BOARD_RUN_AA))),0),0) \
              $(if $(filter 1,$(DITHER)),dither,nodither)/$(if $(filter 1,$(BOARD_RUN_DITHER)),dither,nodither) \
              $(if $(filter 1,$(PROGRESSIVE)),progressive,scanline)/$(if $(filter 1,$(BOARD_PROGRESSIVE)),progressive,scanline) \
              $(if $(filter 0,$(TEXTURE_FILTER)),pointtex,filtertex)/filtertex $(if $(filter 0,$(PRUNE)),noprune,prune)/prune \
              $(CONFIG)/q20 b$(BAND_LINES)/b$(BOARD_BAND_LINES) s$(STACK_SIZE)/s4096 cores$(CORES)/cores$(BOARD_CORES) \
              $(if $(filter 1,$(SPECIALISE)),spec$(if $(filter 1,$(KEEP_FRAMES)),frames),generic)/spec
empty :=
space := $(empty) $(empty)
FW_TAGS := $(subst $(space),,$(foreach c,$(FW_CHOICES),$(if $(filter-out $(lastword $(subst /, ,$(c))),$(firstword $(subst /, ,$(c)))),-$(firstword $(subst /, ,$(c))))))$(BOARD_TAG)
FW_DIR := $(FW_ROOT)/$(BOARD)/$(NAME)$(FW_TAGS)
FW_ELF := $(FW_DIR)/$(BACKEND).elf
SCENEC_DIR := build/scenec$(if $(filter-out q20,$(CONFIG)),-$(CONFIG))

FW_CFLAGS = $(WARN) -ffreestanding $(BOARD_CPU) -O2 -g -ffunction-sections -fdata-sections \
            -fno-tree-loop-distribute-patterns -fstack-usage -fcallgraph-info=su \
            $(BOARD_CAPS) -DBOARD_WIDTH=$(W) -DBOARD_HEIGHT=$(H) -DBOARD_DEPTH=$(DEPTH) $(if $(filter-out 1 2 3 4 5,$(DEPTH)),-DRT_MAX_DEPTH=$(DEPTH)) \
            -DBOARD_FORMAT=$(FMT_MACRO) -DBOARD_BAND_LINES=$(BAND_LINES) -DBOARD_CORES=$(CORES) -DBOARD_CYCLES=$(BOARD_CYCLES) -DBOARD_INSTR_COUNTER=$(BOARD_INSTR_COUNTER) -DRT_MAX_WORKERS=$(CORES) -DRT_FB_ONLY_FORMAT=$(FMT_MACRO) -DSCENE_PRUNE=$(PRUNE) -DRT_USE_SPD=0 $(AA_FLAGS) $(DITHER_FLAGS) $(PROGRESSIVE_FLAGS) $(TEXTURE_FILTER_FLAGS) \
            $(CFG_FLAGS) $(BOARD_CFLAGS) -include $(FW_DIR)/scene_data.h -Iinclude -Isrc -Iplatform -Iapp/firmware -I$(FW_DIR) $(SPEC_CFLAGS)
# Sources compiled with -Os instead of -O2, where bytes count more than
# instructions: the frame (render.c: set-up and once per pixel), errors and
# counters, the UART sink, and the solids' object-space code (xform,
# shape, csg, object), linked only for scenes with solids. Measured on
# mps2-an385: the default scene's code 22473 -> 20301 bytes (the 20 KiB
# budget) for 18743 -> 19478 instructions per pixel; balls-2 +0.4%. The
# camera makes an eye ray a pixel: -Os in the fixed build, which walks T
# by additions (no slower for 56 bytes less), -O2 in the float build,
# whose products -Os would slow (the card +1%).
FW_SIZE_FILES = render rt_error stats sink_stream xform shape csg object
FW_SIZE_FILES_fixed = camera
FW_LDFLAGS = $(BOARD_CPU) -Wl,--defsym=__stack_size=$(STACK_SIZE) -Wl,--defsym=__aa_levels=$(AA_LEVELS) -nostdlib -nostartfiles -T $(BOARD_LD) -Lapp/firmware -Wl,--gc-sections $(BOARD_LDFLAGS)

# Per backend: fixed point; float with the board's FPU when it has one
# (else soft-float); double, soft-float (what a user without this project
# would run: the benchmark's comparison). Each gets flash tables from the
# scene compiler built for it.
FW_FLAGS_fixed  = $(BOARD_FPU)
FW_FLAGS_float  = $(BOARD_FPU) -DRT_BACKEND_FLOAT=1 -fno-math-errno -ffp-contract=off
FW_FLAGS_double = $(BOARD_FPU) -DRT_BACKEND_DOUBLE=1

# The firmware's files: the core, the board-independent firmware, the
# architecture's reset and exit, the board's own, the display sink.
FW_PORT_SRC = app/firmware/main.c app/firmware/report.c app/firmware/stack.c app/firmware/sink_io.c \
              $(if $(filter-out 1,$(CORES)),app/firmware/bands.c) \
              app/firmware/libc_min.c $(BOARD_SINK) \
              $(filter-out $(BOARD_ARCH_SKIP:%=platform/arch/$(BOARD_ARCH)/%.c),$(wildcard platform/arch/$(BOARD_ARCH)/*.c)) \
              $(wildcard platform/arch/$(BOARD_ARCH)/*.S) $(BOARD_SRC)
FW_SRC_DIRS = $(CORE_DIRS) app/firmware platform/arch/$(BOARD_ARCH) $(sort $(patsubst %/,%,$(dir $(BOARD_SRC) $(BOARD_SINK))))
# (the objects are linked by file name, whatever folder a file is in)
CORE_NAMES = $(sort $(notdir $(CORE_SRC:.c=)))
FW_NAMES = $(CORE_NAMES) $(basename $(notdir $(FW_PORT_SRC)))

# ---- scene compiler (a host tool, with the firmware's capacities) -------

$(SCENEC_DIR)/%.o: src/%.c $(CORE_H) app/firmware/firmware.mk
	@mkdir -p $(@D)
	$(show) CC $@
	$(Q)$(CC) $(WARN) -ffreestanding -O2 $(BOARD_CAPS) $(CFG_FLAGS) -Iinclude -Isrc -c $< -o $@

$(SCENEC_DIR)/rt-scenec: tools/scenec.c app/rt/host_io.c $(patsubst src/%.c,$(SCENEC_DIR)/%.o,$(CORE_SRC)) \
                         $(wildcard app/rt/*.h) $(CORE_H)
	$(show) LD $@
	$(Q)$(CC) $(WARN) -D_POSIX_C_SOURCE=200809L -O2 $(BOARD_CAPS) $(CFG_FLAGS) -Iinclude -Isrc -Iapp/rt -o $@ \
	    $(filter %.c %.o,$^)

# ---- firmware ------------------------------------------------------------

# Two scenes of one file name in different folders share a build folder:
# scene.path holds the scene's path and changes when another one is
# built there, so its tables are made again even when that file is older.
$(FW_DIR)/scene.path: FORCE
	@mkdir -p $(@D)
	@[ "$$(cat $@ 2>/dev/null)" = '$(abspath $(SCENE))' ] || echo '$(abspath $(SCENE))' >$@
FORCE:

$(FW_DIR)/scene_data.c $(FW_DIR)/scene_data.h &: $(SCENE) $(FW_DIR)/scene.path $(SCENEC_DIR)/rt-scenec
	@mkdir -p $(@D)
	$(show) SCENEC $(FW_DIR)/scene_data.c
	$(Q)$(SCENEC_DIR)/rt-scenec $(SCENE) -o $(FW_DIR)/scene_data.c --header $(FW_DIR)/scene_data.h

# The float and double builds get their tables from the scene compiler
# built for that backend (host cc, -ffp-contract=off as the firmware, libm
# for the reader's tan/sin/cos/floor): the same bits the host reader makes.
define scenec_fp
$(SCENEC_DIR)-$(1)/%.o: src/%.c $(CORE_H) app/firmware/firmware.mk
	@mkdir -p $$(@D)
	$$(show) CC $$@
	$$(Q)$$(CC) $(WARN) -ffreestanding -O2 -ffp-contract=off $$(BOARD_CAPS) $$(CFG_FLAGS) $(2) -Iinclude -Isrc -c $$< -o $$@

$(SCENEC_DIR)-$(1)/rt-scenec: tools/scenec.c app/rt/host_io.c $$(patsubst src/%.c,$(SCENEC_DIR)-$(1)/%.o,$$(CORE_SRC)) \
                         $(wildcard app/rt/*.h) $(CORE_H)
	$$(show) LD $$@
	$$(Q)$$(CC) $(WARN) -D_POSIX_C_SOURCE=200809L -O2 -ffp-contract=off $$(BOARD_CAPS) $$(CFG_FLAGS) $(2) -Iinclude -Isrc \
	    -Iapp/rt -o $$@ $$(filter %.c %.o,$$^) -lm

$(FW_DIR)/scene_data_$(1).c: $(SCENE) $(FW_DIR)/scene.path $(SCENEC_DIR)-$(1)/rt-scenec
	@mkdir -p $$(@D)
	$$(show) SCENEC $$@
	$$(Q)$(SCENEC_DIR)-$(1)/rt-scenec $(SCENE) -o $$@
endef
$(eval $(call scenec_fp,float,-DRT_BACKEND_FLOAT=1))
$(eval $(call scenec_fp,double,-DRT_BACKEND_DOUBLE=1))

# FW_CACHE=DIR: a file whose preprocessed text and flags an earlier
# firmware's compile had takes that one's object (tools/firmware/cc-cache.sh;
# the test suites, which build many firmware that differ in scene, size or
# format, share one: tests/run-all.py)
FW_CCACHE = $(if $(FW_CACHE),sh tools/firmware/cc-cache.sh $(FW_CACHE) $(FW_DIR))

# $(1) backend, $(2) a folder of sources
define firmware_objs
$(FW_DIR)/$(1)/%.o: $(2)/%.c $(CORE_H) platform/port.h $(wildcard app/firmware/*.h) $(FW_DIR)/scene_data.h platform/$(BOARD)/board.mk
	@mkdir -p $$(@D)
	$$(show) CC $$@
	$$(Q)$$(FW_CCACHE) $$(FW_CC) $$(FW_CFLAGS) $$(FW_FLAGS_$(1)) $$(if $$(filter $$(basename $$(notdir $$<)),$$(FW_SIZE_FILES) $$(FW_SIZE_FILES_$(1))),-Os) \
	    $$(if $$(filter libc_min $$(basename $$(notdir $$(BOARD_SRC))),$$(basename $$(notdir $$<))),-fno-lto) -c $$< -o $$@
$(FW_DIR)/$(1)/%.o: $(2)/%.S platform/$(BOARD)/board.mk
	@mkdir -p $$(@D)
	$$(show) AS $$@
	$$(Q)$$(FW_CC) $$(BOARD_CPU) $$(FW_FLAGS_$(1)) -c $$< -o $$@
endef
$(foreach b,$(BOARD_BACKENDS),$(foreach d,$(FW_SRC_DIRS) $(FW_DIR),$(eval $(call firmware_objs,$(b),$(d)))))

FW_OBJS_fixed  = $(patsubst %,$(FW_DIR)/fixed/%.o,$(FW_NAMES) scene_flash scene_data) $(BOARD_OBJS)
FW_OBJS_float  = $(patsubst %,$(FW_DIR)/float/%.o,$(FW_NAMES) scene_flash scene_data_float) $(BOARD_OBJS)
FW_OBJS_double = $(patsubst %,$(FW_DIR)/double/%.o,$(FW_NAMES) scene_flash scene_data_double) $(BOARD_OBJS)
PRIMS_OBJS = $(filter-out $(FW_DIR)/fixed/main.o,$(FW_OBJS_fixed)) $(FW_DIR)/fixed/bench_prims.o

# libc and libm only for what a soft-float build needs (newlib's sqrt; a
# hard-float build inlines vsqrt and links none of them; the fixed build
# neither: tests/boards/ports-tests.sh checks).
define firmware_elf
$(FW_DIR)/$(1).elf: $$(FW_OBJS_$(1)) $(BOARD_LD) app/firmware/sections.ld
	$$(show) LD $$@
	$$(Q)$$(FW_CC) $$(FW_LDFLAGS) $$(BOARD_FPU) $$(call SPEC_LDFLAGS,$(1)) -Wl,-Map=$(FW_DIR)/$(1).map -o $$@ $$(FW_OBJS_$(1)) $(2) -lgcc
endef
$(eval $(call firmware_elf,fixed,))
$(eval $(call firmware_elf,float,-lm -lc))
$(eval $(call firmware_elf,double,-lm -lc))

# The intersection-cost probe (bench/prims-bench.sh): no frame, just tests.
$(FW_DIR)/prims.elf: $(PRIMS_OBJS) $(BOARD_LD) app/firmware/sections.ld
	$(show) LD $@
	$(Q)$(FW_CC) $(FW_LDFLAGS) $(BOARD_FPU) -o $@ $(PRIMS_OBJS) -lgcc

firmware: $(FW_ELF) $(BOARD_IMAGES)

# The board's images beside the PNG (out/<scene>-<board>-<backend>[-choices].<ext>),
# each copy then named by the command $(1)
copy_images = $(foreach f,$(BOARD_IMAGES),cp $(f) $(basename $(RUN_OUT))$(suffix $(f)) && $(1) $(basename $(RUN_OUT))$(suffix $(f));)

# make image: the files to flash (BOARD_IMAGES) of a board that exists as
# silicon, copied to out/ with the name make run gives the PNG; the
# board's BOARD_IMAGE_NOTE says how to flash them
image: deps-image $(BOARD_IMAGES)
	@$(if $(BOARD_IMAGES),,echo "BOARD=$(BOARD) makes no image to flash: it runs under its emulator only" >&2; exit 1)
	@mkdir -p $(dir $(RUN_OUT))
	@$(call copy_images,$(or $(BOARD_IMAGE_SHOW),echo))
	@echo "$(BOARD_IMAGE_NOTE)"

# make flash: the image onto a board on USB, by the board's BOARD_FLASH
# command (its tool, BOARD_FLASH_PACKAGE, installed when missing)
flash: $(BOARD_IMAGES)
	@$(if $(BOARD_FLASH),,echo "BOARD=$(BOARD) has no flash command$(if $(BOARD_IMAGES),: make image writes the files to flash ($(BOARD_IMAGE_NOTE)),: it runs under its emulator only)" >&2; exit 1)
	@ENSURE_DEPS_FOR='make flash (BOARD=$(BOARD))' sh tools/ensure-deps.sh run $(BOARD_FLASH_PACKAGE)
	$(BOARD_FLASH)

ifneq ($(BOARD_RULES),)
include $(BOARD_RULES)
endif

# ---- running it ------------------------------------------------------------

RUN_RT  ?= build/host/rt
# the folder of make run's, make host-run's and make image's files
OUT_DIR ?= out
RUN_OUT ?= $(OUT_DIR)/$(NAME)-$(BOARD)-$(BACKEND)$(FW_TAGS).png
# The references make run measures against are named by what changes
# them and nothing else (not the board): runs that would render the same
# reference share it, runs that would not never overwrite each other's.
# Both: the size unless the scene's resolution, the depth unless 5
# (REF_TAGS). The exact model: the double build at the run's samples (the
# sampling word of FW_CHOICES, with the backend whose adaptive splits it
# replays) in the board's pixel format, so with FORMAT=rgb565 the figure
# is the renderer's error, not the format's; then dither and pointtex
# when on. The pixel-area image: its colours (RUN_AREA_FORMAT).
REF_TAGS = $(if $(filter-out $(SCENE_SIZE),$(SIZE)),-$(SIZE))$(if $(filter-out 5,$(DEPTH)),-d$(DEPTH))
RUN_REF = $(OUT_DIR)/$(NAME)-double$(REF_TAGS)-$(call sampling_word,$(AA_LEVELS),$(AA_THRESHOLD),$(SPP))$(if \
          $(filter-out 0,$(AA_LEVELS)),-$(BACKEND))-$(FORMAT)$(if $(filter 1,$(DITHER)),-dither)$(if $(filter 0,$(TEXTURE_FILTER)),-pointtex).png

# Run the built firmware: RUN_OUT gets the image, stdout the report.
board-run:
	@QEMU="$(BOARD_QEMU)" QEMU_ICOUNT="$(BOARD_ICOUNT)" QEMU_ACCEL="$(QEMU_ACCEL)" \
	    RUN_END=$(if $(filter semihost,$(BOARD_ARCH_SKIP)),report,exit) $(BOARD_RUN) $(FW_ELF) $(RUN_OUT) $(RUN_RT) $(BOARD_CLOCK_HZ)

RUN_SAMPLING = $(if $(filter-out 0,$(AA_LEVELS)),--aa $(AA))$(if $(filter-out 0 1,$(SPP)),--spp $(SPP))$(if $(filter 0,$(TEXTURE_FILTER)), --texture-filter off)
# the pixel-area image in the colours the format keeps: 8-bit grey for l8
# and l4, 8-bit RGB for the others (so the figure includes the format's
# own rounding, and dithering's effect on it)
RUN_AREA_FORMAT = $(if $(filter l4 l8,$(FORMAT)),l8,rgb888)
RUN_AREA = $(OUT_DIR)/$(NAME)-area$(REF_TAGS)-$(RUN_AREA_FORMAT).png
RUN_DITHER = $(if $(filter 1,$(DITHER)),--dither)
RUN_REPORT = $(FW_DIR)/report-$(BACKEND).txt
run: deps-board
	$(Q)$(MAKE) build/host/rt $(FW_ELF) $(BOARD_IMAGES) AA=$(AA) SPP=$(SPP) DITHER=$(DITHER) TEXTURE_FILTER=$(TEXTURE_FILTER)
	@mkdir -p $(sort $(dir $(RUN_OUT) $(RUN_REF) $(RUN_AREA)))
	$(show) RUN "$(FW_ELF) on $(BOARD)"
	@$(MAKE) -s board-run AA=$(AA) SPP=$(SPP) DITHER=$(DITHER) TEXTURE_FILTER=$(TEXTURE_FILTER) >$(RUN_REPORT); \
	    status=$$?; [ $$status = 0 ] || { cat $(RUN_REPORT); exit $$status; }
	$(show) RT "$(RUN_REF) (the exact model at the same samples)"
	@build/host/rt $(SCENE) -o $(RUN_REF) --double $(RUN_SAMPLING) --same-samples $(BACKEND) --format $(FORMAT) $(RUN_DITHER) --depth $(DEPTH) --size $(SIZE) --quiet
	$(show) RT "$(RUN_AREA) (the pixel-area image: rt --double --spp 16 --texture-filter off)"
	@build/host/rt $(SCENE) -o $(RUN_AREA) --double --spp 16 --texture-filter off --format $(RUN_AREA_FORMAT) --depth $(DEPTH) --size $(SIZE) --quiet
	@$(call copy_images,true)
	@SCENE=$(SCENE) SIZE=$(SIZE) DEPTH=$(DEPTH) BOARD=$(BOARD) BOARD_TITLE="$(BOARD_TITLE)" CLOCK_HZ=$(BOARD_CLOCK_HZ) BACKEND=$(BACKEND) SAMPLING="$(RUN_SAMPLING)$(if $(RUN_DITHER), $(RUN_DITHER))" \
	    OUT=$(RUN_OUT) IMAGE_NOTE="$(if $(RUN_SAMPLING),, (one sample a pixel: make run AA=L anti-aliases, as RAM allows))" \
	    IMAGES="$(foreach f,$(BOARD_IMAGES),$(basename $(RUN_OUT))$(suffix $(f)))" \
	    sh tools/firmware/summary.sh $(RUN_REPORT) "$$(build/host/rt compare $(RUN_OUT) $(RUN_REF))" \
	    "$$(build/host/rt compare $(RUN_OUT) $(RUN_AREA))" "$$(build/host/rt compare $(RUN_OUT) $(RUN_AREA) --blur 1)"

size: $(FW_ELF)
	@CROSS=$(BOARD_CROSS) SINK_CALLBACKS=$(BOARD_SINK_CALLBACKS) tools/firmware/footprint.sh $(FW_ELF) $(FW_DIR)/$(BACKEND) $(FW_DIR)/report-$(BACKEND).txt

# Instructions per function, group and ray kind inside the render, under
# QEMU (bench/profile.py), with the display sink apart as the firmware's
# count has it; fails when the total or the ray counts disagree with the
# firmware's report. The figures also go to PROFILE_JSON. One core: a
# two-core board is profiled with CORES=1 (the trace follows one CPU).
PROFILE_JSON ?= $(FW_DIR)/profile-$(BACKEND).json
ifneq ($(CORES),1)
profile: deps-board
	@$(MAKE) -s profile CORES=1 SIZE=$(SIZE)
else
profile: deps-board
	@$(MAKE) -s $(FW_ELF) SIZE=$(SIZE) KEEP_FRAMES=$(KEEP_FRAMES)
	python3 bench/profile.py $(FW_ELF) --machine $(BOARD) --qemu $(word 1,$(BOARD_QEMU)) \
	    --sink $(BOARD_SINK_CALLBACKS) --json $(PROFILE_JSON) --check
	@echo "JSON: $(PROFILE_JSON)"
endif

print-fwdir:
	@echo $(FW_DIR)

# the board's facts for scripts: make -s board-info BOARD=..
board-info:
	@echo "fw_dir=$(FW_DIR) elf=$(FW_ELF) out=$(basename $(RUN_OUT)) size=$(SIZE) cross=$(BOARD_CROSS) backends='$(BOARD_BACKENDS)' fpu='$(BOARD_FPU)' clock_hz=$(BOARD_CLOCK_HZ) format=$(FORMAT) cores=$(BOARD_CORES) variants='$(BOARD_BENCH_VARIANTS)'"
