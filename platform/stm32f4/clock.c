/*
 * clock.c - the STM32F4's clock tree (clock.h), for the chip: the
 * crystal (HSE; bypass mode where a clock drives it) or the 16 MHz HSI,
 * divided to 1 MHz into the main PLL; VCO 336 MHz, SYSCLK 168 MHz (/ 2)
 * or 84 MHz (/ 4), USB 48 MHz (/ 7); flash wait states, prefetch and the
 * ART accelerator's caches before SYSCLK moves; APB1 at 42 MHz and APB2
 * at 84 MHz, their limits. Under QEMU, whose RCC reads 0, the PLL never
 * reports lock and SYSCLK stays on the HSI.
 */
#include "clock.h"

/* The PLL: its input divided to 1 MHz, times 336 to the VCO, / P for
 * SYSCLK, / 7 for USB's 48 MHz. (2 MHz would jitter less, but on the
 * F405/F407 RM0090 has long asked for N of 192 or more, and 1 MHz into
 * N = 336 is what ST's own set-up of the Discovery uses.) */
#define PLL_VCO_MHZ 336u
#define PLL_N PLL_VCO_MHZ /* from 1 MHz */
#define PLL_P (PLL_VCO_MHZ / STM32_SYSCLK_MHZ)
#define PLL_Q 7u
/* M = the input's MHz, so 1 MHz goes in */
#define PLLCFGR_OF(mhz) ((mhz) | PLL_N << 6 | (PLL_P / 2u - 1u) << 16 | PLL_Q << 24)
_Static_assert(STM32_HSE_MHZ == 0 || (STM32_HSE_MHZ >= 4 && STM32_HSE_MHZ <= 26),
               "the crystal: 4 to 26 MHz (PLLM 2..63 divides it to 1 MHz), or 0 for none");
_Static_assert(PLL_N >= 192 && PLL_N <= 432, "PLLN: 192..432 (RM0090)");
_Static_assert(PLL_P * STM32_SYSCLK_MHZ == PLL_VCO_MHZ && (PLL_P == 2 || PLL_P == 4), "SYSCLK: the VCO / 2 or / 4");
_Static_assert(PLL_VCO_MHZ / PLL_Q == 48, "USB's 48 MHz from the VCO");

/* The buses: AHB at SYSCLK; APB1 at most 42 MHz, APB2 at most 84 MHz. */
#if STM32_SYSCLK_MHZ == 168
#define APB_PRESCALERS (RCC_CFGR_PPRE1_DIV4 | RCC_CFGR_PPRE2_DIV2)
#define APB1_MHZ 42u
#define APB2_MHZ 84u
/* 168 MHz at 2.7-3.6 V: 5 wait states (RM0090, "Relation between CPU
 * clock frequency and flash memory read time") */
#define FLASH_WAIT_STATES 5u
#else
#define APB_PRESCALERS RCC_CFGR_PPRE1_DIV2
#define APB1_MHZ 42u
#define APB2_MHZ 84u
/* 84 MHz: 2 wait states on the F401, F411 and F446 (2.7-3.6 V) */
#define FLASH_WAIT_STATES 2u
#endif
_Static_assert(APB1_MHZ <= 42 && APB2_MHZ <= 84, "APB1 at most 42 MHz, APB2 at most 84 MHz");
_Static_assert(STM32_SYSCLK_MHZ / APB1_MHZ * APB1_MHZ == STM32_SYSCLK_MHZ &&
                   STM32_SYSCLK_MHZ / APB2_MHZ * APB2_MHZ == STM32_SYSCLK_MHZ,
               "APB1 and APB2 divide SYSCLK");

static const char *clock_line; /* the report's line: clocks_init() sets it */

static int wait_for(const volatile uint32_t *reg, uint32_t mask, uint32_t want)
{
    for (uint32_t n = 0; n < WAIT_POLLS; n++)
        if ((*reg & mask) == want)
            return 1;
    return 0;
}

clock_source_t clocks_init(void)
{
    uint32_t pllcfgr = PLLCFGR_OF(HSI_MHZ);
    clock_source_t source = CLOCK_PLL_HSI;
#if STM32_HSE_MHZ
    /* (HSEBYP may change only while the HSE is off: before HSEON, after) */
    if (STM32_HSE_BYPASS)
        RCC_CR |= RCC_CR_HSEBYP;
    RCC_CR |= RCC_CR_HSEON;
    if (wait_for(&RCC_CR, RCC_CR_HSERDY, RCC_CR_HSERDY)) {
        pllcfgr = PLLCFGR_OF(STM32_HSE_MHZ) | RCC_PLLCFGR_SRC_HSE;
        source = CLOCK_PLL_HSE;
    } else {
        RCC_CR &= ~RCC_CR_HSEON;
        RCC_CR &= ~RCC_CR_HSEBYP;
    }
#endif
    RCC_PLLCFGR = pllcfgr;
    RCC_CR |= RCC_CR_PLLON;
    if (!wait_for(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY)) {
        RCC_CR &= ~RCC_CR_PLLON;
        clock_line = "clock: the PLL never reported lock (RCC_CR PLLRDY), so SYSCLK stayed on the "
                     "16 MHz HSI as reset left it (expected under QEMU, whose RCC reads 0)";
        return CLOCK_HSI;
    }
    /* wait states before the clock rises; the caches and prefetch then
     * hide most of them */
    FLASH_ACR = FLASH_WAIT_STATES | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
    if ((FLASH_ACR & FLASH_ACR_LATENCY_MASK) != FLASH_WAIT_STATES) {
        RCC_CR &= ~RCC_CR_PLLON;
        clock_line = "clock: FLASH_ACR did not take the wait states, so SYSCLK stayed on the 16 MHz HSI";
        return CLOCK_HSI;
    }
    RCC_CFGR = APB_PRESCALERS; /* AHB / 1, SYSCLK still the HSI */
    RCC_CFGR = APB_PRESCALERS | RCC_CFGR_SW_PLL;
    if (!wait_for(&RCC_CFGR, RCC_CFGR_SWS_MASK, RCC_CFGR_SWS_PLL)) {
        RCC_CFGR = 0; /* back to the HSI, buses undivided */
        clock_line = "clock: SYSCLK did not switch to the PLL (RCC_CFGR SWS), so it stayed on the 16 MHz HSI";
        return CLOCK_HSI;
    }
    clock_line = source == CLOCK_PLL_HSE ? "clock: PLL from the crystal (HSE)"
                                         : "clock: PLL from the 16 MHz HSI (the crystal did not start)";
    return source;
}

uint32_t clock_sysclk_hz(clock_source_t source)
{
    return (source == CLOCK_HSI ? HSI_MHZ : STM32_SYSCLK_MHZ) * 1000000u;
}

/* (on the HSI the buses stayed undivided) */
uint32_t clock_apb_hz(clock_source_t source, unsigned bus)
{
    return (source == CLOCK_HSI ? HSI_MHZ : bus == 1 ? APB1_MHZ : APB2_MHZ) * 1000000u;
}

const char *clock_report(void) { return clock_line ? clock_line : "clock: not set up"; }
