/*
 * board.h - what the MPS2 AN385 port offers its own firmware: UART0 out,
 * an instruction counter, stack measurement and exit. Only this folder
 * includes it; the core never does.
 */
#ifndef BOARD_H
#define BOARD_H

#include <stddef.h>
#include <stdint.h>

void uart_init(void);
void uart_write(const void *data, size_t len);

/* Guest instructions since icount_start(), exact under QEMU's
 * -icount shift=0 (timer 0 ticks once per 40 instructions). */
void icount_start(void);
uint64_t icount_read(void);

/* Deepest stack use so far, from the paint left by the reset handler. */
uint32_t stack_high_water(void);
uint32_t stack_size(void);
int stack_guard_intact(void);

/* Ends the QEMU run with this exit status (semihosting). */
void board_exit(int status) __attribute__((noreturn));

#endif
