/*
 * port.h - the port contract: what a board folder (platform/<board>/)
 * gives the board-independent firmware in platform/firmware/.
 *
 * A port provides, in its own files:
 *   - start-up: a reset entry that copies .data, zeroes .bss, enables
 *     what C needs (the FPU on a hard-float build), calls main() and
 *     passes its result to port_exit() (platform/arch/<arch>/ has one
 *     per architecture, so a board usually writes none);
 *   - port_init(), port_write(): console bytes out, binary-safe;
 *   - port_icount_start(), port_icount_read(): an instruction counter;
 *   - port_exit(): end the run with a status (semihosting under QEMU;
 *     in platform/arch/<arch>/ as well);
 *   - a linker script that defines MEMORY and includes
 *     platform/firmware/sections.ld (which defines the symbols below);
 *   - board.mk: CPU flags, QEMU command, clock, backends (README,
 *     "Adding a board").
 * Only platform/ includes this header; the core never does.
 */
#ifndef PORT_H
#define PORT_H

#include <stddef.h>
#include <stdint.h>

/* Console ready for port_write (and whatever else the board must set up
 * before the firmware runs). */
void port_init(void);
/* len bytes to the console, blocking; every byte value passes unchanged. */
void port_write(const void *data, size_t len);

/* Guest instructions since port_icount_start(), exact under QEMU's
 * -icount shift=0 (each port says how it counts). */
void port_icount_start(void);
uint64_t port_icount_read(void);

/* Ends the run with this exit status. */
void port_exit(int status) __attribute__((noreturn));

/* ---- provided by platform/firmware/ for the port ------------------------ */

/* The stack region of sections.ld: painted at start, measured after. */
void stack_paint(void);
uint32_t stack_high_water(void);
uint32_t stack_size(void);
int stack_guard_intact(void);

/* A record of report text on the console ('T' record of sink.h's stream
 * format), for fault handlers and ports. */
void report_text(const char *text);

#endif
