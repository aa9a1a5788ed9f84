# board.mk - firmware for the ARM MPS2 AN385 (Cortex-M3, no FPU) under
# QEMU. Included by the top-level Makefile; SCENE, SIZE, DEPTH, FORMAT
# and NAME come from there.
#
# Each (scene, size, depth, format) gets its own build folder: the scene
# compiler turns the NFF into const tables in flash plus a header saying
# what the scene uses, and the firmware is built for exactly that.

ARM_CC    ?= arm-none-eabi-gcc
ARM_NM    ?= arm-none-eabi-nm
ARM_SIZE  ?= arm-none-eabi-size
BOARD_DIR := platform/mps2-an385
# make run turns the render's instruction count into time on a board
# with this clock (the MPS2 AN385's FPGA runs the Cortex-M3 at 25 MHz),
# assuming one instruction per cycle.
BOARD_CLOCK_HZ ?= 25000000

# Flash tables make these limits of the scene compiler, not of RAM.
BOARD_CAPS = -DRT_MAX_SPHERES=1024 -DRT_MAX_CONES=1024 -DRT_MAX_POLYGONS=4096 \
             -DRT_MAX_VERTICES=32768 -DRT_MAX_LIGHTS=16 -DRT_MAX_MATERIALS=128

W := $(word 1,$(subst x, ,$(SIZE)))
H := $(word 2,$(subst x, ,$(SIZE)))
# FORMAT: a name of RT_FB_FORMATS (src/rt_fb.h), lower case: rgb888 -> RT_FB_RGB888.
FMT_MACRO := RT_FB_$(shell echo '$(FORMAT)' | tr a-z A-Z)
# PRUNE=1 (default): code for primitive kinds and shading features the
# scene does not use is compiled out (RT_USE_* from scene_data.h).
PRUNE ?= 1
# CONFIG picks a numeric configuration of the fixed backend (CFG_* in the
# Makefile): q20 (the default, Q11.20), q20fast, q16, q16fast, q12, q24.
CONFIG ?= q20
CFG_FLAGS := $(CFG_$(CONFIG))
FW_DIR := build/board/$(NAME)-$(SIZE)-d$(DEPTH)-$(FORMAT)$(if $(filter 0,$(PRUNE)),-noprune)$(if $(filter-out q20,$(CONFIG)),-$(CONFIG))
SCENEC_DIR := build/scenec$(if $(filter-out q20,$(CONFIG)),-$(CONFIG))

ARM_ARCH = -mcpu=cortex-m3 -mthumb
BOARD_CFLAGS = $(WARN) -ffreestanding $(ARM_ARCH) -O2 -g -ffunction-sections -fdata-sections \
               -fno-tree-loop-distribute-patterns -fstack-usage -fcallgraph-info=su \
               $(BOARD_CAPS) -DBOARD_WIDTH=$(W) -DBOARD_HEIGHT=$(H) -DBOARD_DEPTH=$(DEPTH) \
               -DBOARD_FORMAT=$(FMT_MACRO) -DRT_FB_ONLY_FORMAT=$(FMT_MACRO) -DSCENE_PRUNE=$(PRUNE) -DRT_USE_SPD=0 $(CFG_FLAGS) -include $(FW_DIR)/scene_data.h \
               -Isrc -I$(BOARD_DIR) -I$(FW_DIR)
BOARD_LDFLAGS = $(ARM_ARCH) -nostdlib -nostartfiles -T linker/mps2-an385.ld -Wl,--gc-sections

PORT_SRC  = startup.c uart.c icount.c semihost.c libc_min.c fb_uart.c main.c
CORE_NAMES = $(notdir $(CORE_SRC:.c=))
PORT_NAMES = $(PORT_SRC:.c=)

# ---- scene compiler (a host tool, with the firmware's capacities) -------

$(SCENEC_DIR)/%.o: src/%.c $(wildcard src/*.h) $(BOARD_DIR)/board.mk
	@mkdir -p $(@D)
	$(CC) $(WARN) -ffreestanding -O2 $(BOARD_CAPS) $(CFG_FLAGS) -Isrc -c $< -o $@

$(SCENEC_DIR)/rt-scenec: tools/scenec.c platform/hosted/host_io.c $(patsubst %,$(SCENEC_DIR)/%.o,$(CORE_NAMES)) \
                         $(wildcard platform/hosted/*.h) $(wildcard src/*.h)
	$(CC) $(WARN) -D_POSIX_C_SOURCE=200809L -O2 $(BOARD_CAPS) $(CFG_FLAGS) -Isrc -Iplatform/hosted -o $@ \
	    $(filter %.c %.o,$^)

# ---- firmware ------------------------------------------------------------

$(FW_DIR)/scene_data.c $(FW_DIR)/scene_data.h &: $(SCENE) $(SCENEC_DIR)/rt-scenec
	@mkdir -p $(@D)
	$(SCENEC_DIR)/rt-scenec $(SCENE) -o $(FW_DIR)/scene_data.c --header $(FW_DIR)/scene_data.h

$(FW_DIR)/scene_text_data.c: $(SCENE) $(SCENEC_DIR)/rt-scenec $(FW_DIR)/scene_data.h
	$(SCENEC_DIR)/rt-scenec $(SCENE) -o $@ --text

# $(1) backend name, $(2) backend flags
define firmware_objs
$(FW_DIR)/$(1)/%.o: src/%.c $(wildcard src/*.h) $(FW_DIR)/scene_data.h
	@mkdir -p $$(@D)
	$$(ARM_CC) $$(BOARD_CFLAGS) $(2) -c $$< -o $$@

$(FW_DIR)/$(1)/%.o: $(BOARD_DIR)/%.c $(wildcard $(BOARD_DIR)/*.h) $(wildcard src/*.h) $(FW_DIR)/scene_data.h
	@mkdir -p $$(@D)
	$$(ARM_CC) $$(BOARD_CFLAGS) $(2) -c $$< -o $$@

$(FW_DIR)/$(1)/%.o: $(FW_DIR)/%.c $(wildcard src/*.h)
	@mkdir -p $$(@D)
	$$(ARM_CC) $$(BOARD_CFLAGS) $(2) -c $$< -o $$@
endef
$(eval $(call firmware_objs,fixed,))
$(eval $(call firmware_objs,double,-DRT_BACKEND_DOUBLE=1))
$(eval $(call firmware_objs,float,-DRT_BACKEND_FLOAT=1))

FIXED_OBJS = $(patsubst %,$(FW_DIR)/fixed/%.o,$(CORE_NAMES) $(PORT_NAMES) scene_flash scene_data)
PRIMS_OBJS = $(filter-out $(FW_DIR)/fixed/main.o,$(FIXED_OBJS)) $(FW_DIR)/fixed/bench_prims.o
DOUBLE_OBJS = $(patsubst %,$(FW_DIR)/double/%.o,$(CORE_NAMES) $(PORT_NAMES) scene_text scene_text_data)
FLOAT_OBJS = $(patsubst %,$(FW_DIR)/float/%.o,$(CORE_NAMES) $(PORT_NAMES) scene_text scene_text_data)

$(FW_DIR)/fixed.elf: $(FIXED_OBJS) linker/mps2-an385.ld
	$(ARM_CC) $(BOARD_LDFLAGS) -Wl,-Map=$(FW_DIR)/fixed.map -o $@ $(FIXED_OBJS) -lgcc

# The same core with the double backend, as soft-float: what a user
# without this project would run. It reads the embedded NFF text at boot
# and builds its BVH there, hence the larger stack.
$(FW_DIR)/double.elf: $(DOUBLE_OBJS) linker/mps2-an385.ld
	$(ARM_CC) $(BOARD_LDFLAGS) -Wl,--defsym=__stack_size=0x10000 -Wl,-Map=$(FW_DIR)/double.map \
	    -o $@ $(DOUBLE_OBJS) -lm -lc -lgcc

# ... and as single-precision soft-float (__aeabi_f*).
$(FW_DIR)/float.elf: $(FLOAT_OBJS) linker/mps2-an385.ld
	$(ARM_CC) $(BOARD_LDFLAGS) -Wl,--defsym=__stack_size=0x10000 -Wl,-Map=$(FW_DIR)/float.map \
	    -o $@ $(FLOAT_OBJS) -lm -lc -lgcc

# The intersection-cost probe (bench/prims-bench.sh): no frame, just tests.
$(FW_DIR)/prims.elf: $(PRIMS_OBJS) linker/mps2-an385.ld
	$(ARM_CC) $(BOARD_LDFLAGS) -o $@ $(PRIMS_OBJS) -lgcc

firmware: $(FW_DIR)/fixed.elf

# ---- running it ------------------------------------------------------------

# The reference is the double build in the board's pixel format, so with
# FORMAT=rgb565 the figure is the renderer's error, not the format's.
RUN_REF = out/$(NAME)-double$(if $(filter rgb565,$(FORMAT)),-rgb565).png
RUN_REF_IS = $(if $(filter rgb565,$(FORMAT)),the double reference quantised to rgb565 as well,the exact double reference)

run: deps-board
	$(MAKE) build/host/rt $(FW_DIR)/fixed.elf
	@mkdir -p out
	@$(BOARD_DIR)/qemu-run.sh $(FW_DIR)/fixed.elf out/$(NAME).png build/host/rt $(BOARD_CLOCK_HZ) >$(FW_DIR)/report.txt; \
	    status=$$?; cat $(FW_DIR)/report.txt; exit $$status
	@build/host/rt $(SCENE) -o $(RUN_REF) --double --format $(FORMAT) --depth $(DEPTH) --size $(SIZE) --quiet
	@printf 'board (fixed, $(FORMAT)) vs $(RUN_REF_IS): '
	@build/host/rt compare out/$(NAME).png $(RUN_REF)
	@echo "image: out/$(NAME).png"

size: $(FW_DIR)/fixed.elf
	@$(BOARD_DIR)/footprint.sh $(FW_DIR)/fixed.elf $(FW_DIR)/fixed $(FW_DIR)/report.txt

print-fwdir:
	@echo $(FW_DIR)
