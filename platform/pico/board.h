/*
 * board.h - what board.c gives the Pico's display sink (st7789.c): the
 * clock it set, its cycle counter and its microseconds, taking blocks out
 * of reset (its LED is port.h's port_heartbeat).
 */
#ifndef PICO_BOARD_H
#define PICO_BOARD_H

#include <stdint.h>

#define CLK_SYS_HZ 125000000u /* clk_sys and clk_peri, once port_init() is done */

/* Takes `blocks` out of reset and waits (bounded) until they are; on
 * expiry reports `what` and ends the run with status 5. */
void board_unreset(uint32_t blocks, const char *what);

/* clk_sys cycles since port_init() started the calling core's SysTick:
 * each core its own count, so a difference holds only on one core. */
uint64_t board_cycles(void);

/* Microseconds by the TIMER (port_init() started its tick): one count
 * for both cores, for a time that may start on one and end on the other.
 * Differences modulo 2^32. */
uint32_t board_us(void);

/* Progressive display: pass `pass` is on the panel, its last byte sent
 * (st7789.c). Does nothing; run.mjs watches its address to take the
 * panel's picture and the time of each pass. */
void board_pass_shown(unsigned pass);

#endif
