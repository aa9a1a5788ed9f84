/*
 * stm32f4_clock_test.c - platform/stm32f4/clock.c on the host, against a
 * model of the STM32F4's RCC and FLASH_ACR written from RM0090 (what
 * QEMU, whose RCC reads 0, cannot check): the ready bits follow their
 * enables, SYSCLK follows SW only from a locked PLL, and every access
 * checks the rules the chip imposes: wait states before SYSCLK rises,
 * the PLL configured only while off, HSEBYP changed only with the HSE
 * off, the VCO, USB and APB clocks within their limits. Built once per
 * variant by tests/board-stm32f4-tests.sh (-DSTM32_SYSCLK_MHZ=...,
 * -DSTM32_HSE_MHZ=..., -DSTM32_HSE_BYPASS=...); prints one line per
 * check and "stm32f4-clock: N passed, M failed".
 */
#include <stdio.h>
#include <string.h>

#include <stdint.h>

static volatile uint32_t *model_reg(uint32_t addr);
#define STM32_REG(addr) (*model_reg(addr))
#include "clock.c"

enum { CR, PLLCFGR, CFGR, ACR, OTHER, NREGS };

static struct {
    uint32_t r[NREGS];
    uint32_t last_cr, last_pllcfgr;
    int crystal;     /* the HSE starts when enabled */
    int acr_sticks;  /* FLASH_ACR keeps what is written (QEMU's reads 0) */
    int dead;        /* every RCC and FLASH register reads 0 (QEMU) */
    char fault[160]; /* the first rule broken */
} m;

static void broke(const char *what)
{
    if (!m.fault[0])
        snprintf(m.fault, sizeof m.fault, "%s", what);
}

/* The PLL's output in kHz from PLLCFGR, with its limits checked */
static uint32_t pll_khz(void)
{
    uint32_t c = m.r[PLLCFGR], mdiv = c & 63u, n = (c >> 6) & 511u, p = 2u * (((c >> 16) & 3u) + 1u),
             q = (c >> 24) & 15u;
    uint32_t in_khz = (c & RCC_PLLCFGR_SRC_HSE ? STM32_HSE_MHZ : HSI_MHZ) * 1000u;
    if (mdiv < 2 || in_khz / mdiv < 950 || in_khz / mdiv > 2100)
        broke("PLL input outside 0.95..2.1 MHz (PLLM)");
    uint32_t vco = mdiv ? in_khz / mdiv * n : 0;
    if (vco < 192000 || vco > 432000)
        broke("VCO outside 192..432 MHz");
    if (q < 2 || vco / q != 48000)
        broke("USB clock not 48 MHz (PLLQ)");
    return vco / p;
}

/* The flash wait states SYSCLK needs at 2.7-3.6 V (RM0090: 30 MHz a state) */
static uint32_t states_for(uint32_t khz) { return (khz - 1) / 30000u; }

/* Brings the model up to date before each access: ready bits, the switch,
 * and the rules, checked on the state the last writes left. */
static void update(void)
{
    uint32_t cr = m.r[CR];
    if ((cr ^ m.last_cr) & RCC_CR_HSEBYP && (cr & m.last_cr & RCC_CR_HSEON))
        broke("HSEBYP changed while the HSE was on");
    if (m.r[PLLCFGR] != m.last_pllcfgr && (m.last_cr & RCC_CR_PLLON))
        broke("PLLCFGR written while the PLL was on");
    cr &= ~(RCC_CR_HSERDY | RCC_CR_PLLRDY);
    if ((cr & RCC_CR_HSEON) && m.crystal && ((cr & RCC_CR_HSEBYP) != 0) == (STM32_HSE_BYPASS != 0))
        cr |= RCC_CR_HSERDY;
    if ((cr & RCC_CR_PLLON) && (!(m.r[PLLCFGR] & RCC_PLLCFGR_SRC_HSE) || (cr & RCC_CR_HSERDY)))
        cr |= RCC_CR_PLLRDY;
    m.r[CR] = cr;
    uint32_t cfgr = m.r[CFGR] & ~RCC_CFGR_SWS_MASK;
    if ((cfgr & 3u) == RCC_CFGR_SW_PLL) {
        if (!(cr & RCC_CR_PLLRDY))
            broke("SYSCLK switched to a PLL that is not locked");
        uint32_t khz = pll_khz();
        if ((m.r[ACR] & FLASH_ACR_LATENCY_MASK) < states_for(khz))
            broke("SYSCLK on the PLL with too few flash wait states");
        static const uint32_t apb_div[8] = { 1, 1, 1, 1, 2, 4, 8, 16 };
        if (khz / apb_div[(cfgr >> 10) & 7u] > 42000)
            broke("APB1 above 42 MHz");
        if (khz / apb_div[(cfgr >> 13) & 7u] > 84000)
            broke("APB2 above 84 MHz");
        cfgr |= RCC_CFGR_SWS_PLL;
    }
    m.r[CFGR] = cfgr;
    m.last_cr = m.r[CR];
    m.last_pllcfgr = m.r[PLLCFGR];
}

static volatile uint32_t *model_reg(uint32_t addr)
{
    static volatile uint32_t zero;
    if (m.dead) {
        zero = 0; /* reads 0, writes lost */
        return &zero;
    }
    update();
    if (!m.acr_sticks)
        m.r[ACR] = 0;
    switch (addr) {
    case 0x40023800u: return &m.r[CR];
    case 0x40023804u: return &m.r[PLLCFGR];
    case 0x40023808u: return &m.r[CFGR];
    case 0x40023c00u: return &m.r[ACR];
    default: return &m.r[OTHER];
    }
}

static int pass, fail;

static void check(int ok, const char *what)
{
    printf("  %s  %s%s%s\n", ok ? "ok  " : "FAIL", what, m.fault[0] ? ": " : "", m.fault);
    ok ? pass++ : fail++;
}

static clock_source_t run(int crystal, int acr_sticks, int dead)
{
    memset(&m, 0, sizeof m);
    m.r[CR] = m.last_cr = 0x83u; /* reset: HSION, HSIRDY, trim */
    m.r[PLLCFGR] = m.last_pllcfgr = 0x24003010u;
    m.crystal = crystal;
    m.acr_sticks = acr_sticks;
    m.dead = dead;
    clock_line = 0;
    clock_source_t s = clocks_init();
    if (!dead)
        update(); /* the rules on the final state too */
    return s;
}

int main(void)
{
    char what[200];
    const uint32_t want_hz = STM32_SYSCLK_MHZ * 1000000u;
    printf("stm32f4-clock: %u MHz, crystal %u MHz%s\n", STM32_SYSCLK_MHZ, STM32_HSE_MHZ,
           STM32_HSE_BYPASS ? " (bypass)" : "");

    clock_source_t s = run(1, 1, 0);
#if STM32_HSE_MHZ
    snprintf(what, sizeof what, "crystal answers: PLL from the HSE, SYSCLK %u Hz, every rule kept",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSE && clock_sysclk_hz(s) == want_hz && pll_khz() * 1000u == want_hz &&
              (m.r[CFGR] & RCC_CFGR_SWS_MASK) == RCC_CFGR_SWS_PLL && !m.fault[0] &&
              strstr(clock_report(), "crystal (HSE)"),
          what);
#else
    snprintf(what, sizeof what, "no crystal built in: PLL from the HSI, SYSCLK %u Hz, HSE never on",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && !(m.r[CR] & RCC_CR_HSEON) && !m.fault[0], what);
#endif
    snprintf(what, sizeof what, "FLASH_ACR: %u wait states, prefetch, I and D caches (0x%x)",
             (unsigned)(m.r[ACR] & FLASH_ACR_LATENCY_MASK), (unsigned)m.r[ACR]);
    check((m.r[ACR] & FLASH_ACR_LATENCY_MASK) == states_for(want_hz / 1000u) &&
              (m.r[ACR] & (FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN)) ==
                  (FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN),
          what);
    snprintf(what, sizeof what, "APB1 %u Hz, APB2 %u Hz", (unsigned)clock_apb_hz(s, 1), (unsigned)clock_apb_hz(s, 2));
    check(clock_apb_hz(s, 1) == 42000000u && clock_apb_hz(s, 2) == 84000000u, what);

    s = run(0, 1, 0);
    snprintf(what, sizeof what, "no crystal answers: PLL from the HSI, SYSCLK %u Hz, HSE off again",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && pll_khz() * 1000u == want_hz &&
              !(m.r[CR] & (RCC_CR_HSEON | RCC_CR_HSEBYP)) && !(m.r[PLLCFGR] & RCC_PLLCFGR_SRC_HSE) && !m.fault[0],
          what);

    s = run(1, 0, 0);
    check(s == CLOCK_HSI && clock_sysclk_hz(s) == 16000000u && (m.r[CFGR] & 3u) == 0 && !(m.r[CR] & RCC_CR_PLLON) &&
              strstr(clock_report(), "FLASH_ACR") && !m.fault[0],
          "wait states not kept: SYSCLK stays on the HSI (16 MHz), PLL off, the line says why");

    s = run(1, 1, 1);
    check(s == CLOCK_HSI && clock_sysclk_hz(s) == 16000000u && clock_apb_hz(s, 2) == 16000000u &&
              strstr(clock_report(), "never reported lock"),
          "RCC reads 0 (QEMU): every wait ends, SYSCLK 16 MHz, the line names the PLL");

    printf("stm32f4-clock: %d passed, %d failed\n", pass, fail);
    return fail != 0;
}
