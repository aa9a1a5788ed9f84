/*
 * systick.h - the core's SysTick timer (every Cortex-M with it: the
 * RP2040's M0+, the STM32F4's M4F), as the boards that count with it use
 * it: a 24-bit down counter on the processor clock, reloaded at its top,
 * whose interrupt (SysTick_Handler, the board's) marks each wrap.
 */
#ifndef SYSTICK_H
#define SYSTICK_H

#include <stdint.h>

#include "../../mmio.h"

#define SYST_CSR REG(0xe000e010u)
#define SYST_RVR REG(0xe000e014u)
#define SYST_CVR REG(0xe000e018u)
#define SYST_TOP 0xffffffu /* counts SYST_TOP + 1 clocks a wrap */

/* From its top, interrupting at each wrap. */
static inline void systick_start_wrapping(void)
{
    SYST_RVR = SYST_TOP;
    SYST_CVR = 0;
    SYST_CSR = 1u << 2 | 1u << 1 | 1u << 0; /* processor clock, interrupt, enable */
}

static inline void systick_stop(void) { SYST_CSR = 0; }

#endif
