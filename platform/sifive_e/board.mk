# board.mk - SiFive HiFive1 (FE310, QEMU's sifive_e): an RV32IMAC core,
# 16 KiB of RAM (DTIM), the program executed in place from SPI flash.
# The port contract and the variables are in app/firmware/firmware.mk.
# the board in a phrase, for make run's report (its clock: BOARD_CLOCK_HZ)
BOARD_TITLE    := SiFive HiFive1 (FE310) with an RV32IMAC core, no FPU and 16 KiB of RAM
BOARD_ARCH     := riscv
BOARD_CROSS    := riscv64-unknown-elf-
# -misa-spec=2.2: the FE310's ISA, where the CSR instructions (csrr, csrw)
# belong to the base set. The newer spec's spelling, -march=rv32imac_zicsr,
# makes GCC 12's driver miss the rv32imac/ilp32 multilib and link the
# 64-bit default libgcc; this one selects rv32imac/ilp32 and emits the same
# code.
BOARD_CPU      := -march=rv32imac -misa-spec=2.2 -mabi=ilp32
BOARD_QEMU     := qemu-system-riscv32 -M sifive_e
BOARD_PACKAGES := gcc-riscv64-unknown-elf qemu-system-misc
# The FE310's rated clock (the firmware leaves the PLL as reset left it;
# the figure only scales the render time make run prints).
BOARD_CLOCK_HZ ?= 320000000
# fixed only: the floating-point builds parse the NFF text at boot and
# want a 64 KiB stack, four times this board's RAM
BOARD_BACKENDS := fixed
BOARD_SRC      := platform/sifive_e/board.c
BOARD_LD       := platform/sifive_e/link.ld

# 16 KiB of RAM: make run renders one sample a pixel (AA=1 fits at 128
# pixels wide: two rows of 257 cell corners)
BOARD_RUN_AA   := 0
