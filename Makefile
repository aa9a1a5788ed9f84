# Fixed-point Whitted ray tracer: host build, board firmware, tests.
#
#   make            build the hosted CLI (build/host/rt); V=1 shows the
#                   full commands
#   make run        install the host build's and BOARD's missing packages,
#                   render SCENE on an emulated board (BOARD=mps2-an385 by
#                   default, BACKEND=fixed; app/firmware/firmware.mk)
#                   at the scene's resolution unless SIZE=WxH is given,
#                   write out/<scene>-<board>-<backend>[-choices].png, print instructions per pixel,
#                   render time at BOARD_CLOCK_HZ, QEMU's wall time and the
#                   error against the host's double build (out/'s names:
#                   docs/boards.md; OUT_DIR=dir writes them there)
#   make host-run   the same render on the host, fixed and double
#   make size       flash/RAM by section and stack use of the firmware
#   make profile    where the firmware's render spends its instructions: per
#                   function, group (traversal, each primitive, maths,
#                   shading, output) and ray kind (eye, reflection,
#                   refraction, shadow), checked against the firmware's own
#                   counters (bench/profile.py; same variables as make run,
#                   SIZE 64x64 unless given; about 35 s for balls-2)
#   make test       install missing packages (all of them), build, run every test
#   make install    rt, the scene compiler rt-scenec, the core as
#                   librt_core.a, the public headers (include/rt/) and the
#                   CMake package (lib/cmake/rt/) under DESTDIR PREFIX
#                   (/usr/local; bindir, libdir, includedir), as
#                   `cmake --install` lays them out; make uninstall
#                   removes them
#   make bench      run time against error over numeric configurations, the
#                   host's speed-up with rt --threads 2, BVH scaling, code size
#                   with and without pruning, every board and backend, anti-aliasing
#                   and dithering against the pixel-area image, seconds a frame
#                   against error on every board (its duration: docs/performance.md);
#                   make bench-STEP one of them (BENCH_STEPS), rewriting bench/STEP.md
#   make bench-quick  a subset of the first (its duration: docs/performance.md)
#
# The core (src/) is compiled once per numeric backend (fixed, double,
# float, and double with the fixed build's tolerances); each copy is
# partially linked with app/rt/backend.c into one object that
# exports only its rt_backend_t, so `rt` carries every build.

SCENE ?= scenes/showpiece.nff
# SIZE (WxH): the scene's resolution unless given (firmware.mk; rt's own
# default for make host-run)
DEPTH ?= 5
FORMAT ?= rgb888
# make profile: QEMU logs every block executed, so it renders 64x64 unless
# SIZE is given (on every board, the OLED's included)
ifneq ($(filter profile,$(MAKECMDGOALS)),)
ifeq ($(origin SIZE),undefined)
override SIZE := 64x64
endif
endif
# the goals that read SCENE: a scene that is not there stops them at once
SCENE_GOALS = run host-run image uf2 flash firmware size board-run profile board-info print-fwdir
ifneq ($(filter $(SCENE_GOALS),$(or $(MAKECMDGOALS),all)),)
ifeq ($(wildcard $(SCENE)),)
$(error SCENE=$(SCENE): no such file (the project's scenes are scenes/*.nff, scenes/spd/*.nff and scenes/bench/*.nff))
endif
endif

CC      ?= cc
LD      ?= ld
OBJCOPY ?= objcopy

# Quiet by default: one short line a file (what is done, to which file);
# V=1 prints the full commands, as kbuild and CMake do.
V ?= 0
ifeq ($(V),1)
Q :=
show = @:
else ifneq ($(findstring s,$(firstword -$(MAKEFLAGS))),)
Q := @
show = @:
else
Q := @
show = @printf '  %-7s %s\n'
MAKEFLAGS += --no-print-directory
endif

# Capacities for the host: large enough for every SPD "default" scene,
# and workers for `rt --threads` up to 64 (1.8 KiB each a backend); and
# recorded split decisions (`rt --same-samples`).
HOST_CAPS = -DRT_MAX_SPHERES=16384 -DRT_MAX_CONES=16384 -DRT_MAX_POLYGONS=16384 \
            -DRT_MAX_VERTICES=65536 -DRT_MAX_LIGHTS=32 -DRT_MAX_MATERIALS=1024 -DRT_MAX_WORKERS=64 -DRT_MAX_DEPTH=8 \
            -DRT_AA_REPLAY=1

WARN      = -std=c11 -Wall -Wextra -Werror
# The core: src/ and its layer folders (numeric, geometry, reader, tracer).
CORE_SRC  = $(wildcard src/*.c src/*/*.c)
CORE_DIRS = $(patsubst %/,%,$(sort $(dir $(CORE_SRC))))
CORE_H    = $(wildcard include/*.h src/*.h src/*/*.h)
HOST_INC  = -Iinclude -Isrc -Iapp/rt

# Two host variants: optimised, and sanitised (what the tests run).
host_CFLAGS = -O2 -g
asan_CFLAGS = -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=undefined \
              -fno-omit-frame-pointer
host_LDFLAGS =
asan_LDFLAGS = -fsanitize=address,undefined

.PHONY: all install uninstall run host-run test clean deps deps-board deps-image deps-host size profile bench $(BENCH_STEPS:%=bench-%) bench-quick firmware board-run board-info print-fwdir print-configs stress fuzz fuzz-coverage image uf2 pictures
all: build/host/rt

# The builds of the core in the host tools, with their flags: the ids of
# RT_HOST_BACKENDS in app/rt/backend.h.
HOST_BACKENDS = fixed double float double_ftol
BACKEND_FLAGS_fixed =
BACKEND_FLAGS_double = -DRT_BACKEND_DOUBLE=1
BACKEND_FLAGS_float = -DRT_BACKEND_FLOAT=1 -ffp-contract=off
BACKEND_FLAGS_double_ftol = -DRT_BACKEND_DOUBLE=1 -DRT_TOLERANCES_FIXED=1

# $(1) variant, $(2) backend id, $(3) backend flags
define core_rules
build/$(1)/$(2)/%.o: src/%.c $(CORE_H) Makefile
	@mkdir -p $$(@D)
	$$(show) CC $$@
	$$(Q)$$(CC) $(WARN) -ffreestanding $$($(1)_CFLAGS) $(HOST_CAPS) $(3) -Iinclude -Isrc -c $$< -o $$@

build/$(1)/$(2)/backend.o: app/rt/backend.c app/rt/backend.h $(CORE_H) Makefile
	@mkdir -p $$(@D)
	$$(show) CC $$@
	$$(Q)$$(CC) $(WARN) $$($(1)_CFLAGS) $(HOST_CAPS) $(3) -DBACKEND_ID=$(2) $(HOST_INC) -c $$< -o $$@

build/$(1)/core-$(2).o: $(patsubst src/%.c,build/$(1)/$(2)/%.o,$(CORE_SRC)) build/$(1)/$(2)/backend.o
	$$(show) LD $$@
	$$(Q)$$(LD) -r -o $$@.tmp $$^
	$$(Q)$$(OBJCOPY) -G rt_backend_$(2) $$@.tmp $$@
	@rm -f $$@.tmp
endef

# The core object of variant $(1), backend $(2): its own, or another
# variant's where $(1)_core_$(2) names one built with the same flags
core_obj = build/$(or $($(1)_core_$(2)),$(1))/core-$(2).o

# (each backend's rules are eval'd on their own: foreach joins its results
# with spaces, which would run one rule's recipe into the next rule)
RT_APP = main bands image receive uart_stream host_io report
define host_rules
$(foreach b,$(HOST_BACKENDS),$(eval $(call core_rules,$(1),$(b),$(BACKEND_FLAGS_$(b)))))

build/$(1)/%.o: app/rt/%.c $(wildcard app/rt/*.h) $(CORE_H) Makefile
	@mkdir -p $$(@D)
	$$(show) CC $$@
	$$(Q)$$(CC) $(WARN) -D_POSIX_C_SOURCE=200809L -pthread $$($(1)_CFLAGS) $(HOST_CAPS) $(HOST_INC) -c $$< -o $$@

# libpng for PNG files; zlib for the UART stream's Adler-32 checksums;
# POSIX threads for --threads (bands.c).
build/$(1)/rt: $(RT_APP:%=build/$(1)/%.o) $(foreach b,$(HOST_BACKENDS),$(call core_obj,$(1),$(b)))
	$$(show) LD $$@
	$$(Q)$$(CC) -pthread $$($(1)_LDFLAGS) -o $$@ $$^ -lpng -lz -lm

build/$(1)/test_%: tests/unit/test_%.c $(foreach b,$(HOST_BACKENDS),$(call core_obj,$(1),$(b))) tests/lib/testlib.h tests/unit/probe_jump.h
	$$(show) CC $$@
	$$(Q)$$(CC) $(WARN) -D_POSIX_C_SOURCE=200809L $$($(1)_CFLAGS) $$($(1)_LDFLAGS) $(HOST_CAPS) $(HOST_INC) -Itests/lib \
	    -o $$@ $$< $(foreach b,$(HOST_BACKENDS),$(call core_obj,$(1),$(b))) -lm
endef

$(eval $(call host_rules,host))
$(eval $(call host_rules,asan))

# Numeric configurations of the fixed backend, the one list of them (make
# run CONFIG=..., make bench, tests/boards/configs-tests.sh; each one's
# accuracy against the exact build is docs/accuracy.md's table), and
# build/cfg-NAME/rt for each: build/host/rt with its fixed backend built
# with other fraction bits or fast operations (nothing else in rt
# depends on them; with no flags, build/host/rt itself).
CONFIGS = q20 q20fast q16 q16fast q12
CFG_q20 =
CFG_q20fast = -DFX_FAST_MATH=1
CFG_q16 = -DFX_FRAC_BITS=16
CFG_q16fast = -DFX_FRAC_BITS=16 -DFX_FAST_MATH=1
CFG_q12 = -DFX_FRAC_BITS=12
define cfg_rules
$(if $(CFG_$(1)),$(eval $(call core_rules,cfg-$(1),fixed,)))
build/cfg-$(1)/rt: $(RT_APP:%=build/host/%.o) $(foreach b,$(HOST_BACKENDS),build/$(if $(CFG_$(1)),$(if $(filter fixed,$(b)),cfg-$(1),host),host)/core-$(b).o)
	@mkdir -p $$(@D)
	$$(show) LD $$@
	$$(Q)$$(CC) -pthread -o $$@ $$^ -lpng -lz -lm
endef
$(foreach c,$(CONFIGS),$(eval cfg-$(c)_CFLAGS = $(host_CFLAGS) $(CFG_$(c)))$(eval $(call cfg_rules,$(c))))
# the list for scripts: make -s print-configs
print-configs:
	@echo $(CONFIGS)

# ThreadSanitizer build of rt (tests/host/threads-tests.sh): renders on several
# threads share no written byte (and the saturation counter is atomic).
tsan_CFLAGS = -O1 -g -fsanitize=thread -DFX_COUNT_SATURATIONS=1
tsan_LDFLAGS = -fsanitize=thread
$(eval $(call host_rules,tsan))

# The stress suite's build: sanitised, and counting fixed-point saturations.
stress_CFLAGS = $(asan_CFLAGS) -DFX_COUNT_SATURATIONS=1
stress_LDFLAGS = $(asan_LDFLAGS)
# FX_COUNT_SATURATIONS changes only the fixed backend (the other builds'
# counts are never read: app/rt/backend.c), so they are asan's objects
stress_core_double = asan
stress_core_float = asan
stress_core_double_ftol = asan
$(eval $(call host_rules,stress))

# ---- unit tests (tests/unit/) ---------------------------------------------
#
# The one list of unit tests is tests/suites.list, whose $B/test_NAME lines
# make test runs; each is built as build/asan/test_NAME. By default a test
# links the whole core (every backend, as rt does): build/VARIANT/test_NAME
# from tests/unit/test_NAME.c (host_rules above). A test that links only
# the files it tests names them in test_NAME_SRC, its own source first,
# with test_NAME_FLAGS (defines) and test_NAME_INC (include folders) if it
# needs them; UNIT_FX_SRC is the fixed-point layer most of them link.
UNIT_TESTS := $(patsubst $$B/%,%,$(filter $$B/test_%,$(file < tests/suites.list)))
UNIT_FX_SRC = $(wildcard src/numeric/fx*.c)

# every fixed-point operation against double
test_fx_SRC = tests/unit/test_fx.c $(UNIT_FX_SRC)
# the same with fx.c on the ARMv6-M path (no long multiply, no divide, no
# CLZ): 16x16 partial products, the reciprocal's seed table, fx_clz32's
# binary search
test_fx_soft_SRC = $(test_fx_SRC)
test_fx_soft_FLAGS = -DFX_MUL64_PARTIAL=1 -DFX_RECIP_TABLE=1 -DFX_CLZ_BUILTIN=0
# the coarse sphere test of cores without a long multiply, against the
# exact test (this build's sphere_hit_inline, which does not call it)
test_sphere_coarse_SRC = tests/unit/test_sphere_coarse.c src/geometry/sphere.c $(UNIT_FX_SRC)
# the sample boxes by which a flat scene's eye rays skip spheres, against
# the exact test on every sample of random views
test_eye_box_SRC = tests/unit/test_eye_box.c src/geometry/camera.c src/geometry/sphere.c $(UNIT_FX_SRC) src/rt_error.c
# a filtered checker lookup inside one cell takes the point sample: the
# shortcut against the whole filter, random footprints
test_footprint_SRC = tests/unit/test_footprint.c src/tracer/texture.c $(UNIT_FX_SRC) src/rt_error.c
test_footprint_INC = -Isrc/tracer

UNIT_PARTS = $(foreach t,$(UNIT_TESTS),$(if $($(t)_SRC),$(t)))
$(foreach t,$(UNIT_PARTS),$(eval build/asan/$(t): $($(t)_SRC)))
$(UNIT_PARTS:%=build/asan/%): build/asan/%: $(CORE_H) tests/lib/testlib.h Makefile
	@mkdir -p $(@D)
	$(show) CC $@
	$(Q)$(CC) $(WARN) $(asan_CFLAGS) $(asan_LDFLAGS) $($*_FLAGS) -Iinclude -Isrc $($*_INC) -Itests/lib -o $@ $($*_SRC) -lm

# ---- make install --------------------------------------------------------
#
# What `cmake --install` installs from CMakeLists.txt, file for file:
#   $(bindir)/rt              build/host/rt (every backend, HOST_CAPS)
#   $(bindir)/rt-scenec       the scene compiler for the installed library
#   $(libdir)/librt_core.a    the core, fixed backend, rt_config.h's defaults
#   $(includedir)/rt/         the public headers (include/)
#   $(includedir)/rt/internal/  the core's internal headers (src/'s *.h),
#                             which the tables rt-scenec writes include
#   $(libdir)/cmake/rt/       find_package(rt CONFIG): rt::core, rt_add_scene
# (tests/host/install-tests.sh checks that both lay out the same files).
PREFIX     ?= /usr/local
bindir     ?= $(PREFIX)/bin
libdir     ?= $(PREFIX)/lib
includedir ?= $(PREFIX)/include
INSTALL    ?= install

# The library as CMake's rt_core (Release): the core with -ffreestanding,
# default capacities, fixed point.
build/lib/core/%.o: src/%.c $(CORE_H) Makefile
	@mkdir -p $(@D)
	$(show) CC $@
	$(Q)$(CC) $(WARN) -ffreestanding -O2 -Iinclude -Isrc -c $< -o $@

build/lib/librt_core.a: $(patsubst src/%.c,build/lib/core/%.o,$(CORE_SRC))
	@rm -f $@
	$(show) AR $@
	$(Q)$(AR) rcs $@ $^

# The scene compiler for that library (the same configuration, so its
# tables link with it), as CMakeLists.txt's rt-scenec.
build/lib/rt-scenec: tools/scenec.c app/rt/host_io.c $(CORE_SRC) $(CORE_H) $(wildcard app/rt/*.h) Makefile
	@mkdir -p $(@D)
	$(show) CC $@
	$(Q)$(CC) $(WARN) -D_POSIX_C_SOURCE=200809L -O2 -ffp-contract=off -Iinclude -Isrc -Iapp/rt -o $@ \
	    tools/scenec.c app/rt/host_io.c $(CORE_SRC) -lm

INTERNAL_H    = $(wildcard src/*.h src/*/*.h)
INTERNAL_DIRS = $(sort $(patsubst src/%/,%,$(filter-out src/,$(dir $(INTERNAL_H)))))

install: build/host/rt build/lib/rt-scenec build/lib/librt_core.a
	sh cmake/make-package.sh build/lib/cmake-rt "$(PREFIX)" "$(bindir)" "$(libdir)" "$(includedir)" \
	    $$(echo __SIZEOF_POINTER__ | $(CC) -E -P - | tr -d ' ')
	$(INSTALL) -d "$(DESTDIR)$(bindir)" "$(DESTDIR)$(libdir)/cmake/rt" "$(DESTDIR)$(includedir)/rt" \
	    $(foreach d,$(INTERNAL_DIRS),"$(DESTDIR)$(includedir)/rt/internal/$(d)")
	$(INSTALL) -m 755 build/host/rt build/lib/rt-scenec "$(DESTDIR)$(bindir)"
	$(INSTALL) -m 644 build/lib/librt_core.a "$(DESTDIR)$(libdir)"
	$(INSTALL) -m 644 $(wildcard include/*.h) "$(DESTDIR)$(includedir)/rt"
	$(INSTALL) -m 644 $(wildcard src/*.h) "$(DESTDIR)$(includedir)/rt/internal"
	for d in $(INTERNAL_DIRS); do $(INSTALL) -m 644 src/$$d/*.h "$(DESTDIR)$(includedir)/rt/internal/$$d" || exit 1; done
	$(INSTALL) -m 644 build/lib/cmake-rt/*.cmake "$(DESTDIR)$(libdir)/cmake/rt"

# removes what install put there (the same variables)
uninstall:
	rm -f "$(DESTDIR)$(bindir)/rt" "$(DESTDIR)$(bindir)/rt-scenec" "$(DESTDIR)$(libdir)/librt_core.a" \
	    $(patsubst include/%,"$(DESTDIR)$(includedir)/rt/%",$(wildcard include/*.h)) \
	    $(patsubst src/%,"$(DESTDIR)$(includedir)/rt/internal/%",$(INTERNAL_H)) \
	    "$(DESTDIR)$(libdir)/cmake/rt/"rtConfig*.cmake "$(DESTDIR)$(libdir)/cmake/rt/"rtTargets*.cmake \
	    "$(DESTDIR)$(libdir)/cmake/rt/rt_add_scene.cmake"
	-rmdir $(foreach d,$(INTERNAL_DIRS),"$(DESTDIR)$(includedir)/rt/internal/$(d)") \
	    "$(DESTDIR)$(includedir)/rt/internal" "$(DESTDIR)$(includedir)/rt" "$(DESTDIR)$(libdir)/cmake/rt" 2>/dev/null

NAME := $(basename $(notdir $(SCENE)))

# (named as make run's references: firmware.mk's REF_TAGS; the double
# image is make run's reference at one sample in rgb888)
HOST_RUN_FIXED = $(OUT_DIR)/$(NAME)-host$(REF_TAGS).png
HOST_RUN_DOUBLE = $(OUT_DIR)/$(NAME)-double$(REF_TAGS)-aa0-rgb888.png
host-run: deps-host
	$(Q)$(MAKE) build/host/rt
	@mkdir -p $(OUT_DIR)
	build/host/rt $(SCENE) -o $(HOST_RUN_FIXED) --fixed --depth $(DEPTH) --size $(SIZE) --stats
	build/host/rt $(SCENE) -o $(HOST_RUN_DOUBLE) --double --depth $(DEPTH) --size $(SIZE) --quiet
	@printf 'fixed vs the exact double reference: '
	@build/host/rt compare $(HOST_RUN_FIXED) $(HOST_RUN_DOUBLE)

include app/firmware/firmware.mk

# deps: everything the tests and benchmarks use (make test, bench,
# stress, fuzz); deps-board: only what rendering on BOARD needs (make run,
# profile): the host build and the board's BOARD_PACKAGES (python3
# too for make profile); deps-image: what building BOARD's image needs
# (make image, uf2): the same but its emulator (no QEMU, no npm ci of the
# Pico's rp2040js; Node.js stays, for uf2.mjs); deps-host: the host build
# (make host-run). Each names the command it installs for in its messages
# (tools/ensure-deps.sh).
DEPS_FOR = make $(or $(firstword $(filter-out deps deps-board deps-image deps-host,$(MAKECMDGOALS))),$(1))
deps:
	@ENSURE_DEPS_FOR='$(call DEPS_FOR,test)' sh tools/ensure-deps.sh test
deps-host:
	@ENSURE_DEPS_FOR='$(call DEPS_FOR,host-run)' sh tools/ensure-deps.sh host
deps-board:
	@ENSURE_DEPS_FOR='$(call DEPS_FOR,run) (BOARD=$(BOARD))' sh tools/ensure-deps.sh run $(BOARD_PACKAGES) \
	    $(if $(filter profile,$(MAKECMDGOALS)),python3)
deps-image:
	@ENSURE_DEPS_FOR='$(call DEPS_FOR,image) (BOARD=$(BOARD))' ENSURE_DEPS_EMULATOR=0 sh tools/ensure-deps.sh run \
	    $(filter-out qemu-system-%,$(BOARD_PACKAGES))

# make bench: every step below, in this order; make bench-STEP runs one and
# rewrites its result file, bench/STEP.md (with .csv and .svg where it has
# them), then records the file's freshness counts (bench/freshness.py: the
# small runs make test measures again to tell a stale file).
BENCH_STEPS = results threads bvh prims lib-size profile specialise pico-xip pico-frames \
              boards cores aa filter scenes time
bench: deps
	$(MAKE) -j2 build/host/rt $(foreach c,$(CONFIGS),build/cfg-$(c)/rt)
	@set -e; for s in $(BENCH_STEPS); do $(MAKE) --no-print-directory bench-$$s; echo; done

# Run time against error over the numeric configurations (bench/results.md,
# results.csv, plot.svg).
bench-results: deps
	$(MAKE) -j2 build/host/rt $(foreach c,$(CONFIGS),build/cfg-$(c)/rt)
	python3 bench/run_bench.py --board $(BOARD)
	python3 bench/freshness.py --write bench/results.md
bench-threads: deps build/host/rt
	python3 bench/threads_bench.py
	python3 bench/freshness.py --write bench/threads.md
bench-bvh: deps
	@BOARD=$(BOARD) sh bench/keep.sh bench/bvh.md "BVH and pruning" sh bench/bvh-bench.sh
	python3 bench/freshness.py --write bench/bvh.md
bench-prims: deps
	@sh bench/keep.sh bench/prims.md "One intersection test per primitive on the board" sh bench/prims-bench.sh
	python3 bench/freshness.py --write bench/prims.md
bench-lib-size: deps
	@sh bench/keep.sh bench/lib-size.md "The core's footprint as a library" sh bench/lib-size.sh
	python3 bench/freshness.py --write bench/lib-size.md
bench-profile: deps
	@sh bench/keep.sh bench/profile.md "Where balls-2's instructions go on mps2-an385 (fixed, 64x64)" \
	    $(MAKE) -s profile BOARD=mps2-an385 BACKEND=fixed SCENE=scenes/spd/balls-2.nff SIZE=64x64 DEPTH=5 AA=0
	python3 bench/freshness.py --write bench/profile.md
bench-specialise: deps
	@sh bench/keep.sh bench/specialise.md "Firmware built for its scene (SPECIALISE=1) against the generic firmware" \
	    sh bench/specialise-bench.sh
	python3 bench/freshness.py --write bench/specialise.md
bench-pico-xip: deps
	@sh bench/keep.sh bench/pico-xip.md "The Pico's flash reads in the render, through a model of the XIP cache" \
	    sh bench/pico-xip.sh
	python3 bench/freshness.py --write bench/pico-xip.md
bench-pico-frames: deps
	@sh bench/keep.sh bench/pico-frames.md \
	    "The Pico's frame at 320x240 on one core and two, scanline order and progressive display" sh bench/pico-frames.sh
	python3 bench/freshness.py --write bench/pico-frames.md
bench-boards: deps
	python3 bench/boards_bench.py
	python3 bench/freshness.py --write bench/boards.md
bench-cores: deps
	python3 bench/cores_bench.py
	python3 bench/freshness.py --write bench/cores.md
bench-aa: deps
	python3 bench/aa_bench.py
	python3 bench/freshness.py --write bench/aa.md
bench-filter: deps
	python3 bench/filter_bench.py
	python3 bench/freshness.py --write bench/filter.md
bench-scenes: deps
	python3 bench/scenes_bench.py
	python3 bench/freshness.py --write bench/scenes.md
# after bench-scenes: its one-sample rows are bench/scenes.csv's
bench-time: deps
	python3 bench/time_bench.py
	python3 bench/freshness.py --write bench/time.md

# The README's and docs' pictures (docs/*.png but demos.png and oled.png).
pictures: build/host/rt
	sh bench/pictures.sh

bench-quick: deps
	$(MAKE) -j2 build/host/rt build/cfg-q20/rt build/cfg-q16/rt
	python3 bench/run_bench.py --quick --board $(BOARD)

FUZZERS = build/fuzz/fuzz_nff build/fuzz/fuzz_nff_double build/fuzz/fuzz_nff_float build/fuzz/fuzz_readers \
          build/fuzz/fuzz_receive build/fuzz/fuzz_scenec build/fuzz/fuzz_scenec_float
TESTS = build/host/rt $(UNIT_TESTS:%=build/asan/%) build/asan/rt \
        build/stress/rt build/stress/test_rayfuzz build/tsan/rt $(CONFIGS:%=build/cfg-%/rt) build/scenec/rt-scenec \
        build/scenec-float/rt-scenec build/scenec-double/rt-scenec build/lib/librt_core.a build/lib/rt-scenec $(FUZZERS)

test: deps
	$(Q)$(MAKE) -j2 $(TESTS)
	@FUZZ_SMOKE=$(FUZZ_SMOKE) python3 tests/run-all.py build/asan

# Fuzzing (clang's libFuzzer) under ASan and UBSan:
#   fuzz_nff         the reader and a tiny render, fixed build, default capacities
#   fuzz_nff_double  the same, double build, host capacities (what rt runs)
#   fuzz_nff_float   the same, float build, host capacities
#   fuzz_readers     the fixed, float and double readers side by side: one
#                    verdict and one message for every input
#   fuzz_scenec      the scene compiler: reader (board capacities) and emitters
#   fuzz_scenec_float  the same for the float tables
#   fuzz_receive     rt receive's UART stream decoder
# Seeds: tests/fuzz/corpus (NFF), tests/fuzz/corpus-receive (streams); new
# inputs go to build/fuzz/corpus-NAME. make test runs FUZZ_SMOKE seconds
# of each (tests/fuzz/fuzz-smoke.sh); make fuzz FUZZER=NAME runs one longer.
FUZZ_SECONDS ?= 300
FUZZ_SMOKE ?= 15
FUZZER ?= fuzz_nff
FUZZ_FLAGS = -std=c11 -Wall -Wextra -Werror -g -O1 -fsanitize=address,undefined -fno-sanitize-recover=undefined
build/fuzz/fuzz_nff: tests/fuzz/fuzz_nff.c $(CORE_SRC) $(CORE_H) Makefile
	@mkdir -p $(@D)
	$(show) CC $@
	$(Q)clang $(FUZZ_FLAGS) -fsanitize=fuzzer -Iinclude -Isrc -o $@ tests/fuzz/fuzz_nff.c $(CORE_SRC)

# $(1) backend id, $(2) its flags: one build of the core for the
# differential harness, instrumented, exporting only rt_backend_<id>
define fuzz_core_rule
build/fuzz/core-$(1).o: $(CORE_SRC) $(CORE_H) app/rt/backend.c app/rt/backend.h Makefile
	@rm -rf build/fuzz/$(1) && mkdir -p build/fuzz/$(1)
	$(show) CC $$@
	$(Q)cd build/fuzz/$(1) && clang $(FUZZ_FLAGS) -fsanitize=fuzzer-no-link $(HOST_CAPS) $(2) -DBACKEND_ID=$(1) \
	    $(addprefix -I$(CURDIR)/,include src app/rt) -c $(addprefix $(CURDIR)/,$(CORE_SRC) app/rt/backend.c)
	$(Q)$(LD) -r -o $$@.tmp build/fuzz/$(1)/*.o
	$(Q)$(OBJCOPY) -G rt_backend_$(1) $$@.tmp $$@
	@rm -f $$@.tmp
endef
$(eval $(call fuzz_core_rule,fixed,))
$(eval $(call fuzz_core_rule,float,$(BACKEND_FLAGS_float)))
$(eval $(call fuzz_core_rule,double,$(BACKEND_FLAGS_double)))

# fuzz_nff_double and fuzz_nff_float link the core objects fuzz_readers is
# built from (the same flags: FUZZ_FLAGS, HOST_CAPS, the backend's), so the
# core is compiled once per backend for both
FUZZ_CORE_OBJS = $(addprefix build/fuzz/$(1)/,$(notdir $(CORE_SRC:.c=.o)))
build/fuzz/fuzz_nff_double: tests/fuzz/fuzz_nff.c build/fuzz/core-double.o
	$(show) CC $@
	$(Q)clang $(FUZZ_FLAGS) -fsanitize=fuzzer $(HOST_CAPS) $(BACKEND_FLAGS_double) -Iinclude -Isrc -o $@ tests/fuzz/fuzz_nff.c \
	    $(call FUZZ_CORE_OBJS,double)

build/fuzz/fuzz_nff_float: tests/fuzz/fuzz_nff.c build/fuzz/core-float.o
	$(show) CC $@
	$(Q)clang $(FUZZ_FLAGS) -fsanitize=fuzzer $(HOST_CAPS) $(BACKEND_FLAGS_float) -Iinclude -Isrc -o $@ tests/fuzz/fuzz_nff.c \
	    $(call FUZZ_CORE_OBJS,float)

build/fuzz/fuzz_readers: tests/fuzz/fuzz_readers.c build/fuzz/core-fixed.o build/fuzz/core-float.o build/fuzz/core-double.o
	$(show) CC $@
	$(Q)clang $(FUZZ_FLAGS) -fsanitize=fuzzer $(HOST_CAPS) $(HOST_INC) -o $@ $^ -lm

# $(1) name, $(2) backend flags: the scene compiler with the firmware's
# capacities, for the fixed tables and for the float ones (hex floats)
define fuzz_scenec_rule
build/fuzz/$(1): tests/fuzz/fuzz_scenec.c tools/scenec.c app/rt/host_io.c \
                        $(wildcard app/rt/*.h) $(CORE_SRC) $(CORE_H) Makefile
	@mkdir -p $$(@D)
	$(show) CC $@
	$(Q)clang $(FUZZ_FLAGS) -fsanitize=fuzzer -D_POSIX_C_SOURCE=200809L -ffp-contract=off $(BOARD_CAPS) $(2) -Iinclude -Isrc \
	    -Iapp/rt -o $$@ tests/fuzz/fuzz_scenec.c app/rt/host_io.c $(CORE_SRC) -lm
endef
$(eval $(call fuzz_scenec_rule,fuzz_scenec,))
$(eval $(call fuzz_scenec_rule,fuzz_scenec_float,-DRT_BACKEND_FLOAT=1))

build/fuzz/fuzz_receive: tests/fuzz/fuzz_receive.c app/rt/uart_stream.c app/rt/uart_stream.h \
                         app/rt/image.h include/rt_fb.h Makefile
	@mkdir -p $(@D)
	$(show) CC $@
	$(Q)clang $(FUZZ_FLAGS) -fsanitize=fuzzer -D_POSIX_C_SOURCE=200809L -Iinclude -Isrc -Iapp/rt -o $@ \
	    tests/fuzz/fuzz_receive.c app/rt/uart_stream.c -lz

fuzz: deps build/fuzz/$(FUZZER)
	@mkdir -p build/fuzz/corpus-$(FUZZER)
	build/fuzz/$(FUZZER) build/fuzz/corpus-$(FUZZER) $(if $(filter fuzz_receive,$(FUZZER)),tests/fuzz/corpus-receive,tests/fuzz/corpus) \
	    -max_total_time=$(FUZZ_SECONDS) -timeout=10 -max_len=4096 -print_final_stats=1

fuzz-coverage: deps
	sh tests/fuzz/fuzz-coverage.sh

# Numerical stress suite (tests/host/stress.py); make test runs its quick subset.
stress: deps
	$(MAKE) build/stress/rt build/stress/test_rayfuzz
	python3 tests/host/stress.py

clean:
	rm -rf build out
