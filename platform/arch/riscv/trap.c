/*
 * trap.c - the fault report of every RISC-V port: start.S sends every
 * trap here (this firmware enables no interrupt, so each one is a fault:
 * a load or store where no memory is, such as past the end of RAM, an
 * illegal instruction, ...). It reports the cause (mcause), the faulting
 * pc (mepc) and mtval, and exits with status 4.
 */
#include "port.h"

void trap_c(void) __attribute__((noreturn, used));

static char *put_hex(char *p, const char *label, uint32_t v)
{
    while (*label)
        *p++ = *label++;
    *p++ = '0';
    *p++ = 'x';
    for (int shift = 28; shift >= 0; shift -= 4)
        *p++ = "0123456789abcdef"[(v >> shift) & 15u];
    return p;
}

void trap_c(void)
{
    uint32_t cause, epc, tval;
    __asm__ volatile("csrr %0, mcause" : "=r"(cause));
    __asm__ volatile("csrr %0, mepc" : "=r"(epc));
    __asm__ volatile("csrr %0, mtval" : "=r"(tval));
    char text[64];
    char *p = put_hex(text, "fault: mcause ", cause);
    p = put_hex(p, " mepc ", epc);
    p = put_hex(p, " mtval ", tval);
    *p = '\0';
    report_text(text);
    port_exit(4);
}
