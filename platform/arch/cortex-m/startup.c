/*
 * startup.c - vector table and reset for every Cortex-M port (M0, M3,
 * M4F): the architecture's half of the port contract (port.h).
 *
 * Reset enables the FPU on a hard-float build, in assembly before any C
 * runs (GCC may hoist a VFP load to the top of a C function), copies
 * what runs from RAM out of flash (the code and the scene's tables on a
 * board whose link.ld puts them there, and .data), zeroes .bss and calls
 * main(). Reset itself stays in flash (.text.start), and reaches main()
 * and port_exit() through registers: from flash they may be further away
 * than a BL reaches. The vector table is the architecture's 16 system
 * entries; a board that counts with SysTick defines SysTick_Handler, any
 * other exception is a fault.
 */
#include <stdint.h>

#include "port.h"

extern uint32_t __code_start[], __code_end[], __code_load[];
extern uint32_t __scene_start[], __scene_end[], __scene_load[];
extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_top[];
/* Each start/end pair above bounds one region of the linker script: the
 * loops below compare pointers within it, which cppcheck cannot know. */

int main(void);
void Reset_Handler(void) __attribute__((section(".text.start")));
void Fault_Handler(void);
void SysTick_Handler(void) __attribute__((weak, alias("Fault_Handler")));
void reset_c(void) __attribute__((noreturn, used, section(".text.start")));

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
    SysTick_Handler,
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

/* Words from src to [dst, end), unless they are already there (code
 * and tables that run from flash). In flash with reset, and small: it
 * runs once. volatile: stops the compiler turning the loop into a memcpy
 * call before memory is set up. */
__attribute__((section(".text.start"), noinline, optimize("Os"))) static void
copy_words(volatile uint32_t *dst, const uint32_t *end, const uint32_t *src)
{
    if (dst == src)
        return;
    /* cppcheck-suppress comparePointers ; one region of the linker script */
    while (dst < end)
        *dst++ = *src++;
}

__attribute__((optimize("Os"))) void reset_c(void)
{
    copy_words(__code_start, __code_end, __code_load);
    copy_words(__scene_start, __scene_end, __scene_load);
    copy_words(__data_start, __data_end, __data_load);
    /* cppcheck-suppress comparePointers ; one region: .bss */
    for (volatile uint32_t *dst = __bss_start; dst < __bss_end; dst++)
        *dst = 0;
    /* through registers: a BL from flash may not reach code in RAM */
    int (*volatile run)(void) = main;
    void (*volatile end)(int) = port_exit;
    end(run());
    for (;;)
        ;
}

void Fault_Handler(void)
{
    report_text("fault: abort");
    port_exit(4);
}
