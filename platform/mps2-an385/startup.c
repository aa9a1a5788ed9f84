/*
 * startup.c - vector table and reset handler for the Cortex-M3.
 *
 * Reset copies .data from flash, zeroes .bss and paints the stack with a
 * pattern, so the deepest stack use can be read back after a render.
 */
#include <stdint.h>

#include "board.h"

extern uint32_t __data_start[], __data_end[], __data_load[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_limit[], __stack_top[], __stack_guard_end[];
/* Each start/end pair above bounds one region of the linker script: the
 * loops below compare pointers within it, which cppcheck cannot know. */

#define STACK_PAINT 0xA5A5A5A5u

int main(void);
void Reset_Handler(void);
void Fault_Handler(void);

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

void Reset_Handler(void)
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
    /* paint up to just below this function's own frame */
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (dst = __stack_limit; dst < (volatile uint32_t *)sp - 16; dst++)
        *dst = STACK_PAINT;
    board_exit(main());
}

uint32_t stack_size(void) { return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)__stack_limit); }

uint32_t stack_high_water(void)
{
    const uint32_t *p = __stack_limit;
    /* cppcheck-suppress comparePointers ; one region: the stack */
    while (p < __stack_top && *p == STACK_PAINT)
        p++;
    return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)p);
}

int stack_guard_intact(void)
{
    /* cppcheck-suppress comparePointers ; one region: the stack's guard */
    for (const uint32_t *p = __stack_limit; p < __stack_guard_end; p++)
        if (*p != STACK_PAINT)
            return 0;
    return 1;
}

void Fault_Handler(void)
{
    static const char msg[] = "T\x0c\x00" "fault: abort";
    uart_write(msg, sizeof msg - 1);
    board_exit(4);
}
