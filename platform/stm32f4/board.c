/*
 * board.c - the STM32F4's side of the port contract (port.h), for the
 * chip; the same image runs under QEMU's netduinoplus2.
 *
 *  - Clocks (clock.c): the PLL from the crystal, or from the HSI when
 *    no crystal answers, to the variant's SYSCLK (168, 100 or 84 MHz),
 *    with the voltage scale, flash wait states, prefetch (not on a
 *    revision A F405/F407) and caches set first. When the PLL does not
 *    lock or SYSCLK does not switch (QEMU, whose RCC reads 0), the
 *    render runs on at the reset clock, HSI 16 MHz, and the report says
 *    so.
 *  - Console: USART1 on PA9 (TX) and PA10 (RX), or USART2 on PA2/PA3
 *    (STM32_USART=2: a Nucleo's ST-LINK), alternate function 7,
 *    STM32_BAUD 8N1 from the APB clock it ended up with. The bytes sent
 *    are counted: the report gives them and the rate, so the time the
 *    picture takes on the wire can be told from the render's.
 *  - Counting: DWT's CYCCNT counts core cycles on the chip. Under QEMU
 *    it stays 0; TIM2, which there advances one tick per instruction
 *    under -icount shift=0, counts instructions instead. Which one runs
 *    is found at start (port_counts_*), and the report names it. Both
 *    are 32 bits: SysTick's interrupt, every 2^24 core clocks, folds
 *    them into 64-bit totals.
 *  - The user LED (STM32_LED_PORT, STM32_LED_PIN, lit by a low pin with
 *    STM32_LED_ACTIVE_LOW) toggles at each band, then stays on when the
 *    run ended well, off when it did not.
 *  - The end: the clock, the counter and the exit status as the last
 *    report lines, the USART drained, then the core sleeps (WFI) with
 *    interrupts off. No semihosting: on a board with no debugger a BKPT
 *    would be a HardFault.
 */
#include "../arch/cortex-m/systick.h"
#include "../mmio.h"
#include "clock.h"
#include "port.h"
#include "sink.h"

#ifndef STM32_LED_PORT /* a letter, 'A'..'I'; 0: no LED */
#define STM32_LED_PORT 'D'
#define STM32_LED_PIN 12
#endif
#ifndef STM32_LED_ACTIVE_LOW
#define STM32_LED_ACTIVE_LOW 0
#endif

/* GPIO: port n ('A' + n) at 0x40020000 + 0x400 n; its clock is RCC_AHB1ENR bit n */
#define GPIO(port) (0x40020000u + 0x400u * (uint32_t)((port) - 'A'))
#define GPIO_MODER(base) REG((base) + 0x00u)
#define GPIO_ODR(base) REG((base) + 0x14u)
#define GPIO_BSRR(base) REG((base) + 0x18u)
#define GPIO_AFR(base, pin) REG((base) + 0x20u + 4u * ((pin) / 8u))
#define GPIO_MODE_OUTPUT 1u
#define GPIO_MODE_AF 2u
#define AF_USART 7u

/* USART1 on APB2 (PA9, PA10) or USART2 on APB1 (PA2, PA3) */
#if STM32_USART == 1
#define USART 0x40011000u
#define USART_APB 2
#define USART_TX_PIN 9u
#define USART_RX_PIN 10u
#else
#define USART 0x40004400u
#define USART_APB 1
#define USART_TX_PIN 2u
#define USART_RX_PIN 3u
#endif
#define USART_SR REG(USART + 0x00u)
#define USART_DR REG(USART + 0x04u)
#define USART_BRR REG(USART + 0x08u)
#define USART_CR1 REG(USART + 0x0cu)
#define USART_SR_TC (1u << 6)
#define USART_SR_TXE (1u << 7)
#define USART_CR1_UE (1u << 13)
#define USART_CR1_TE (1u << 3)
#define USART_CR1_RE (1u << 2)
#ifdef STM32_USART_HZ /* board.mk refused a BAUD that does not fit; this is a backstop */
_Static_assert(USART_BAUD_FITS(STM32_USART_HZ, STM32_BAUD), "BAUD within 2% from the console's clock");
#endif

/* DWT's cycle counter, TIM2 (32 bits); SysTick folds them (systick.h) */
#define DEMCR REG(0xe000edfcu)
#define DEMCR_TRCENA (1u << 24)
#define DWT_CTRL REG(0xe0001000u)
#define DWT_CYCCNT REG(0xe0001004u)
#define DWT_CTRL_CYCCNTENA (1u << 0)
#define TIM2_CR1 REG(0x40000000u)
#define TIM2_EGR REG(0x40000014u)
#define TIM2_CNT REG(0x40000024u)
#define TIM2_PSC REG(0x40000028u)
#define TIM2_ARR REG(0x4000002cu)

static clock_source_t clock_source;
static int cyccnt_runs;
static uint64_t uart_bytes; /* sent so far */

static void pin_mode(uint32_t gpio, uint32_t pin, uint32_t mode)
{
    GPIO_MODER(gpio) = (GPIO_MODER(gpio) & ~(3u << 2u * pin)) | mode << 2u * pin;
}

static void usart_init(void)
{
#if STM32_USART == 1
    RCC_APB2ENR |= RCC_APB2ENR_USART1;
#else
    RCC_APB1ENR |= RCC_APB1ENR_USART2;
#endif
    RCC_AHB1ENR |= 1u << 0; /* GPIOA */
    (void)RCC_AHB1ENR;      /* (two clocks before the port answers) */
    uint32_t gpio = GPIO('A');
    GPIO_AFR(gpio, USART_TX_PIN) = (GPIO_AFR(gpio, USART_TX_PIN) & ~(15u << 4u * (USART_TX_PIN % 8u))) |
                                   AF_USART << 4u * (USART_TX_PIN % 8u);
    GPIO_AFR(gpio, USART_RX_PIN) = (GPIO_AFR(gpio, USART_RX_PIN) & ~(15u << 4u * (USART_RX_PIN % 8u))) |
                                   AF_USART << 4u * (USART_RX_PIN % 8u);
    pin_mode(gpio, USART_TX_PIN, GPIO_MODE_AF);
    pin_mode(gpio, USART_RX_PIN, GPIO_MODE_AF);
    USART_BRR = USART_BRR_OF(clock_apb_hz(clock_source, USART_APB), STM32_BAUD);
    USART_CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE;
}

static void led_set(int on)
{
#if STM32_LED_PORT
    int high = on != STM32_LED_ACTIVE_LOW;
    GPIO_BSRR(GPIO(STM32_LED_PORT)) = 1u << (STM32_LED_PIN + (high ? 0u : 16u)); /* set, or reset */
#else
    (void)on;
#endif
}

/* off before the pin drives it (an active-low LED would light at once) */
static void led_init(void)
{
#if STM32_LED_PORT
    RCC_AHB1ENR |= 1u << (STM32_LED_PORT - 'A');
    (void)RCC_AHB1ENR;
    led_set(0);
    pin_mode(GPIO(STM32_LED_PORT), STM32_LED_PIN, GPIO_MODE_OUTPUT);
#endif
}

void port_heartbeat(void)
{
#if STM32_LED_PORT
    GPIO_ODR(GPIO(STM32_LED_PORT)) ^= 1u << STM32_LED_PIN;
#endif
}

/* ---- counters: 32-bit hardware counts folded into 64-bit totals ---------- */

typedef struct {
    uint64_t total;
    uint32_t last;
} count64_t;

static count64_t cycles64, instr64;

static uint64_t fold(count64_t *c, uint32_t now)
{
    c->total += now - c->last;
    c->last = now;
    return c->total;
}

/* (interrupts off: SysTick folds the same totals) */
static uint64_t fold_now(count64_t *c, const volatile uint32_t *counter)
{
    uint32_t primask;
    __asm__ volatile("mrs %0, primask\n cpsid i" : "=r"(primask) : : "memory");
    uint64_t v = fold(c, *counter);
    __asm__ volatile("msr primask, %0" : : "r"(primask) : "memory");
    return v;
}

/* every 2^24 core clocks, well inside either counter's 2^32 */
void SysTick_Handler(void)
{
    fold(&cycles64, DWT_CYCCNT);
    fold(&instr64, TIM2_CNT);
}

static void counters_init(void)
{
    DEMCR |= DEMCR_TRCENA;
    DWT_CYCCNT = 0;
    DWT_CTRL |= DWT_CTRL_CYCCNTENA;
    __asm__ volatile("nop\n nop\n nop\n nop" ::: "memory");
    cyccnt_runs = DWT_CYCCNT != 0;
    RCC_APB1ENR |= RCC_APB1ENR_TIM2;
    (void)RCC_APB1ENR;
    TIM2_PSC = 0;
    TIM2_ARR = 0xffffffffu;
    TIM2_EGR = 1u; /* load the prescaler */
    TIM2_CR1 = 1u; /* count */
    systick_start_wrapping();
}

/* CYCCNT on the chip; under QEMU it stays 0, and TIM2 counts
 * instructions (one tick each under -icount shift=0). On the chip TIM2
 * counts APB1 timer clocks, not instructions, so it is not reported. */
int port_counts_cycles(void) { return cyccnt_runs; }
int port_counts_instructions(void) { return !cyccnt_runs; }

uint64_t port_cycles_read(void) { return fold_now(&cycles64, &DWT_CYCCNT); }
/* TIM2 already runs (counters_init, from port_init) and the firmware only
 * subtracts two reads of it, so there is nothing to start */
void port_icount_start(void) {}
uint64_t port_icount_read(void) { return fold_now(&instr64, &TIM2_CNT); }

/* ---- the port ------------------------------------------------------------- */

void port_init(void)
{
    clock_source = clocks_init();
    usart_init();
    led_init();
    counters_init();
}

void port_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (!(USART_SR & USART_SR_TXE))
            ;
        USART_DR = p[i];
    }
    uart_bytes += len;
}

void port_exit(int status)
{
    /* after the frame, as the Pico's: the console's rate and the bytes
     * it carried up to here (the frame's records, the report lines), the
     * clock the render ran at and how it was counted, then the status,
     * the last line */
    report_value("uart_baud", STM32_BAUD);
    report_value("uart_bytes", uart_bytes);
    report_value("sysclk_hz", clock_sysclk_hz(clock_source));
    report_text(clock_report());
    report_text(cyccnt_runs ? "counter: DWT CYCCNT, core cycles"
                            : "counter: TIM2, instructions (DWT CYCCNT reads 0: an emulator; TIM2 advances one tick an "
                              "instruction under QEMU -icount shift=0)");
    report_value("exit_status", (uint64_t)(uint32_t)status);
    for (uint32_t n = 0; n < WAIT_POLLS && !(USART_SR & USART_SR_TC); n++)
        ;
    systick_stop();
    led_set(status == 0);
    __asm__ volatile("cpsid i" : : : "memory");
    for (;;)
        __asm__ volatile("wfi");
}
