/* uart.c - CMSDK APB UART0 at 0x40004000, transmit only. */
#include "board.h"

#define UART0_BASE 0x40004000u
#define UART_DATA (*(volatile uint32_t *)(UART0_BASE + 0x00))
#define UART_STATE (*(volatile uint32_t *)(UART0_BASE + 0x04))
#define UART_CTRL (*(volatile uint32_t *)(UART0_BASE + 0x08))
#define UART_BAUDDIV (*(volatile uint32_t *)(UART0_BASE + 0x10))

#define STATE_TX_FULL 1u
#define CTRL_TX_ENABLE 1u

void uart_init(void)
{
    UART_BAUDDIV = 16; /* the minimum the model accepts; QEMU ignores the rate */
    UART_CTRL = CTRL_TX_ENABLE;
}

void uart_write(const void *data, size_t len)
{
    const uint8_t *p = data;
    for (size_t i = 0; i < len; i++) {
        while (UART_STATE & STATE_TX_FULL)
            ;
        UART_DATA = p[i];
    }
}
