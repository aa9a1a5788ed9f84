# rt.mk - the core for a Makefile project (GNU make):
#
#   RT_DIR := path/to/rt                # optional: defaults to this file's folder
#   RT_BACKEND := fixed                 # optional: fixed (default), float or double
#   RT_CONFIG_FILE := my_rt_conf.h      # optional: user configuration header
#   include $(RT_DIR)/rt.mk
#
#   SRC    += $(RT_SRC)                 # compile with $(RT_CFLAGS)
#   CFLAGS += $(addprefix -I,$(RT_INC)) $(RT_DEFS)
#
# Defines:
#   RT_SRC          the core's C files (freestanding: compile them with
#                   -ffreestanding, $(RT_CFLAGS))
#   RT_INC          the public headers' folder (include/: rt.h and the rt_*.h it
#                   includes)
#   RT_DEFS         -D flags of the configuration: give them to every file
#                   that includes rt.h, not only the core
#   RT_CFLAGS       what the core's files need: -std=c11 -ffreestanding,
#                   include/ and src/ (the internal headers), $(RT_DEFS);
#                   with RT_BACKEND float also -ffp-contract=off
#                   -fno-math-errno (rt --float's arithmetic: no fused
#                   multiply-adds; sqrtf inline), as CMake's rt_core has
#                   them (the CPU's flags, -mcpu, -mfpu, -mfloat-abi, are
#                   the project's CFLAGS)
#   RT_SCENEC_SRC   the scene compiler's sources (a HOST program: build it
#                   with the host cc, $(RT_SCENEC_CFLAGS), the same
#                   capacities as the target and $(RT_SCENEC_LDLIBS)); its
#                   tables are in RT_BACKEND's format; then
#                     rt-scenec SCENE.nff -o scene_data.c --header scene_data.h
#                   and, to prune, compile the core with
#                     -DSCENE_PRUNE=1 -include scene_data.h
#   RT_SCENEC_CFLAGS
#   RT_SCENEC_LDLIBS  -lm (the float and double readers call tan, sin, cos)
#
# examples/make/Makefile is a whole project on these (docs/embedding.md,
# "A Make project"). rt.mk compiles the core from this source tree; the
# installed library (make install) needs no rt.mk: -I PREFIX/include/rt
# and PREFIX/lib/librt_core.a, and -I PREFIX/include/rt/internal for
# rt-scenec's tables.
ifeq ($(RT_DIR),)
RT_DIR := $(patsubst %/,%,$(dir $(lastword $(MAKEFILE_LIST))))
endif
RT_BACKEND ?= fixed
RT_CONFIG_FILE ?=

RT_SRC := $(wildcard $(RT_DIR)/src/*.c $(RT_DIR)/src/*/*.c)
RT_INC := $(RT_DIR)/include
RT_DEFS := $(if $(filter float,$(RT_BACKEND)),-DRT_BACKEND_FLOAT=1) \
           $(if $(filter double,$(RT_BACKEND)),-DRT_BACKEND_DOUBLE=1) \
           $(if $(RT_CONFIG_FILE),-DRT_CONFIG_FILE='"$(abspath $(RT_CONFIG_FILE))"')
RT_CFLAGS := -std=c11 -ffreestanding $(addprefix -I,$(RT_INC)) -I$(RT_DIR)/src $(RT_DEFS) \
             $(if $(filter float,$(RT_BACKEND)),-ffp-contract=off -fno-math-errno)

RT_SCENEC_SRC := $(RT_DIR)/tools/scenec.c $(RT_DIR)/app/rt/host_io.c $(RT_SRC)
RT_SCENEC_CFLAGS := -std=c11 -O2 -ffp-contract=off -D_POSIX_C_SOURCE=200809L -I$(RT_DIR)/include -I$(RT_DIR)/src \
                    -I$(RT_DIR)/app/rt $(RT_DEFS)
RT_SCENEC_LDLIBS := -lm

ifeq ($(filter fixed float double,$(RT_BACKEND)),)
$(error rt.mk: RT_BACKEND must be fixed, float or double, not '$(RT_BACKEND)')
endif
