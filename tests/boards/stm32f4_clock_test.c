/*
 * stm32f4_clock_test.c - platform/stm32f4/clock.c on the host, against a
 * model of the STM32F4's RCC, PWR_CR, FLASH_ACR and DBGMCU_IDCODE written
 * from RM0090, RM0368 and RM0383 and ST's device headers (what QEMU,
 * whose RCC reads 0, cannot check): the ready bits follow their enables,
 * SYSCLK follows SW only from a locked PLL, PWR_CR takes writes only with
 * its clock on, and every access checks the rules the chip imposes: wait
 * states before SYSCLK rises, by the chip's own table; the voltage scale
 * that allows SYSCLK (F401, F411), set while the PLL is off, whatever
 * scale reset left; the PLL configured only while off and PLLCFGR's
 * reserved bits kept at their reset value; HSEBYP changed only with the
 * HSE off, and an HSE that starts only in the mode its hardware needs
 * (a crystal never in bypass); the PLL's input, N, VCO, USB and APB
 * clocks within the chip's limits. Beyond the rules: the PLL's input as
 * fast as any exact set-up allows (2 MHz where one does; found here by
 * trying every M, N, P and Q), the flash prefetch off on a revision A
 * F405/F407 only, and the console's divider: BRR for BAUD from the clock
 * it ends up with, and which rates fit (RM0090's USARTDIV, mantissa and
 * fraction, worked out here in floating point). Built once per variant
 * by tests/boards/board-stm32f4-tests.sh with the flags the firmware
 * gets (make stm32-clock-flags); prints one line per check and
 * "stm32f4-clock: N passed, M failed".
 */
#include <stdio.h>
#include <string.h>

#include <stdint.h>

static volatile uint32_t *model_reg(uint32_t addr);
#define STM32_REG(addr) (*model_reg(addr))
#include "clock.c"

enum { CR, PLLCFGR, CFGR, ACR, IDCODE, APB1ENR, PWRCR, OTHER, NREGS };

static struct {
    uint32_t r[NREGS];
    uint32_t last_cr, last_pllcfgr;
    int crystal;     /* the HSE: 0 none, 1 what the build says (crystal or
                      * clock), 2 the other one */
    int acr_sticks;  /* FLASH_ACR keeps what is written (QEMU's reads 0) */
    int dead;        /* every RCC and FLASH register reads 0 (QEMU) */
    uint32_t pwr;    /* PWR_CR as written, when its clock was on */
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

/* The chip's limits (ST's device headers: RCC_PLLN_MIN_VALUE,
 * RCC_PLLVCO_OUTPUT_MIN, RCC_MAX_FREQUENCY_SCALEx, FLASH_SCALEx_LATENCYy_FREQ;
 * the datasheets' APB limits): N and the VCO; SYSCLK under each voltage
 * scale (VOS 0..3; 0 on the F405/F407: its one VOS bit, not modelled);
 * the HCLK up to which each wait state count will do at 2.7-3.6 V */
#if STM32_CHIP == 405
enum { N_MIN = 50, VCO_MIN_MHZ = 100, APB1_MAX = 42000, APB2_MAX = 84000 };
static const uint32_t vos_max_khz[4] = { 168000, 168000, 168000, 168000 };
static const uint32_t ws_max_khz[] = { 30000, 60000, 90000, 120000, 150000, 168000 };
#elif STM32_CHIP == 401
enum { N_MIN = 192, VCO_MIN_MHZ = 192, APB1_MAX = 42000, APB2_MAX = 84000 };
static const uint32_t vos_max_khz[4] = { 60000, 60000, 84000, 84000 }; /* 00 and 11 reserved: 3 and 2 */
static const uint32_t ws_max_khz[] = { 30000, 60000, 84000 };
#else
enum { N_MIN = 50, VCO_MIN_MHZ = 100, APB1_MAX = 50000, APB2_MAX = 100000 };
static const uint32_t vos_max_khz[4] = { 64000, 64000, 84000, 100000 };
static const uint32_t ws_max_khz[] = { 30000, 64000, 90000, 100000 };
#endif

/* USB's clock must be 48 MHz exactly where SYSCLK leaves a VCO that gives
 * it (some P and Q), else at most 48 MHz (SDIO's limit) */
static int usb48_possible(uint32_t sysclk_mhz)
{
    for (uint32_t p = 2; p <= 8; p += 2)
        if (sysclk_mhz * p >= VCO_MIN_MHZ && sysclk_mhz * p <= 432 && sysclk_mhz * p % 48 == 0)
            return 1;
    return 0;
}

/* Whether M, N, P, Q from `in_hz` keep every limit; the VCO's output in Hz
 * through *vco_hz (exact or not) */
static int pll_in_spec(uint64_t in_hz, uint32_t mdiv, uint32_t n, uint32_t q, uint64_t *vco_hz, const char **why)
{
    *vco_hz = mdiv ? in_hz * n / mdiv : 0;
    *why = mdiv < 2 || mdiv > 63 || in_hz < 1000000u * (uint64_t)mdiv || in_hz > 2000000u * (uint64_t)mdiv
               ? "PLL input outside 1..2 MHz (PLLM)"
           : n < N_MIN || n > 432 ? "PLLN out of range"
           : *vco_hz < VCO_MIN_MHZ * 1000000u || *vco_hz > 432000000u ? "VCO outside its range"
           : q < 2 || q > 15 || in_hz * n > 48000000u * (uint64_t)mdiv * q ? "USB clock over 48 MHz (PLLQ)"
           : usb48_possible(STM32_SYSCLK_MHZ) && in_hz * n != 48000000u * (uint64_t)mdiv * q
               ? "USB clock not 48 MHz (PLLQ), which this SYSCLK allows"
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

/* The flash wait states SYSCLK needs at 2.7-3.6 V, by the chip's table;
 * 99 when it is over the table's last line */
static uint32_t states_for(uint32_t khz)
{
    for (uint32_t n = 0; n < sizeof ws_max_khz / sizeof ws_max_khz[0]; n++)
        if (khz <= ws_max_khz[n])
            return n;
    return 99;
}

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
    if ((m.r[PWRCR] ^ m.pwr) & PWR_CR_VOS_MASK) {
        if (!(m.r[APB1ENR] & RCC_APB1ENR_PWR))
            m.r[PWRCR] = m.pwr; /* PWR unclocked: the write is lost */
        else if (m.last_cr & RCC_CR_PLLON)
            broke("VOS changed while the PLL was on");
    }
    m.pwr = m.r[PWRCR];
    cr &= ~(RCC_CR_HSERDY | RCC_CR_PLLRDY);
    /* the HSE runs only in the mode its hardware needs: a crystal with the
     * oscillator (HSEBYP 0), a clock signal bypassing it (HSEBYP 1) */
    int hw_clock = m.crystal == 1 ? STM32_HSE_BYPASS != 0 : STM32_HSE_BYPASS == 0;
    if ((cr & RCC_CR_HSEON) && m.crystal && ((cr & RCC_CR_HSEBYP) != 0) == hw_clock)
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
        if (khz > vos_max_khz[(m.pwr & PWR_CR_VOS_MASK) >> PWR_CR_VOS_SHIFT])
            broke("SYSCLK above what the voltage scale (PWR_CR VOS) allows");
        static const uint32_t apb_div[8] = { 1, 1, 1, 1, 2, 4, 8, 16 };
        if (khz / apb_div[(cfgr >> 10) & 7u] > APB1_MAX)
            broke("APB1 above the chip's most");
        if (khz / apb_div[(cfgr >> 13) & 7u] > APB2_MAX)
            broke("APB2 above the chip's most");
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
    case 0x40023840u: return &m.r[APB1ENR];
    case 0x40007000u: return &m.r[PWRCR];
    default: return &m.r[OTHER];
    }
}

static int pass, fail;

static void check(int ok, const char *what)
{
    printf("  %s  %s%s%s\n", ok ? "ok  " : "FAIL", what, m.fault[0] ? ": " : "", m.fault);
    ok ? pass++ : fail++;
}

/* PWR_CR at reset: the tests run from each voltage scale reset may have
 * left (VOS 01 and 10), so that none is taken for granted */
static uint32_t pwr_reset = 1u << PWR_CR_VOS_SHIFT;

static clock_source_t run(int crystal, int acr_sticks, int dead, uint32_t idcode)
{
    memset(&m, 0, sizeof m);
    m.r[PWRCR] = m.pwr = pwr_reset;
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

/* The fastest bus clock within `max_khz` that SYSCLK divided by 1, 2, 4,
 * 8 or 16 gives */
static uint32_t fastest_apb_hz(uint32_t sysclk_hz, uint32_t max_khz)
{
    for (uint32_t d = 1; d <= 16; d *= 2)
        if (sysclk_hz / d <= max_khz * 1000u)
            return sysclk_hz / d;
    return 0;
}

/* The console's divider from RM0090's USARTDIV, in floating point: f /
 * (16 baud), its whole part the mantissa (1 to 4095), its fraction
 * rounded to 16ths (a carry into the mantissa when it rounds to 16); the
 * rate that gives, and whether it is within 2% */
static int baud_fits_rm(double f, double baud, unsigned *brr, double *actual)
{
    double div = f / (16 * baud);
    unsigned mant = (unsigned)div, frac = (unsigned)((div - mant) * 16 + 0.5);
    if (frac == 16) {
        mant++;
        frac = 0;
    }
    *brr = mant << 4 | frac;
    *actual = mant ? f / (16 * (mant + frac / 16.0)) : 0;
    return mant >= 1 && mant <= 4095 && *actual != 0 && (*actual > baud ? *actual - baud : baud - *actual) <= 0.02 * baud;
}

int main(void)
{
    char what[512];
    const uint32_t want_hz = STM32_SYSCLK_MHZ * 1000000u;
    const uint32_t caches = FLASH_ACR_ICEN | FLASH_ACR_DCEN;
    printf("stm32f4-clock: F%u limits, %u MHz, HSE %u MHz %s, USART%u at %u baud\n", STM32_CHIP, STM32_SYSCLK_MHZ,
           STM32_HSE_MHZ, !STM32_HSE_MHZ ? "(none)" : STM32_HSE_BYPASS ? "bypass (a clock)" : "crystal", STM32_USART,
           STM32_BAUD);

    clock_source_t s;
    /* from each voltage scale reset may leave (the F405/F407's one VOS
     * bit: scale 1) */
    for (uint32_t vos = 1; vos <= (STM32_CHIP == 405 ? 1u : 2u); vos++) {
        pwr_reset = vos << PWR_CR_VOS_SHIFT;
        s = run(1, 1, 0, 0);
#if STM32_HSE_MHZ
        snprintf(what, sizeof what,
                 "VOS %u at reset, HSE answers: PLL from the HSE, SYSCLK %u Hz, VOS %u, every rule kept", (unsigned)vos,
                 (unsigned)clock_sysclk_hz(s), (unsigned)((m.pwr & PWR_CR_VOS_MASK) >> PWR_CR_VOS_SHIFT));
        check(s == CLOCK_PLL_HSE && clock_sysclk_hz(s) == want_hz && pll_hz() == want_hz &&
                  (m.r[CFGR] & RCC_CFGR_SWS_MASK) == RCC_CFGR_SWS_PLL && !m.fault[0] &&
                  strstr(clock_report(), "crystal (HSE)"),
              what);
#else
        snprintf(what, sizeof what, "VOS %u at reset, no HSE built in: PLL from the HSI, SYSCLK %u Hz, HSE never on",
                 (unsigned)vos, (unsigned)clock_sysclk_hz(s));
        check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && pll_hz() == want_hz &&
                  !(m.r[CR] & RCC_CR_HSEON) && !m.fault[0],
              what);
#endif
    }
#if STM32_HSE_MHZ
    check_input("the HSE");
#endif
    snprintf(what, sizeof what, "PLLCFGR 0x%08x: its reserved bits as reset left them (bit 29 set)",
             (unsigned)m.r[PLLCFGR]);
    check(!((m.r[PLLCFGR] ^ PLLCFGR_RESET) & PLLCFGR_RESERVED) && (m.r[PLLCFGR] & 1u << 29), what);
    snprintf(what, sizeof what, "FLASH_ACR: %u wait states (the chip's table at %u MHz), prefetch, I and D caches (0x%x)",
             (unsigned)(m.r[ACR] & FLASH_ACR_LATENCY_MASK), STM32_SYSCLK_MHZ, (unsigned)m.r[ACR]);
    check((m.r[ACR] & FLASH_ACR_LATENCY_MASK) == states_for(want_hz / 1000u) &&
              (m.r[ACR] & (FLASH_ACR_PRFTEN | caches)) == (FLASH_ACR_PRFTEN | caches),
          what);
    uint32_t apb1 = fastest_apb_hz(want_hz, APB1_MAX), apb2 = fastest_apb_hz(want_hz, APB2_MAX);
    snprintf(what, sizeof what, "APB1 %u Hz, APB2 %u Hz: the fastest within the chip's %u and %u MHz",
             (unsigned)clock_apb_hz(s, 1), (unsigned)clock_apb_hz(s, 2), APB1_MAX / 1000u, APB2_MAX / 1000u);
    check(clock_apb_hz(s, 1) == apb1 && clock_apb_hz(s, 2) == apb2, what);

    s = run(0, 1, 0, 0);
    snprintf(what, sizeof what, "no HSE answers: PLL from the HSI, SYSCLK %u Hz, HSE off again",
             (unsigned)clock_sysclk_hz(s));
    check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && pll_hz() == want_hz &&
              !(m.r[CR] & (RCC_CR_HSEON | RCC_CR_HSEBYP)) && !(m.r[PLLCFGR] & RCC_PLLCFGR_SRC_HSE) && !m.fault[0],
          what);
    check_input("the 16 MHz HSI");
#if STM32_HSE_MHZ
    /* a crystal in bypass mode does not oscillate; a clock signal wants
     * the bypass: the HSE= choice has to match the board */
    s = run(2, 1, 0, 0);
    snprintf(what, sizeof what, "the board has %s, not the %s built for: the HSE never starts, PLL from the HSI, "
             "and the line names HSE=", STM32_HSE_BYPASS ? "a crystal" : "a clock signal",
             STM32_HSE_BYPASS ? "clock (bypass)" : "crystal");
    check(s == CLOCK_PLL_HSI && clock_sysclk_hz(s) == want_hz && !(m.r[CR] & RCC_CR_HSEON) &&
              strstr(clock_report(), "HSE=crystal|bypass") && !m.fault[0],
          what);
#endif

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

    /* The console: BRR for the build's BAUD from the clock the USART ends
     * up on, and which rates fit at that clock, against RM0090's USARTDIV */
    uint32_t usart_hz = STM32_USART == 1 ? apb2 : apb1;
    unsigned brr;
    double actual;
    int fits = baud_fits_rm(usart_hz, STM32_BAUD, &brr, &actual);
    snprintf(what, sizeof what, "BAUD %u from USART%u's %g MHz: BRR %u (%u + %u/16) as RM0090's USARTDIV, %.0f baud, "
             "%.2f%% off: fits", STM32_BAUD, STM32_USART, usart_hz / 1e6, (unsigned)USART_BRR_OF(usart_hz, STM32_BAUD),
             brr >> 4, brr & 15u, actual, (actual > STM32_BAUD ? actual - STM32_BAUD : STM32_BAUD - actual) / STM32_BAUD * 100);
    check(fits && USART_BRR_OF(usart_hz, STM32_BAUD) == brr && USART_BAUD_FITS(usart_hz, STM32_BAUD) &&
              usart_hz == STM32_USART_HZ,
          what);
    static const uint32_t rates[] = { 1200,    9600,    115200,  230400,  460800,  921600,  1000000, 1500000,
                                      2000000, 3000000, 3686400, 4000000, 4800000, 5000000, 6000000, 7000000 };
    char fit[200] = "", misfit[200] = "";
    int agree = 1;
    for (size_t i = 0; i < sizeof rates / sizeof rates[0]; i++) {
        for (unsigned bus = 1; bus <= 2; bus++) {
            uint32_t hz = bus == 1 ? apb1 : apb2;
            int rm = baud_fits_rm(hz, rates[i], &brr, &actual);
            agree &= rm == USART_BAUD_FITS(hz, rates[i]) && (!rm || USART_BRR_OF(hz, rates[i]) == brr);
            if (hz == usart_hz) {
                char *list = rm ? fit : misfit;
                snprintf(list + strlen(list), sizeof fit - strlen(list), "%s%u", list[0] ? " " : "",
                         (unsigned)rates[i]);
            }
        }
    }
    snprintf(what, sizeof what, "USART%u at %g MHz: fit %s; refused %s; as RM0090's USARTDIV says, on both buses",
             STM32_USART, usart_hz / 1e6, fit, misfit);
    check(agree && USART_BAUD_FITS(usart_hz, 115200u) && USART_BAUD_FITS(usart_hz, 921600u) &&
              USART_BAUD_FITS(usart_hz, 2000000u),
          what);

    printf("stm32f4-clock: %d passed, %d failed\n", pass, fail);
    return fail != 0;
}
