/* rv_loops.S - hand-counted loops for bench/cycles.py's self-test on the
 * SiFive E31 (rv32imac) of QEMU's sifive_e: code in flash at 0x20400000,
 * data in the DTIM at 0x80000000. See arm_loops.S. */
    .section .text.start, "ax"
    .global _start
_start:
    li sp, 0x80004000
    li a0, N_LOOP
    call loop2                  /* 2 * N_LOOP + 1 */
    li a0, N_LOOP
    call mmio_loop              /* 3 * N_LOOP + 1 */
    li a0, N_LOOP
    call nested
    li a0, N_LOOP
    call mix
    /* semihosting SYS_EXIT, ADP_Stopped_ApplicationExit */
    li a0, 0x18
    li a1, 0x20026
    .option push
    .option norvc
    .balign 16
    slli zero, zero, 0x1f
    ebreak
    srai zero, zero, 7
    .option pop
1:  j 1b

    .text
    .global loop2
loop2:
1:  addi a0, a0, -1
    bnez a0, 1b
    ret

    .global mmio_loop
mmio_loop:
    li a2, 0x0200bff8            /* CLINT mtime */
1:  lw a1, 0(a2)
    addi a0, a0, -1
    bnez a0, 1b
    ret

    .global nested
nested:
    addi sp, sp, -16
    sw ra, 12(sp)
    sw s0, 8(sp)
    mv s0, a0
1:  call leaf
    addi s0, s0, -1
    bnez s0, 1b
    lw ra, 12(sp)
    lw s0, 8(sp)
    addi sp, sp, 16
    ret

    .global leaf
leaf:
    addi a1, a1, 1
    ret

/* lw then a dependent use (load-use stall), sw, mul then a dependent use
 * (multiplier latency), divu, one of each per iteration */
    .global mix
mix:
    la a5, buf
    li a2, 7
1:  lw a3, 0(a5)
    addi a3, a3, 1
    sw a3, 4(a5)
    mul a4, a3, a2
    add a4, a4, a2
    divu a4, a4, a2
    addi a0, a0, -1
    bnez a0, 1b
    ret

    .bss
    .align 2
buf: .space 32
