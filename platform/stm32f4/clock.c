/*
 * clock.c - the STM32F4's clock tree (clock.h), for the chip: the
 * crystal (HSE; bypass mode where a clock drives it) or the 16 MHz HSI
 * divided to at most 2 MHz into the main PLL; VCO 336 MHz, SYSCLK
 * 168 MHz (/ 2) or 84 MHz (/ 4), USB 48 MHz (/ 7); flash wait states,
 * prefetch (not on a revision A F405/F407) and the ART accelerator's
 * caches before SYSCLK moves; APB1 at 42 MHz and APB2 at 84 MHz, their
 * limits. Under QEMU, whose RCC reads 0, the PLL never reports lock and
 * SYSCLK stays on the HSI.
 */
#include "clock.h"

/* The PLL: its input / M, times N to the VCO's 336 MHz, / P for SYSCLK,
 * / 7 for USB's 48 MHz. The input is 2 MHz where it can be (RM0090 allows
 * 1 to 2 MHz and asks for 2 to limit the PLL's jitter); two rules hold it
 * lower on some inputs:
 *  - N = 336 MHz / input must be whole, or SYSCLK, and with it the
 *    USART's baud rate and every time the report gives, would be off: M
 *    is a multiple of mhz / gcd(mhz, 336). A 25 MHz crystal thus gets
 *    M 25, 1 MHz (M 13, 1.92 MHz, would give 168.27 MHz with N 175, over
 *    the chip's most, or 167.31 MHz and USB at 47.8 MHz with N 174);
 *  - the 84 MHz image also runs on the F401 and F411, where N must be
 *    192 or more (ST's HAL asks it of the F411, other sources of the
 *    F401; RM0090 allows 50 or more on the F405/F407): there the input is
 *    at most 336 / 192 = 1.75 MHz, 1.6 MHz from 8 or 16 MHz (M 5 or 10,
 *    N 210).
 * PLL_M_OF is the least M that keeps both rules and the 2 MHz; the
 * static asserts below check every limit for the crystal and the HSI. */
#define PLL_VCO_MHZ 336u
#define PLL_P (PLL_VCO_MHZ / STM32_SYSCLK_MHZ)
#define PLL_Q 7u
#define PLL_IN_MAX_MHZ 2u
#if STM32_SYSCLK_MHZ == 168
#define PLL_N_MIN 50u /* F405/F407 (RM0090) */
#else
#define PLL_N_MIN 192u /* F401, F411 */
#endif
#define PLL_N_MAX 432u
#define CEIL_DIV(a, b) (((a) + (b) - 1u) / (b))
#define MAX(a, b) ((a) > (b) ? (a) : (b))
/* gcd(mhz, 336), from 336 = 2^4 x 3 x 7 */
#define GCD_336(mhz)                                                                                                   \
    (((mhz) % 16u == 0 ? 16u : (mhz) % 8u == 0 ? 8u : (mhz) % 4u == 0 ? 4u : (mhz) % 2u == 0 ? 2u : 1u) *             \
     ((mhz) % 3u == 0 ? 3u : 1u) * ((mhz) % 7u == 0 ? 7u : 1u))
_Static_assert(PLL_VCO_MHZ == 16u * 3u * 7u, "GCD_336 knows the VCO's factors");
#define PLL_M_STEP(mhz) ((mhz) / GCD_336(mhz))
#define PLL_M_LEAST(mhz) MAX(CEIL_DIV(mhz, PLL_IN_MAX_MHZ), CEIL_DIV((mhz) * PLL_N_MIN, PLL_VCO_MHZ))
#define PLL_M_OF(mhz) (CEIL_DIV(PLL_M_LEAST(mhz), PLL_M_STEP(mhz)) * PLL_M_STEP(mhz))
#define PLL_N_OF(mhz) (PLL_VCO_MHZ * PLL_M_OF(mhz) / (mhz))
/* M 2..63 and at most mhz (1 MHz or more in), N whole and in range */
#define PLL_FITS(mhz)                                                                                                  \
    (PLL_M_OF(mhz) >= 2u && PLL_M_OF(mhz) <= 63u && PLL_M_OF(mhz) <= (mhz) &&                                          \
     PLL_N_OF(mhz) * (mhz) == PLL_VCO_MHZ * PLL_M_OF(mhz) && PLL_N_OF(mhz) >= PLL_N_MIN && PLL_N_OF(mhz) <= PLL_N_MAX)
#define PLLCFGR_OF(mhz) (PLL_M_OF(mhz) | PLL_N_OF(mhz) << 6 | (PLL_P / 2u - 1u) << 16 | PLL_Q << 24)
/* PLLM, PLLN, PLLP, PLLSRC, PLLQ: every other bit is reserved (the F446's
 * PLLR among them) and keeps its reset value (RM0090 7.3.2: bit 29 is set) */
#define PLLCFGR_FIELDS (0x3fu | 0x1ffu << 6 | 3u << 16 | RCC_PLLCFGR_SRC_HSE | 0xfu << 24)
_Static_assert(STM32_HSE_MHZ == 0 || (STM32_HSE_MHZ >= 4 && STM32_HSE_MHZ <= 26),
               "the crystal: 4 to 26 MHz, or 0 for none");
_Static_assert(PLL_FITS(HSI_MHZ) && PLL_M_OF(HSI_MHZ) * PLL_IN_MAX_MHZ >= HSI_MHZ, "the PLL from the HSI");
#if STM32_HSE_MHZ
_Static_assert(PLL_FITS(STM32_HSE_MHZ) && PLL_M_OF(STM32_HSE_MHZ) * PLL_IN_MAX_MHZ >= STM32_HSE_MHZ,
               "the PLL from the crystal");
#endif
_Static_assert(PLL_P * STM32_SYSCLK_MHZ == PLL_VCO_MHZ && (PLL_P == 2 || PLL_P == 4), "SYSCLK: the VCO / 2 or / 4");
_Static_assert(PLL_VCO_MHZ / PLL_Q == 48 && PLL_VCO_MHZ % PLL_Q == 0, "USB's 48 MHz from the VCO");

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

/* A revision A F405/F407, on which ST's own set-up leaves the flash
 * prefetch off. RM0090 gives it REV_ID 0x1000 with DEV_ID 0x413, but
 * the revision A parts read DEV_ID 0x411, the F2's (errata: "MCU device
 * ID is incorrect"); as this image runs only on a Cortex-M4F, 0x411 here
 * is one of them. Anything else, the 0 QEMU reads among them, is not. */
static int revision_a_f405(uint32_t idcode)
{
    uint32_t dev_id = idcode & 0xfffu, rev_id = idcode >> 16;
    return (dev_id == 0x413u && rev_id == 0x1000u) || dev_id == 0x411u;
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
    RCC_PLLCFGR = (RCC_PLLCFGR & ~PLLCFGR_FIELDS) | pllcfgr;
    RCC_CR |= RCC_CR_PLLON;
    if (!wait_for(&RCC_CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY)) {
        RCC_CR &= ~RCC_CR_PLLON;
        clock_line = "clock: the PLL never reported lock (RCC_CR PLLRDY), so SYSCLK stayed on the "
                     "16 MHz HSI as reset left it (expected under QEMU, whose RCC reads 0)";
        return CLOCK_HSI;
    }
    /* wait states before the clock rises; the caches and prefetch then
     * hide most of them */
    int revision_a = revision_a_f405(DBGMCU_IDCODE);
    FLASH_ACR = FLASH_WAIT_STATES | (revision_a ? 0u : FLASH_ACR_PRFTEN) | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
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
    static const char *const lines[2][2] = {
        { "clock: PLL from the crystal (HSE)",
          "clock: PLL from the crystal (HSE); flash prefetch off: a revision A F405/F407" },
        { "clock: PLL from the 16 MHz HSI (the crystal did not start)",
          "clock: PLL from the 16 MHz HSI (the crystal did not start); flash prefetch off: a revision A F405/F407" },
    };
    clock_line = lines[source == CLOCK_PLL_HSI][revision_a];
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
