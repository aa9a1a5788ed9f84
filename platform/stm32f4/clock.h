/*
 * clock.h - the STM32F4's clock tree (clock.c) and the RCC registers
 * board.c shares with it. Apart from board.c so that a host test
 * (tests/boards/stm32f4_clock_test.c) can run it against a model of RCC and
 * FLASH: STM32_REG, when defined, replaces the register access (by
 * default mmio.h's REG, as everywhere else).
 */
#ifndef STM32F4_CLOCK_H
#define STM32F4_CLOCK_H

#include <stdint.h>

#include "../mmio.h"

#ifndef STM32_REG
#define STM32_REG(addr) REG(addr)
#endif

/* The variant's choices (board.mk's table passes them; these defaults
 * are the f405 row's) */
#ifndef STM32_CHIP /* whose limits apply: 405 (F405/F407), 401, 411 */
#define STM32_CHIP 405
#endif
#ifndef STM32_SYSCLK_MHZ /* 168, 100 or 84 */
#define STM32_SYSCLK_MHZ 168
#endif
#ifndef STM32_HSE_MHZ /* the crystal; 0: none */
#define STM32_HSE_MHZ 8
#endif
#ifndef STM32_HSE_BYPASS /* 1: driven by a clock (a Nucleo's ST-LINK), not a crystal */
#define STM32_HSE_BYPASS 0
#endif
#ifndef STM32_USART /* the console: USART1 (on APB2) or USART2 (on APB1) */
#define STM32_USART 1
#endif
#ifndef STM32_BAUD
#define STM32_BAUD 115200
#endif

/* The USART's divider, 16x oversampling (OVER8 0): USARTDIV = f / (16
 * baud) in 1/16ths, so BRR = f / baud, rounded (mantissa in bits 15:4,
 * fraction in 3:0). BRR 16 (USARTDIV 1) to 65535. */
#define USART_BRR_OF(hz, baud) (((hz) + (baud) / 2u) / (baud))
/* How far the rate BRR gives is from `baud`, in parts per million */
#define USART_PPM_OFF(hz, baud)                                                                                       \
    ((unsigned long long)((hz) > USART_BRR_OF(hz, baud) * (baud) ? (hz) - USART_BRR_OF(hz, baud) * (baud)            \
                                                                    : USART_BRR_OF(hz, baud) * (baud) - (hz)) *        \
     1000000ull / ((unsigned long long)USART_BRR_OF(hz, baud) * (baud)))
/* What BAUD= may be (board.mk refuses the rest with the same rule): BRR
 * in range and the rate within 2% (the receiver tolerates 3.41% with a
 * fractional divider, both ends' errors together) */
#define USART_BAUD_MAX_PPM 20000u
#define USART_BAUD_FITS(hz, baud)                                                                                     \
    (USART_BRR_OF(hz, baud) >= 16u && USART_BRR_OF(hz, baud) <= 0xffffu &&                                             \
     USART_PPM_OFF(hz, baud) <= USART_BAUD_MAX_PPM)

/* RCC: what the clock tree and the peripherals' clock enables use */
#define RCC_CR STM32_REG(0x40023800u)
#define RCC_PLLCFGR STM32_REG(0x40023804u)
#define RCC_CFGR STM32_REG(0x40023808u)
#define RCC_AHB1ENR STM32_REG(0x40023830u)
#define RCC_APB1ENR STM32_REG(0x40023840u)
#define RCC_APB2ENR STM32_REG(0x40023844u)
#define RCC_CR_HSEON (1u << 16)
#define RCC_CR_HSERDY (1u << 17)
#define RCC_CR_HSEBYP (1u << 18)
#define RCC_CR_PLLON (1u << 24)
#define RCC_CR_PLLRDY (1u << 25)
#define RCC_PLLCFGR_SRC_HSE (1u << 22)
#define RCC_CFGR_SW_PLL 2u
#define RCC_CFGR_SWS_MASK (3u << 2)
#define RCC_CFGR_SWS_PLL (2u << 2)
#define RCC_CFGR_PPRE1_DIV2 (4u << 10)
#define RCC_CFGR_PPRE1_DIV4 (5u << 10)
#define RCC_CFGR_PPRE2_DIV2 (4u << 13)
#define RCC_APB1ENR_TIM2 (1u << 0)
#define RCC_APB1ENR_USART2 (1u << 17)
#define RCC_APB1ENR_PWR (1u << 28)
#define RCC_APB2ENR_USART1 (1u << 4)

/* PWR_CR: the regulator's voltage scale (VOS, bits 15:14) */
#define PWR_CR STM32_REG(0x40007000u)
#define PWR_CR_VOS_SHIFT 14
#define PWR_CR_VOS_MASK (3u << PWR_CR_VOS_SHIFT)

/* FLASH_ACR: wait states, prefetch, instruction and data caches */
#define FLASH_ACR STM32_REG(0x40023c00u)
#define FLASH_ACR_LATENCY_MASK 0xfu
#define FLASH_ACR_PRFTEN (1u << 8)
#define FLASH_ACR_ICEN (1u << 9)
#define FLASH_ACR_DCEN (1u << 10)

/* DBGMCU_IDCODE: DEV_ID in bits 11:0, REV_ID in bits 31:16 (in the
 * private peripheral bus: readable without a clock enable) */
#define DBGMCU_IDCODE STM32_REG(0xe0042000u)

/* Polls before a wait gives up: the crystal's start-up is 2 ms at most
 * (about 8,000 polls at 16 MHz); the PLL locks in 0.1 ms. */
#define WAIT_POLLS 200000u

#define HSI_MHZ 16u

typedef enum { CLOCK_PLL_HSE, CLOCK_PLL_HSI, CLOCK_HSI } clock_source_t;

/* The PLL from the crystal, or from the HSI when the crystal does not
 * start; the voltage scale (F401, F411), flash wait states, prefetch (not on a revision A F405/F407) and
 * caches, the APB dividers, then SYSCLK onto the PLL. Every wait
 * bounded; on failure SYSCLK stays on the HSI, where reset left it.
 * Returns where it ended. */
clock_source_t clocks_init(void);

/* SYSCLK, and the clock of APB bus 1 or 2, in Hz, once clocks_init()
 * has returned `source` */
uint32_t clock_sysclk_hz(clock_source_t source);
uint32_t clock_apb_hz(clock_source_t source, unsigned bus);

/* The report's line on the clock tree: where it ended, and why */
const char *clock_report(void);

#endif
