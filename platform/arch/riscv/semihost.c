/* semihost.c - port_exit for every RISC-V port: the exit status goes to
 * QEMU through RISC-V semihosting (SYS_EXIT_EXTENDED; QEMU needs
 * -semihosting-config enable=on,target=native). The call is an ebreak
 * between two marker instructions, all three uncompressed and on one page
 * (the 16-byte alignment sees to that). */
#include "port.h"

#define SYS_EXIT_EXTENDED 0x20u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

void port_exit(int status)
{
    volatile uint32_t block[2] = { ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status };
    register uint32_t a0 __asm__("a0") = SYS_EXIT_EXTENDED;
    register volatile uint32_t *a1 __asm__("a1") = block;
    __asm__ volatile(".option push\n"
                     ".option norvc\n"
                     ".balign 16\n"
                     "slli zero, zero, 0x1f\n"
                     "ebreak\n"
                     "srai zero, zero, 7\n"
                     ".option pop"
                     :
                     : "r"(a0), "r"(a1)
                     : "memory");
    for (;;)
        ;
}
