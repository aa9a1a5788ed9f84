/*
 * pico_fault.S - images that a real RP2040 would not run, for
 * tests/boards/board-pico-tests.sh: run.mjs must fail each with its reason.
 * Built with -DFAULT_<name>; the image links after our boot2 (its .boot2
 * section at 0x10000000), its vector table at 0x10000100.
 *   FAULT_RESET      UART0 written while RESETS holds it in reset
 *   FAULT_BKPT       bkpt 0xab (semihosting): a HardFault with no debugger
 *   FAULT_UNMAPPED   a read of 0x40068000, where nothing answers
 *   FAULT_TIMER      the TIMER out of reset and read with the watchdog's
 *                    tick as at reset (CYCLES 0): no microseconds on the chip
 *   FAULT_BOOT2      (at 0x20041f00, as a boot2 of its own) straight to the
 *                    image without setting the SSI up for execute-in-place
 */
    .syntax unified
    .cpu cortex-m0plus
    .thumb
    .text
#ifdef FAULT_BOOT2
    .global start
    .thumb_func
start:
    ldr r0, =0x10000100
    ldr r1, [r0]
    msr msp, r1
    ldr r2, [r0, #4]
    bx r2
#else
    .word 0x20040000
    .word start + 1
    .global start
    .thumb_func
start:
#if defined(FAULT_RESET)
    ldr r0, =0x40034030
    movs r1, #1
    str r1, [r0]
#elif defined(FAULT_BKPT)
    bkpt 0xab
#elif defined(FAULT_UNMAPPED)
    ldr r0, =0x40068000
    ldr r1, [r0]
#elif defined(FAULT_TIMER)
    ldr r0, =0x4000f000 /* RESETS_RESET's clear alias */
    ldr r1, =(1 << 21)  /* TIMER */
    str r1, [r0]
    ldr r0, =0x40054028 /* TIMERAWL */
    ldr r1, [r0]
#endif
1:  b 1b
#endif
    .ltorg
