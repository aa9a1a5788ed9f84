/*
 * boot2.S - our second-stage boot for the RP2040: generic, serial 03h
 * reads, which every SPI flash answers.
 *
 * The boot ROM reads the first 256 bytes of flash, checks the CRC-32 of
 * bytes 0..251 against bytes 252..255, copies the 256 bytes to SRAM at
 * 0x20041f00 and branches there (thumb bit set, SP = 0x20042000). This
 * code runs from that copy: it sets up the SSI (base 0x18000000, a
 * Synopsys DW_apb_ssi) for execute-in-place with plain 03h reads, then
 * starts the image through its vector table at 0x10000100.
 *
 * Built on its own (at most 252 bytes of code), then padded and given its
 * CRC by `tools/emu/pico/uf2.mjs boot2`, which writes the .boot2
 * section the firmware links at 0x10000000:
 *   arm-none-eabi-gcc -mcpu=cortex-m0plus -mthumb -nostdlib -nostartfiles \
 *       -Wl,-Ttext=0x20041f00 -o boot2.elf platform/pico/boot2.S
 *   arm-none-eabi-objcopy -O binary boot2.elf boot2.bin
 *   node tools/emu/pico/uf2.mjs boot2 boot2.bin boot2_crc.S
 *
 * Register offsets and field positions are from the RP2040 datasheet's
 * SSI register description (DW_apb_ssi), also in its SVD:
 *   CTRLR0 +0x00: SPI_FRF 22:21 (0 standard, 1 dual, 2 quad), DFS_32
 *     20:16 (frame size - 1), TMOD 9:8 (3 = EEPROM read: send the
 *     command and address, then receive); written only while disabled
 *   CTRLR1 +0x04: NDF 15:0 (frames to receive - 1)
 *   SSIENR +0x08: SSI_EN bit 0
 *   BAUDR +0x14: SCKDV 15:0, an even divider of clk_sys (bit 0 reads 0)
 *   RX_SAMPLE_DLY +0xf0: RSD 7:0, receive sample delay (clk_sys cycles)
 *   SPI_CTRLR0 +0xf4: XIP_CMD 31:24 (the command XIP sends), WAIT_CYCLES
 *     15:11, INST_L 9:8 (2 = 8-bit instruction), ADDR_L 5:2 (address
 *     length in 4-bit units: 6 = 24 bits), TRANS_TYPE 1:0 (0 = command
 *     and address both in standard SPI)
 *
 * Clock: BAUDR 4 gives flash SCK = clk_sys / 4: about 1.6 MHz from the
 * ring oscillator here, 31.25 MHz once the firmware runs clk_sys at
 * 125 MHz, within the 50 MHz that 03h (Read Data, no dummy cycles) allows
 * on the Winbond W25Q parts. Slow but safe; the quad-I/O EBh read the
 * Pico's flash also supports is not used.
 *
 * Written from the datasheet facts above, not copied from any SDK boot2.
 */
    .syntax unified
    .cpu cortex-m0plus
    .thumb

    .equ SSI_BASE,          0x18000000
    .equ SSI_CTRLR0,        0x00
    .equ SSI_CTRLR1,        0x04
    .equ SSI_SSIENR,        0x08
    .equ SSI_BAUDR,         0x14
    .equ SSI_RX_SAMPLE_DLY, 0xf0
    .equ SSI_SPI_CTRLR0,    0xf4

    .equ CLKDIV,            4
    /* CTRLR0: SPI_FRF 0 (standard), DFS_32 31 (32-bit frames), TMOD 3 */
    .equ CTRLR0_XIP,        (0 << 21) | (31 << 16) | (3 << 8)
    /* SPI_CTRLR0: XIP_CMD 03h, WAIT_CYCLES 0, INST_L 2 (8 bits),
       ADDR_L 6 (24 bits), TRANS_TYPE 0 (command and address standard) */
    .equ SPI_CTRLR0_XIP,    (0x03 << 24) | (0 << 11) | (2 << 8) | (6 << 2) | 0

    .equ PPB_VTOR,          0xe000ed08
    .equ IMAGE_VECTORS,     0x10000100  /* boot2 takes flash 0x10000000..0x100000ff */

    .text
    .global _start
    .type _start, %function
    .thumb_func
_start:
    ldr r3, =SSI_BASE
    movs r0, #0
    str r0, [r3, #SSI_SSIENR]       /* disable: the set-up registers are writable only so */
    movs r1, #CLKDIV
    str r1, [r3, #SSI_BAUDR]
    ldr r1, =CTRLR0_XIP
    str r1, [r3, #SSI_CTRLR0]
    str r0, [r3, #SSI_CTRLR1]       /* NDF 0 */
    movs r2, #SSI_RX_SAMPLE_DLY     /* beyond str's immediate reach: register offset */
    str r0, [r3, r2]                /* sample at the nominal edge (ample at SCK = clk_sys/4) */
    adds r2, #(SSI_SPI_CTRLR0 - SSI_RX_SAMPLE_DLY)
    ldr r1, =SPI_CTRLR0_XIP
    str r1, [r3, r2]
    movs r1, #1
    str r1, [r3, #SSI_SSIENR]       /* enable: XIP reads of 0x10000000.. now work */

    /* Start the image as a reset would: vector table, stack, entry. */
    ldr r0, =IMAGE_VECTORS
    ldr r1, =PPB_VTOR
    str r0, [r1]
    ldmia r0!, {r1, r2}             /* r1 = initial SP, r2 = reset vector (thumb bit set) */
    msr msp, r1
    bx r2

    .ltorg
    .size _start, . - _start
