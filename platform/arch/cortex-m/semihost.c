/* semihost.c - port_exit for every Cortex-M port: the exit status goes
 * to QEMU through ARM semihosting (SYS_EXIT_EXTENDED; QEMU needs
 * -semihosting-config enable=on,target=native). */
#include "port.h"

#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

void port_exit(int status)
{
    volatile uint32_t block[2] = { ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status };
    register uint32_t r0 __asm__("r0") = SYS_EXIT_EXTENDED;
    register volatile uint32_t *r1 __asm__("r1") = block;
    __asm__ volatile("bkpt 0xab" : : "r"(r0), "r"(r1) : "memory");
    for (;;)
        ;
}
