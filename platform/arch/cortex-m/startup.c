/*
 * startup.c - vector table and reset for every Cortex-M port (M0, M3,
 * M4F): the architecture's half of the port contract (port.h).
 *
 * Reset enables the FPU on a hard-float build, in assembly before any C
 * runs (GCC may hoist a VFP load to the top of a C function), copies
 * .data from flash, zeroes .bss and calls main(). The vector table is
 * the architecture's 16 system entries; this firmware uses no interrupts.
 */
#include <stdint.h>

#include "port.h"

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_top[];
/* Each start/end pair above bounds one region of the linker script: the
 * loops below compare pointers within it, which cppcheck cannot know. */

int main(void);
void Reset_Handler(void);
void Fault_Handler(void);
void reset_c(void) __attribute__((noreturn, used));

__attribute__((section(".vectors"), used))
static void (*const vector_table[16])(void) = {
    (void (*)(void))(uintptr_t)__stack_top, /* initial SP */
    Reset_Handler,
    Fault_Handler, /* NMI */
    Fault_Handler, /* HardFault */
    Fault_Handler, /* MemManage */
    Fault_Handler, /* BusFault */
    Fault_Handler, /* UsageFault */
    0, 0, 0, 0,
    Fault_Handler, /* SVCall */
    Fault_Handler, /* DebugMon */
    0,
    Fault_Handler, /* PendSV */
    Fault_Handler, /* SysTick */
};

__attribute__((naked)) void Reset_Handler(void)
{
    __asm__ volatile(
#ifdef __ARM_FP
        /* CPACR (0xE000ED88): full access to CP10 and CP11, the FPU */
        "ldr r0, =0xE000ED88\n"
        "ldr r1, [r0]\n"
        "ldr r2, =0x00F00000\n"
        "orr r1, r1, r2\n"
        "str r1, [r0]\n"
        "dsb\n"
        "isb\n"
#endif
        "ldr r0, =reset_c\n" /* bx: a plain b may not reach it on the M0 */
        "bx r0\n");
}

void reset_c(void)
{
    /* volatile: stops the compiler turning the loops into memcpy/memset
     * calls before memory is set up */
    volatile uint32_t *dst = __data_start;
    const uint32_t *src = __data_load;
    /* cppcheck-suppress comparePointers ; one region: .data */
    while (dst < __data_end)
        *dst++ = *src++;
    /* cppcheck-suppress comparePointers ; one region: .bss */
    for (dst = __bss_start; dst < __bss_end; dst++)
        *dst = 0;
    port_exit(main());
}

void Fault_Handler(void)
{
    report_text("fault: abort");
    port_exit(4);
}
