/*
 * clock.c - the STM32F4's clock tree (clock.h), for the chip: the
 * crystal (HSE; bypass mode where a clock drives it) or the 16 MHz HSI
 * divided to at most 2 MHz into the main PLL; SYSCLK 168 MHz (VCO 336 /
 * 2), 84 MHz (336 / 4) or 100 MHz (400 / 4); the regulator's voltage
 * scale for that clock (F401, F411); flash wait states, prefetch (not on
 * a revision A F405/F407) and the ART accelerator's caches before SYSCLK
 * moves; APB1 and APB2 at most their limits. Under QEMU, whose RCC reads
 * 0, the PLL never reports lock and SYSCLK stays on the HSI.
 */
#include "clock.h"

/* The chip's limits (ST's CMSIS device headers stm32f405xx.h,
 * stm32f401xc.h, stm32f411xe.h; RM0090, RM0368, RM0383): the PLL's N
 * and VCO (the F401's from 192 and 192 MHz, the others' from 50 and 100
 * MHz; 432 at most), SYSCLK, APB1 and APB2. */
#if STM32_CHIP == 405
#define PLL_N_MIN 50u
#define PLL_VCO_MIN_MHZ 100u
#define SYSCLK_MAX_MHZ 168u
#define APB1_MAX_MHZ 42u
#define APB2_MAX_MHZ 84u
#elif STM32_CHIP == 401
#define PLL_N_MIN 192u
#define PLL_VCO_MIN_MHZ 192u
#define SYSCLK_MAX_MHZ 84u
#define APB1_MAX_MHZ 42u
#define APB2_MAX_MHZ 84u
#elif STM32_CHIP == 411
#define PLL_N_MIN 50u
#define PLL_VCO_MIN_MHZ 100u
#define SYSCLK_MAX_MHZ 100u
#define APB1_MAX_MHZ 50u
#define APB2_MAX_MHZ 100u
#else
#error "STM32_CHIP: 405, 401 or 411"
#endif
_Static_assert(STM32_SYSCLK_MHZ <= SYSCLK_MAX_MHZ, "SYSCLK within the chip's most");

/* The PLL: its input / M, times N to the VCO, / P for SYSCLK (P 2 at
 * 168 MHz, else 4: the VCO at 336 or 400 MHz, as ST's own set-ups have
 * it), / Q for USB's 48 MHz: exact from 336 MHz (Q 7); no Q gives it from
 * 400 MHz, where Q 9 keeps that clock under 48 MHz (44.4, as SDIO
 * requires; the firmware uses neither). The input is 2 MHz where it can
 * be (1 to 2 MHz allowed, 2 asked for to limit the PLL's jitter); two
 * rules hold it lower on some inputs:
 *  - N = VCO / input must be whole, or SYSCLK, and with it the USART's
 *    baud rate and every time the report gives, would be off: M is a
 *    multiple of mhz / gcd(mhz, VCO). A 25 MHz crystal thus gets M 25,
 *    1 MHz, at 336 MHz (M 13, 1.92 MHz, would give 168.27 MHz with N 175,
 *    over the chip's most, or 167.31 MHz and USB at 47.8 MHz with N 174),
 *    but M 13 and N 208 at 400 MHz;
 *  - N at least PLL_N_MIN: on the F401 (and so on the Nucleo-64, whose
 *    image runs on it) the input is at most 336 / 192 = 1.75 MHz, 1.6 MHz
 *    from 8 or 16 MHz (M 5 or 10, N 210).
 * PLL_M_OF is the least M that keeps both rules and the 2 MHz; the
 * static asserts below check every limit for the crystal and the HSI. */
#define PLL_P (STM32_SYSCLK_MHZ == 168 ? 2u : 4u)
#define PLL_VCO_MHZ (STM32_SYSCLK_MHZ * PLL_P)
#define CEIL_DIV(a, b) (((a) + (b) - 1u) / (b))
#define PLL_Q CEIL_DIV(PLL_VCO_MHZ, 48u)
#define PLL_IN_MAX_MHZ 2u
#define PLL_N_MAX 432u
#define MAX(a, b) ((a) > (b) ? (a) : (b))
/* gcd(mhz, VCO) for mhz up to 26: the largest power of each prime up to
 * 26 that divides both */
#define DIVIDES_BOTH(d, mhz) ((mhz) % (d) == 0 && PLL_VCO_MHZ % (d) == 0)
#define GCD_VCO(mhz)                                                                                                   \
    ((DIVIDES_BOTH(16u, mhz)  ? 16u                                                                                    \
      : DIVIDES_BOTH(8u, mhz) ? 8u                                                                                     \
      : DIVIDES_BOTH(4u, mhz) ? 4u                                                                                     \
      : DIVIDES_BOTH(2u, mhz) ? 2u                                                                                     \
                              : 1u) *                                                                                  \
     (DIVIDES_BOTH(9u, mhz) ? 9u : DIVIDES_BOTH(3u, mhz) ? 3u : 1u) *                                                  \
     (DIVIDES_BOTH(25u, mhz) ? 25u : DIVIDES_BOTH(5u, mhz) ? 5u : 1u) * (DIVIDES_BOTH(7u, mhz) ? 7u : 1u) *            \
     (DIVIDES_BOTH(11u, mhz) ? 11u : 1u) * (DIVIDES_BOTH(13u, mhz) ? 13u : 1u) * (DIVIDES_BOTH(17u, mhz) ? 17u : 1u) * \
     (DIVIDES_BOTH(19u, mhz) ? 19u : 1u) * (DIVIDES_BOTH(23u, mhz) ? 23u : 1u))
#define PLL_M_STEP(mhz) ((mhz) / GCD_VCO(mhz))
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
_Static_assert(PLL_VCO_MHZ >= PLL_VCO_MIN_MHZ && PLL_VCO_MHZ <= 432u, "the VCO within its range");
_Static_assert(PLL_Q >= 2 && PLL_Q <= 15 && PLL_VCO_MHZ / PLL_Q <= 48, "USB's clock at most 48 MHz");

/* The buses: AHB at SYSCLK; APB2 at SYSCLK up to 100 MHz, else / 2;
 * APB1 at half APB2 (board.mk's STM32_USART_HZ assumes the same) */
#define APB2_MHZ (STM32_SYSCLK_MHZ > 100 ? STM32_SYSCLK_MHZ / 2u : STM32_SYSCLK_MHZ)
#define APB1_MHZ (APB2_MHZ / 2u)
#define APB_PRESCALERS                                                                                                 \
    ((STM32_SYSCLK_MHZ > 100 ? RCC_CFGR_PPRE1_DIV4 | RCC_CFGR_PPRE2_DIV2 : RCC_CFGR_PPRE1_DIV2))
_Static_assert(APB1_MHZ <= APB1_MAX_MHZ && APB2_MHZ <= APB2_MAX_MHZ, "APB1 and APB2 within the chip's limits");
_Static_assert(STM32_SYSCLK_MHZ % APB2_MHZ == 0 && STM32_SYSCLK_MHZ % APB1_MHZ == 0, "APB1 and APB2 divide SYSCLK");
#ifdef STM32_USART_HZ
_Static_assert(STM32_USART_HZ == (STM32_USART == 1 ? APB2_MHZ : APB1_MHZ) * 1000000u,
               "board.mk's console clock, against which it checked BAUD, is this one");
#endif

/* Flash wait states at 2.7-3.6 V: one per 30 MHz of HCLK on the F405/F407
 * (RM0090); the F401 needs 2 at 84 MHz, the F411 3 at 100 MHz (RM0368,
 * RM0383), which the same rule gives */
#define FLASH_WAIT_STATES ((STM32_SYSCLK_MHZ - 1u) / 30u)

/* The regulator's voltage scale (PWR_CR VOS) on the F401 and F411: scale
 * 2 (VOS 10) for up to 84 MHz, scale 1 (VOS 11: the F411 only) for 100
 * MHz. Set with the PLL off; it takes effect when the PLL runs. The
 * F405/F407's single VOS bit starts at scale 1, its 168 MHz: left alone. */
#if STM32_CHIP != 405
#define PWR_VOS (STM32_SYSCLK_MHZ > 84 ? 3u : 2u)
#endif

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
#ifdef PWR_VOS
    RCC_APB1ENR |= RCC_APB1ENR_PWR;
    (void)RCC_APB1ENR; /* (two clocks before PWR answers) */
    PWR_CR = (PWR_CR & ~PWR_CR_VOS_MASK) | PWR_VOS << PWR_CR_VOS_SHIFT;
#endif
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
        { "clock: PLL from the 16 MHz HSI (the HSE did not start: no crystal, or the wrong HSE=crystal|bypass)",
          "clock: PLL from the 16 MHz HSI (the HSE did not start: no crystal, or the wrong HSE=crystal|bypass); "
          "flash prefetch off: a revision A F405/F407" },
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
