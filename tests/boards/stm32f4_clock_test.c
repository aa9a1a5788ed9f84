/*
 * stm32f4_clock_test.c - platform/stm32f4/clock.c on the host, against a
 * model of the STM32F4's RCC, FLASH_ACR and DBGMCU_IDCODE written from
 * RM0090 (what QEMU, whose RCC reads 0, cannot check): the ready bits
 * follow their enables, SYSCLK follows SW only from a locked PLL, and
 * every access checks the rules the chip imposes: wait states before
 * SYSCLK rises, the PLL configured only while off and PLLCFGR's reserved
 * bits kept at their reset value, HSEBYP changed only with the HSE off,
 * the PLL's input, N, VCO, USB and APB clocks within their limits (the
 * 84 MHz image's also within the F401's and F411's). Beyond the rules:
 * the PLL's input as fast as any exact set-up allows (2 MHz where one
 * does; found here by trying every M, N, P and Q), and the flash
 * prefetch off on a revision A F405/F407 only. Built once per variant by
 * tests/boards/board-stm32f4-tests.sh (-DSTM32_SYSCLK_MHZ=..., -DSTM32_HSE_MHZ=...,
 * -DSTM32_HSE_BYPASS=...); prints one line per check and
 * "stm32f4-clock: N passed, M failed".
 */
#include <stdio.h>
#include <string.h>

#include <stdint.h>

static volatile uint32_t *model_reg(uint32_t addr);
#define STM32_REG(addr) (*model_reg(addr))
#include "clock.c"

enum { CR, PLLCFGR, CFGR, ACR, IDCODE, OTHER, NREGS };

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

/* PLLCFGR at reset, and its bits that are not PLLM (5:0), PLLN (14:6),
 * PLLP (17:16), PLLSRC (22) or PLLQ (27:24): reserved, to be kept as
 * reset left them (RM0090 7.3.2) */
#define PLLCFGR_RESET 0x24003010u
#define PLLCFGR_RESERVED (~(0x3fu | 0x1ffu << 6 | 3u << 16 | 1u << 22 | 0xfu << 24))

/* The chip's limits on N and the VCO: RM0090's for the F405/F407; the
 * 84 MHz image also runs on the F401 and F411, whose N starts at 192 */
#if STM32_SYSCLK_MHZ == 168
enum { N_MIN = 50, VCO_MIN_MHZ = 100 };
#else
enum { N_MIN = 192, VCO_MIN_MHZ = 192 };
#endif

/* Whether M, N, P, Q from `in_hz` keep every limit; the VCO's output in Hz
 * through *vco_hz (exact or not) */
static int pll_in_spec(uint64_t in_hz, uint32_t mdiv, uint32_t n, uint32_t q, uint64_t *vco_hz, const char **why)
{
    *vco_hz = mdiv ? in_hz * n / mdiv : 0;
    *why = mdiv < 2 || mdiv > 63 || in_hz < 1000000u * (uint64_t)mdiv || in_hz > 2000000u * (uint64_t)mdiv
               ? "PLL input outside 1..2 MHz (PLLM)"
           : n < N_MIN || n > 432 ? "PLLN out of range"
           : *vco_hz < VCO_MIN_MHZ * 1000000u || *vco_hz > 432000000u ? "VCO outside its range"
           : q < 2 || q > 15 || in_hz * n != 48000000u * (uint64_t)mdiv * q ? "USB clock not 48 MHz (PLLQ)"
                                                                           : 0;
    return !*why;
}

static uint64_t source_hz(uint32_t c) { return (c & RCC_PLLCFGR_SRC_HSE ? STM32_HSE_MHZ : HSI_MHZ) * 1000000ull; }

/* The PLL's output in Hz from PLLCFGR, with its limits checked; 0 when
 * it is not a whole number of Hz */
static uint64_t pll_hz(void)
{
    uint32_t c = m.r[PLLCFGR], mdiv = c & 63u, n = (c >> 6) & 511u, p = 2u * (((c >> 16) & 3u) + 1u),
             q = (c >> 24) & 15u;
    uint64_t vco;
    const char *why;
    if (!pll_in_spec(source_hz(c), mdiv, n, q, &vco, &why))
        broke(why);
    return mdiv && source_hz(c) * n % (mdiv * p) == 0 ? source_hz(c) * n / (mdiv * p) : 0;
}

/* The fastest PLL input, in mHz (25 MHz / 13 is not whole), of any set-up
 * within the limits that gives exactly `sysclk_hz` and USB's 48 MHz from
 * `in_hz`: every M, N, P and Q tried */
static uint64_t best_input_millihz(uint64_t in_hz, uint64_t sysclk_hz)
{
    uint64_t best = 0;
    for (uint32_t mdiv = 2; mdiv <= 63; mdiv++)
        for (uint32_t n = 2; n <= 432; n++)
            for (uint32_t p = 2; p <= 8; p += 2)
                for (uint32_t q = 2; q <= 15; q++) {
                    uint64_t vco;
                    const char *why;
                    if (pll_in_spec(in_hz, mdiv, n, q, &vco, &why) && in_hz * n == sysclk_hz * mdiv * p &&
                        in_hz * 1000u / mdiv > best)
                        best = in_hz * 1000u / mdiv;
                }
    return best;
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
    if ((m.r[PLLCFGR] ^ PLLCFGR_RESET) & PLLCFGR_RESERVED)
        broke("PLLCFGR's reserved bits changed");
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
        uint32_t khz = (uint32_t)(pll_hz() / 1000u);
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
    case 0xe0042000u: return &m.r[IDCODE];
    default: return &m.r[OTHER];
    }
}

static int pass, fail;

static void check(int ok, const char *what)
{
    printf("  %s  %s%s%s\n", ok ? "ok  " : "FAIL", what, m.fault[0] ? ": " : "", m.fault);
    ok ? pass++ : fail++;
}

static clock_source_t run(int crystal, int acr_sticks, int dead, uint32_t idcode)
{
    memset(&m, 0, sizeof m);
    m.r[CR] = m.last_cr = 0x83u; /* reset: HSION, HSIRDY, trim */
    m.r[PLLCFGR] = m.last_pllcfgr = PLLCFGR_RESET;
    m.r[IDCODE] = idcode;
    m.crystal = crystal;
    m.acr_sticks = acr_sticks;
    m.dead = dead;
    clock_line = 0;
    clock_source_t s = clocks_init();
    if (!dead)
        update(); /* the rules on the final state too */
    return s;
}

/* The PLL's input as set, against the fastest any exact set-up allows */
static void check_input(const char *source)
{
    char what[200];
    uint32_t c = m.r[PLLCFGR], mdiv = c & 63u;
    uint64_t in_millihz = mdiv ? source_hz(c) * 1000u / mdiv : 0,
             best = best_input_millihz(source_hz(c), STM32_SYSCLK_MHZ * 1000000ull);
    snprintf(what, sizeof what, "PLL from %s: M %u, N %u, P %u, Q %u: %.3f MHz in (the fastest exact: %.3f MHz)",
             source, (unsigned)mdiv, (unsigned)((c >> 6) & 511u), 2u * (((c >> 16) & 3u) + 1u),
             (unsigned)((c >> 24) & 15u), in_millihz / 1e9, best / 1e9);
    check(best != 0 && in_millihz == best && !m.fault[0], what);
}

int main(void)
{
    char what[200];
    const uint32_t want_hz = STM32_SYSCLK_MHZ * 1000000u;
    const uint32_t caches = FLASH_ACR_ICEN | FLASH_ACR_DCEN;
    printf("stm32f4-clock: %u MHz, crystal %u MHz%s\n", STM32_SYSCLK_MHZ, STM32_HSE_MHZ,
           STM32_HSE_BYPASS ? " (bypass)" : "");

    clock_source_t s = run(1, 1, 0, 0);
#if STM32_HSE_MHZ
    snprintf(what, sizeof what, "crystal answers: PLL from the HSE, SYSCLK %u Hz, every rule kept",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSE && clock_sysclk_hz(s) == want_hz && pll_hz() == want_hz &&
              (m.r[CFGR] & RCC_CFGR_SWS_MASK) == RCC_CFGR_SWS_PLL && !m.fault[0] &&
              strstr(clock_report(), "crystal (HSE)"),
          what);
    check_input("the crystal");
#else
    snprintf(what, sizeof what, "no crystal built in: PLL from the HSI, SYSCLK %u Hz, HSE never on",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && pll_hz() == want_hz && !(m.r[CR] & RCC_CR_HSEON) &&
              !m.fault[0],
          what);
#endif
    snprintf(what, sizeof what, "PLLCFGR 0x%08x: its reserved bits as reset left them (bit 29 set)",
             (unsigned)m.r[PLLCFGR]);
    check(!((m.r[PLLCFGR] ^ PLLCFGR_RESET) & PLLCFGR_RESERVED) && (m.r[PLLCFGR] & 1u << 29), what);
    snprintf(what, sizeof what, "FLASH_ACR: %u wait states, prefetch, I and D caches (0x%x)",
             (unsigned)(m.r[ACR] & FLASH_ACR_LATENCY_MASK), (unsigned)m.r[ACR]);
    check((m.r[ACR] & FLASH_ACR_LATENCY_MASK) == states_for(want_hz / 1000u) &&
              (m.r[ACR] & (FLASH_ACR_PRFTEN | caches)) == (FLASH_ACR_PRFTEN | caches),
          what);
    snprintf(what, sizeof what, "APB1 %u Hz, APB2 %u Hz", (unsigned)clock_apb_hz(s, 1), (unsigned)clock_apb_hz(s, 2));
    check(clock_apb_hz(s, 1) == 42000000u && clock_apb_hz(s, 2) == 84000000u, what);

    s = run(0, 1, 0, 0);
    snprintf(what, sizeof what, "no crystal answers: PLL from the HSI, SYSCLK %u Hz, HSE off again",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && pll_hz() == want_hz &&
              !(m.r[CR] & (RCC_CR_HSEON | RCC_CR_HSEBYP)) && !(m.r[PLLCFGR] & RCC_PLLCFGR_SRC_HSE) && !m.fault[0],
          what);
    check_input("the 16 MHz HSI");

    /* prefetch by DBGMCU_IDCODE: off on a revision A F405/F407 only */
    static const struct {
        uint32_t idcode;
        int prefetch;
        const char *chip;
    } ids[] = {
        { 0x10006413u, 0, "a revision A F405/F407 as RM0090 lists it (REV_ID 0x1000)" },
        { 0x20006411u, 0, "a revision A F405/F407 as it reads (DEV_ID 0x411, the F2's)" },
        { 0x10016413u, 1, "a revision Z F405/F407" },
        { 0x10076413u, 1, "a revision 2 F405/F407" },
        { 0x10006431u, 1, "a revision A F411" },
        { 0x10006423u, 1, "a revision A F401" },
        { 0, 1, "an IDCODE that reads 0 (QEMU's)" },
    };
    for (size_t i = 0; i < sizeof ids / sizeof ids[0]; i++) {
        s = run(1, 1, 0, ids[i].idcode);
        int off = strstr(clock_report(), "prefetch off") != 0;
        snprintf(what, sizeof what, "%s (0x%08x): prefetch %s, caches on, %u wait states", ids[i].chip,
                 (unsigned)ids[i].idcode, ids[i].prefetch ? "on" : "off, and the clock line says so",
                 (unsigned)(m.r[ACR] & FLASH_ACR_LATENCY_MASK));
        check(s != CLOCK_HSI && !(m.r[ACR] & FLASH_ACR_PRFTEN) == !ids[i].prefetch && off == !ids[i].prefetch &&
                  (m.r[ACR] & caches) == caches &&
                  (m.r[ACR] & FLASH_ACR_LATENCY_MASK) == states_for(want_hz / 1000u) && !m.fault[0],
              what);
    }

    s = run(1, 0, 0, 0);
    check(s == CLOCK_HSI && clock_sysclk_hz(s) == 16000000u && (m.r[CFGR] & 3u) == 0 && !(m.r[CR] & RCC_CR_PLLON) &&
              strstr(clock_report(), "FLASH_ACR") && !m.fault[0],
          "wait states not kept: SYSCLK stays on the HSI (16 MHz), PLL off, the line says why");

    s = run(1, 1, 1, 0);
    check(s == CLOCK_HSI && clock_sysclk_hz(s) == 16000000u && clock_apb_hz(s, 2) == 16000000u &&
              strstr(clock_report(), "never reported lock"),
          "RCC reads 0 (QEMU): every wait ends, SYSCLK 16 MHz, the line names the PLL");

    printf("stm32f4-clock: %d passed, %d failed\n", pass, fail);
    return fail != 0;
}
