/*
 * board.c - the LM3S6965 evaluation board's side of the port contract
 * (port.h): the system clock set to 50 MHz (the chip's maximum), the
 * console on UART0 (a PL011), the instruction counter on the watchdog
 * timer. The display is oled.c.
 *
 * The instruction counter: under qemu -icount shift=0 one guest
 * instruction takes 1 ns, so at 50 MHz a timer clocked by the system
 * clock ticks exactly once per 20 instructions. SysTick has 24 bits (a
 * wrap every 335 M instructions, which one band of a slow scene can
 * exceed, and two wraps between reads look like one) and QEMU cannot read
 * the general-purpose timers' counters, so the count comes from the
 * watchdog's 32-bit down counter, run from 0xFFFFFFFF with its reset
 * disabled and its interrupt left off in the NVIC. It stops at its second
 * time-out, so the count is exact (to one tick, 20 instructions, per read)
 * up to 2^32 ticks, 85.9 G instructions after port_icount_start; past
 * that the firmware stops with an error rather than report a wrong count
 * (QEMU takes minutes to get there; a 128x64 frame takes well under 1 G).
 */
#include "../mmio.h"
#include "port.h"

/* System control */
#define SYSCTL_RIS REG(0x400FE050u) /* bit 6: PLL locked */
#define SYSCTL_RCC REG(0x400FE060u)
#define SYSCTL_RCGC1 REG(0x400FE104u) /* clock gates: bit 0 UART0, bit 4 SSI0 */
#define SYSCTL_RCGC2 REG(0x400FE108u) /* bit n: GPIO port n (A = 0) */
#define RCC_MOSCDIS (1u << 0)
#define RCC_OSCSRC (3u << 4)
#define RCC_XTAL (15u << 6)
#define RCC_XTAL_8MHZ (14u << 6) /* the board's crystal */
#define RCC_BYPASS (1u << 11)
#define RCC_PWRDN (1u << 13)
#define RCC_USESYSDIV (1u << 22)
#define RCC_SYSDIV (15u << 23)
#define RCC_SYSDIV_4 (3u << 23) /* 200 MHz PLL / 4 = 50 MHz */

/* UART0 (PL011) */
#define UART0_DR REG(0x4000C000u)
#define UART0_FR REG(0x4000C018u) /* bit 5: TX FIFO full */
#define UART0_IBRD REG(0x4000C024u)
#define UART0_FBRD REG(0x4000C028u)
#define UART0_LCRH REG(0x4000C02Cu)
#define UART0_CTL REG(0x4000C030u)

/* Watchdog: a CMSDK-style timer that counts down at the system clock */
#define WDT_LOAD REG(0x40000000u)
#define WDT_VALUE REG(0x40000004u)
#define WDT_CTL REG(0x40000008u) /* bit 0: count and interrupt; bit 1: reset */
#define WDT_RIS REG(0x40000010u) /* bit 0: timed out once */
#define WDT_LOCK REG(0x40000C00u)
#define WDT_UNLOCK 0x1ACCE551u
#define INSTRUCTIONS_PER_TICK 20u /* 1 GHz of -icount shift=0 / 50 MHz */

/* The PLL from the 8 MHz crystal, then 50 MHz (the data sheet's order:
 * bypass, power the PLL up, set the divider, wait for lock, use it). */
static void clock_50mhz(void)
{
    uint32_t rcc = SYSCTL_RCC;
    rcc = (rcc | RCC_BYPASS) & ~RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    rcc = (rcc & ~(RCC_XTAL | RCC_OSCSRC | RCC_PWRDN | RCC_MOSCDIS)) | RCC_XTAL_8MHZ;
    SYSCTL_RCC = rcc;
    rcc = (rcc & ~RCC_SYSDIV) | RCC_SYSDIV_4 | RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    for (uint32_t i = 0; i < 100000u && !(SYSCTL_RIS & (1u << 6)); i++)
        ;
    SYSCTL_RCC = rcc & ~RCC_BYPASS;
}

void port_init(void)
{
    clock_50mhz();
    SYSCTL_RCGC1 |= (1u << 0) | (1u << 4);            /* UART0, SSI0 */
    SYSCTL_RCGC2 |= (1u << 0) | (1u << 2) | (1u << 3); /* GPIO A, C, D */
    UART0_CTL = 0;
    UART0_IBRD = 1; /* QEMU ignores the rate */
    UART0_FBRD = 0;
    UART0_LCRH = 0x60;  /* 8 bits, no parity, one stop bit, no FIFO */
    UART0_CTL = 0x301;  /* RX, TX, UART enable */
}

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (UART0_FR & (1u << 5))
            ;
        UART0_DR = p[i];
    }
}

static uint32_t last_value;
static uint64_t ticks;

void port_icount_start(void)
{
    WDT_LOCK = WDT_UNLOCK;
    WDT_LOAD = 0xFFFFFFFFu; /* loads the counter */
    WDT_CTL = 1u;           /* counting; no reset, and its interrupt is off in the NVIC */
    last_value = 0xFFFFFFFFu;
    ticks = 0;
    if (WDT_VALUE == 0u) { /* not counting: a QEMU without the watchdog reads 0 */
        report_text("instruction counter: the watchdog timer does not count");
        port_exit(5);
    }
}

uint64_t port_icount_read(void)
{
    uint32_t v = WDT_VALUE;
    if (WDT_RIS & 1u) { /* timed out: the count is no longer exact */
        report_text("instruction counter: over 2^32 watchdog ticks (85.9 G instructions)");
        port_exit(5);
    }
    ticks += last_value - v; /* counts down */
    last_value = v;
    return ticks * INSTRUCTIONS_PER_TICK;
}
