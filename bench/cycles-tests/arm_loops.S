/* arm_loops.S - hand-counted loops for bench/cycles.py's self-test
 * (bench/cycles_selftest.py). One source for every Cortex-M board:
 *   RAM_TOP   initial stack pointer
 *   MMIO_ADDR a readable peripheral register (QEMU re-translates a block
 *             that touches I/O under -icount: the count must stay exact)
 *   HAVE_V7M  Cortex-M3/M4 (Thumb-2: CBZ, long multiplies, divides)
 *   HAVE_FPU  Cortex-M4F
 * Each function below is measured with --from-symbol; the self-test
 * knows how many instructions of each class it executes. */
    .syntax unified
    .thumb
    .section .vectors, "a"
    .word RAM_TOP
    .word reset + 1

    .text
    .thumb_func
    .global reset
reset:
    ldr r0, =N_LOOP
    bl loop2                    /* 2 * N_LOOP + 1 instructions */
    ldr r0, =N_LOOP
    bl mmio_loop                /* 3 * N_LOOP + 1 */
    ldr r0, =N_LOOP
    bl nested                   /* calls leaf N_LOOP times */
    ldr r0, =N_LOOP
    bl mix
#ifdef HAVE_FPU
    ldr r0, =N_LOOP
    bl fpu_mix
#endif
    /* semihosting SYS_EXIT, ADP_Stopped_ApplicationExit */
    movs r0, #0x18
    ldr r1, =0x20026
    bkpt 0xab
1:  b 1b

/* 1: subs; bne 1b -- 2 instructions per iteration, then bx lr */
    .thumb_func
    .global loop2
loop2:
1:  subs r0, #1
    bne 1b
    bx lr

/* a peripheral read per iteration */
    .thumb_func
    .global mmio_loop
mmio_loop:
    ldr r2, =MMIO_ADDR
1:  ldr r1, [r2]
    subs r0, #1
    bne 1b
    bx lr

/* push {r4, lr}; loop: bl leaf; subs; bne; pop {r4, pc}.  leaf: adds; bx lr */
    .thumb_func
    .global nested
nested:
    push {r4, lr}
    mov r4, r0
1:  bl leaf
    subs r4, #1
    bne 1b
    pop {r4, pc}

    .thumb_func
    .global leaf
leaf:
    adds r1, #1
    bx lr

/* one of each class per iteration (the self-test knows the mix):
 *   ldr, str, muls (+ on v7-M: umull, smlal, udiv), ldm/stm of 3 registers */
    .thumb_func
    .global mix
mix:
    push {r4-r7, lr}
    ldr r7, =buf
    movs r1, #3
    movs r2, #7
1:  ldr r3, [r7]
    str r3, [r7, #4]
    muls r3, r2
    ldm r7!, {r4-r6}
    subs r7, #12
    stm r7!, {r4-r6}
    subs r7, #12
#ifdef HAVE_V7M
    umull r4, r5, r2, r3
    smlal r4, r5, r2, r3
    udiv r4, r3, r2
#endif
    subs r0, #1
    bne 1b
    pop {r4-r7, pc}

#ifdef HAVE_FPU
    .fpu fpv4-sp-d16
    .thumb_func
    .global fpu_mix
fpu_mix:
    ldr r1, =0xE000ED88          /* CPACR: enable CP10 and CP11 */
    ldr r2, [r1]
    orr r2, r2, #(0xF << 20)
    str r2, [r1]
    dsb
    isb
    ldr r3, =buf
    vmov.f32 s0, #1.0
    vmov.f32 s1, #2.0
1:  vldr s2, [r3]
    vadd.f32 s2, s2, s0
    vmul.f32 s3, s2, s1
    vdiv.f32 s4, s3, s1
    vsqrt.f32 s5, s4
    vstr s5, [r3]
    subs r0, #1
    bne 1b
    bx lr
#endif

    .ltorg
    .bss
    .align 2
buf: .space 32
