/*
 * start.S - reset and trap entry for every RISC-V port (RV32, machine
 * mode): the architecture's half of the port contract (port.h).
 *
 * Reset sets gp (for the linker's gp-relative relaxation; link.ld
 * defines __global_pointer$) and sp, points mtvec at trap_entry, copies
 * .data from flash, zeroes .bss, calls main() and passes its result to
 * port_exit(). Interrupts stay off (mstatus.MIE is 0 after reset); any
 * trap is a fault: trap_entry takes a fresh stack and calls trap_c
 * (trap.c), which reports it and exits with status 4.
 */
    .section .text.start, "ax"
    .globl _start
    .type _start, @function
_start:
    .option push
    .option norelax /* else gp would be set relative to itself */
    la gp, __global_pointer$
    .option pop
    la sp, __stack_top
    la t0, trap_entry
    csrw mtvec, t0
    /* .data: word by word (sections.ld aligns its bounds to 4) */
    la t0, __data_load
    la t1, __data_start
    la t2, __data_end
1:  bgeu t1, t2, 2f
    lw t3, 0(t0)
    sw t3, 0(t1)
    addi t0, t0, 4
    addi t1, t1, 4
    j 1b
2:  la t1, __bss_start
    la t2, __bss_end
3:  bgeu t1, t2, 4f
    sw zero, 0(t1)
    addi t1, t1, 4
    j 3b
4:  call main
    tail port_exit /* a0: main's result */
    .size _start, . - _start

    .section .text.trap_entry, "ax"
    .balign 4 /* mtvec, direct mode: the low two bits are the mode */
    .globl trap_entry
    .type trap_entry, @function
trap_entry:
    /* the trap may come from a broken sp; the run ends here anyway */
    .option push
    .option norelax
    la gp, __global_pointer$
    .option pop
    la sp, __stack_top
    tail trap_c
    .size trap_entry, . - trap_entry
