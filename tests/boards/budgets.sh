# budgets.sh - the firmware's footprint budgets, stated once (sourced by
# tests/boards/board-tests.sh and board-aa-tests.sh; docs/testing.md,
# "Footprint budgets", gives the same reasons).
#
# Each is a share of the smallest board the renderer targets, the BBC
# micro:bit (nRF51822: 256 KiB of flash, 16 KiB of RAM; platform/microbit/
# link.ld, docs/board-notes.md), so that the rest stays the user's: their
# application, display and radio stacks, the scene's tables and the band
# buffer they size. They are measured on the default board's fixed-point
# firmware (mps2-an385, Cortex-M3) with the default scene.

# Code (.vectors, .text, .ARM.exidx; the scene tables are data): an eighth
# of the flash, 32 KiB, for any scene's firmware, built for its scene or
# generic. A firmware that links what its scene does not use trips it:
# with every feature linked it is about 36 KiB (the pruning check of
# tests/boards/board-tests.sh prints it, "pruned == unpruned image").
FW_CODE_MAX=32768
# code_of ELF: its code, as the budget counts it
code_of() { arm-none-eabi-size -A "$1" | awk '$1 == ".text" || $1 == ".vectors" || $1 == ".ARM.exidx" { c += $2 } END { print c }'; }

# Static RAM (.data and .bss, the band buffer excluded: its size is the
# user's choice of BAND_LINES and width): a quarter of the RAM, 4 KiB.
FW_RAM_MAX=4096

# Stack high-water of a render, anti-aliased or not: 3 KiB, three sixteenths
# of the RAM. The boards link a 4 KiB stack; the last quarter of it stays
# for the calls below the render and the interrupts of the user's firmware.
FW_STACK_MAX=3072
