/* stm32f4_fault.c - for tests/boards/board-stm32f4-tests.sh: a main() that reads
 * the F405's CCM RAM, which QEMU does not model (a BusFault there), linked
 * with the board's own start-up and port_exit: the fault must end the run
 * with status 4 and its report line, never a hang. */
int main(void);

int main(void) { return *(volatile int *)0x10000000; }
