/*
 * mmio.h - a memory-mapped register as every port reads and writes one:
 * REG(addr) is the 32-bit word at that address, volatile so that each
 * access reaches the bus, in program order, and none is merged or left
 * out. One definition for every board and architecture (Cortex-M and
 * RISC-V alike).
 */
#ifndef PLATFORM_MMIO_H
#define PLATFORM_MMIO_H

#include <stdint.h>

#define REG(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

#endif
