#!/usr/bin/env node
// run.mjs - runs the Pico firmware under rp2040js (the RP2040 emulator;
// pinned in package.json, installed into node_modules/ by npm ci), booted
// the way the chip boots it.
//
//   node run.mjs [--module PANEL[,flip]] [--no-crystal] [--xip-model] FIRMWARE.elf OUT.png RT [CLOCK_HZ]
//       Flash holds FIRMWARE.uf2 (beside the ELF, checked block by block
//       by uf2.mjs); the ELF is read only for its symbols (and compared
//       with the UF2, so that a stale UF2 is caught). Boots as the boot
//       ROM does: the CRC-32 of flash bytes 0..251 must match bytes
//       252..255 (else the chip drops into USB boot and nothing runs), the
//       256 bytes go to SRAM 0x20041f00, SP = 0x20042000, and boot2 runs
//       from there: it sets the SSI up for execute-in-place and starts the
//       vector table at 0x10000100. Both cores (core 1 in the boot ROM's
//       wait for its launch: core1.mjs). UART0 goes to FIRMWARE.serial,
//       what SPI0 sends (each byte with the data/command line, GP16) to
//       FIRMWARE.spi. The run ends when both cores sleep (WFI, WFE) with
//       nothing left that could wake them. Prints the report (RT
//       receive) and writes OUT.png: from the UART stream when the console
//       opens with a frame (the stream sink), else from the panel (the
//       ST7789 sink, whose report gives frame_width and frame_height): the
//       frame centred on the module's picture, every other pixel of which
//       must be black (the firmware clears the panel first); the whole
//       picture goes to FIRMWARE.panel.stream (rt's stream format), the
//       frame to OUT.png.
//       Then the runner's own counts of the render (below), for a panel
//       frame_cycles (the render's start to the panel's last byte, SPI
//       bytes timed at SPI0's clock: makePanelClock) and, with progressive
//       display, first_picture_cycles (to pass 1's last byte) and the
//       panel's frame after each pass in FIRMWARE.passN.stream (taken
//       where the firmware calls board_pass_shown), the clocks at the
//       end, the render's time at CLOCK_HZ from the firmware's
//       render_cycles, and the host's wall time. The firmware's own
//       frame_ms and first_picture_us (the TIMER's microseconds) are
//       compared with the runner's count of the same events
//       (emulator_frame_us, emulator_first_picture_us, which also says
//       which core ended pass 1): over 2% apart, beyond the report's
//       rounding, fails.
//       --module: the panel module on the pins (st7789.mjs's PANELS,
//       320x240 by default; ",flip": turned by 180 degrees), which the
//       decoder takes as the glass the picture is seen through.
//       --no-crystal: XOSC never reports stable, as on a board whose
//       crystal does not start (the firmware must say so and stop).
//       --xip-model: counts the render's flash reads through a model of
//       the XIP cache (16 KiB, two ways, 8-byte lines, LRU), and the misses
//       it would have with its code and scene tables in flash (slower).
//       Also prints the LED's (GP25) state at the end.
//   node run.mjs --panel FIRMWARE.spi W H OUT.stream [PANEL [FLIP]]
//       Only the panel's decoding: the WxH frame centred on the module's
//       picture, the rest checked black, as an rgb565be frame in rt's
//       stream format (app/firmware/sink.h).
//
// The chip's state at boot2's start: every block of RESETS in reset but
// IO_QSPI and PADS_QSPI (the ROM's), RESET_DONE its complement; clk_sys
// and clk_ref from the ring oscillator (rp2040js's 6.5 MHz), clk_peri
// stopped; the SSI disabled. The simulation clock advances by each
// instruction's cycles at the current clk_sys, so SysTick (clocked by
// clk_sys in rp2040js as on the chip) counts core cycles at any clock.
// Sleeping (WFI) advances it to the next alarm, and the sleeping cycles
// count as cycles, as they do on SysTick.
//
// Two cores (core1.mjs has the model and what it leaves out): the core
// that has used fewer cycles steps next, core 0 on ties; a core asleep
// in WFI or WFE does not step, and one woken takes up the clock's count
// (the clock runs to the slower running core's). Core 1 starts in the
// boot ROM's wait for the launch sequence (modelled, as boot2's step
// is: no ROM is loaded). What the emulator cannot show: it is
// sequentially consistent (every store is seen by the other core at
// once, so a missing barrier cannot be caught), and the cores never
// contend for an SRAM bank (on silicon they stall each other when both
// hit one bank in one cycle: a two-core speed-up here is close to 2.0x,
// where silicon is expected near 1.85-1.95x). Failing on top of the
// single-core checks: a launch out of the datasheet's sequence, an entry
// without its Thumb bit, a vector table not aligned to 256 bytes, a
// divider result read before it is valid, and core 1 still running when
// core 0 sleeps for good after its last report line; and, when the ELF
// names its spinlock-guarded data (__spinlocked_start, __spinlocked_end),
// a core's write there holding no spinlock while core 1 runs (best effort:
// a lock is held from the read that claimed it to any write to it).
//
// Strict: what silicon would not run fails the run, naming the PC and
// what the chip would do: a peripheral of RESETS touched while in reset;
// an access where nothing is mapped; the UARTs' or SPIs' data or control
// registers written while clk_peri is stopped; a fetch or load from XIP
// flash before boot2 has set the SSI up for it (or with a set-up the flash
// model does not answer, or a flash clock over the read command's limit);
// bkpt or an undefined instruction (a HardFault on a board with no
// debugger: no semihosting); an unaligned word access; the TIMER read
// while the watchdog's tick does not give it microseconds (rp2040js
// counts them whatever the tick). The SSI here is
// our own small model, rp2040js's is a stub: standard-SPI 03h or 0Bh XIP
// reads only; quad-I/O, direct-mode transfers and flash timing are not
// modelled.
//
// Counting: the firmware reads its SysTick in port_cycles_read at the
// render's start, in pairs around each piece of display output, and at
// the render's end. The runner watches that symbol's address (from the
// ELF): each time a core is about to execute it, it records that core's
// instruction count and cycles. Render = (end - start) - the output pairs.
// It prints render_instructions, instructions_per_pixel,
// emulator_render_cycles (core 0's) and how the firmware's SysTick
// render_cycles compares (over 0.1% apart fails); core1_render_instructions
// and core1_render_cycles when core 1 calls it too; then for each core N
// coreN_instructions and coreN_cycles (cycles running, its sleep left out;
// core 1's include the ROM's wait), core1_launches, and where core 1 is
// at the end. Cycles are rp2040js's Cortex-M0+ model: no flash wait
// states, no XIP cache; the SIO divider is timed as on silicon (its
// result valid 8 cycles after the last operand write, core1.mjs), not
// charged at the write as rp2040js does.
//
// The panel decoder (st7789.mjs) is strict, so a damaged transfer gives no
// image: each fault fails with the byte offset in the SPI log.
//
// Exit status: the firmware's last report line, `exit_status N`; 1 when
// the run, the decoder or the counts fail.
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { RP2040 } from 'rp2040js';
import { ROM_END, attachCore1 } from './core1.mjs';
import { PANELS, checkBorder, decodePanel, panelStream } from './st7789.mjs';
import { BOOT2_SIZE, BOOT2_SRAM, FLASH_BASE, SRAM_BASE, SRAM_END, boot2Crc, readUf2 } from './uf2.mjs';

const PIN_DC = 16, PIN_CS = 17, PIN_SCK = 18, PIN_BACKLIGHT = 20, PIN_LED = 25;
const SPI_MAX_HZ = 62.5e6; // the ST7789's 16 ns write cycle
const WALL_LIMIT_S = 900;
const MARK_SYMBOL = 'port_cycles_read';
const GUARD_SYMBOLS = ['__spinlocked_start', '__spinlocked_end']; // the image's spinlock-guarded data
const PASS_SYMBOL = 'board_pass_shown'; // progressive display: a pass is on the panel
const SYSTICK_TOLERANCE = 0.1; // percent
const TIME_TOLERANCE = 2; // percent: the board's frame_ms and first_picture_us (TIMER) against the emulator's count
const hex = (v) => `0x${(v >>> 0).toString(16).padStart(8, '0')}`;

function fail(msg) {
  console.error(`pico run: ${msg}`);
  process.exit(1);
}

class RunFailure extends Error {}

// ---- the ELF: symbols, and its flash bytes to compare with the UF2 ----------

function readElf(path) {
  const f = readFileSync(path);
  if (f.length < 52 || f.readUInt32BE(0) !== 0x7f454c46 || f[4] !== 1 || f[5] !== 1) fail(`${path}: not a 32-bit little-endian ELF`);
  const segments = [];
  const phoff = f.readUInt32LE(0x1c), phsize = f.readUInt16LE(0x2a), phnum = f.readUInt16LE(0x2c);
  for (let i = 0; i < phnum; i++) {
    const p = phoff + i * phsize;
    const type = f.readUInt32LE(p), off = f.readUInt32LE(p + 4), paddr = f.readUInt32LE(p + 12), filesz = f.readUInt32LE(p + 16);
    if (type === 1 && filesz > 0) segments.push({ paddr, bytes: f.subarray(off, off + filesz) }); // PT_LOAD
  }
  const symbols = new Map();
  const shoff = f.readUInt32LE(0x20), shsize = f.readUInt16LE(0x2e), shnum = f.readUInt16LE(0x30);
  const sh = (i) => {
    const s = shoff + i * shsize;
    return { type: f.readUInt32LE(s + 4), offset: f.readUInt32LE(s + 16), size: f.readUInt32LE(s + 20), link: f.readUInt32LE(s + 24), entsize: f.readUInt32LE(s + 36) };
  };
  for (let i = 0; i < shnum; i++) {
    const tab = sh(i);
    if (tab.type !== 2) continue; // SHT_SYMTAB
    const str = sh(tab.link);
    for (let o = tab.offset; o + 16 <= tab.offset + tab.size; o += tab.entsize || 16) {
      const nameOff = f.readUInt32LE(o), value = f.readUInt32LE(o + 4), info = f[o + 12], shndx = f.readUInt16LE(o + 14);
      if (!nameOff || shndx === 0 || (info & 0xf) > 2) continue; // named, defined, NOTYPE/OBJECT/FUNC
      const start = str.offset + nameOff;
      const name = f.toString('latin1', start, f.indexOf(0, start));
      if (!symbols.has(name) || info >> 4 === 1) symbols.set(name, value); // prefer GLOBAL
    }
  }
  return { segments, symbols };
}

// ---- the chip around the core ----------------------------------------------

// RESETS: bit, base of each block it holds in reset.
const BLOCKS = [
  ['ADC', 0, 0x4004c000], ['BUSCTRL', 1, 0x40030000], ['DMA', 2, 0x50000000], ['I2C0', 3, 0x40044000],
  ['I2C1', 4, 0x40048000], ['IO_BANK0', 5, 0x40014000], ['IO_QSPI', 6, 0x40018000], /* JTAG 7: no registers */
  ['PADS_BANK0', 8, 0x4001c000], ['PADS_QSPI', 9, 0x40020000], ['PIO0', 10, 0x50200000], ['PIO1', 11, 0x50300000],
  ['PLL_SYS', 12, 0x40028000], ['PLL_USB', 13, 0x4002c000], ['PWM', 14, 0x40050000], ['RTC', 15, 0x4005c000],
  ['SPI0', 16, 0x4003c000], ['SPI1', 17, 0x40040000], ['SYSCFG', 18, 0x40004000], ['SYSINFO', 19, 0x40000000],
  ['TBMAN', 20, 0x4006c000], ['TIMER', 21, 0x40054000], ['UART0', 22, 0x40034000], ['UART1', 23, 0x40038000],
  ['USBCTRL', 24, 0x50110000],
];
const RESETS_ALL = 0x1ffffff;
const RESETS_AFTER_ROM = RESETS_ALL & ~(1 << 6 | 1 << 9); // the ROM takes IO_QSPI and PADS_QSPI out of reset
// registers that need clk_peri running: PL011 DR, LCR_H, CR; PL022 CR0, CR1, DR
const CLK_PERI_REGS = {
  UART0: { 0x00: 'DR', 0x2c: 'LCR_H', 0x30: 'CR' }, UART1: { 0x00: 'DR', 0x2c: 'LCR_H', 0x30: 'CR' },
  SPI0: { 0x00: 'CR0', 0x04: 'CR1', 0x08: 'DR' }, SPI1: { 0x00: 'CR0', 0x04: 'CR1', 0x08: 'DR' },
};

function atomic(cur, type, value) {
  return type === 1 ? cur ^ value : type === 2 ? cur | value : type === 3 ? cur & ~value : value;
}

function makeResets(stop) {
  return {
    reset: RESETS_AFTER_ROM,
    wdsel: 0,
    readUint32(offset) {
      switch (offset & 0xfff) {
        case 0x0: return this.reset;
        case 0x4: return this.wdsel;
        case 0x8: return ~this.reset & RESETS_ALL; // RESET_DONE
      }
      return stop(`RESETS has no register at +0x${(offset & 0xfff).toString(16)} (only RESET, WDSEL, RESET_DONE)`);
    },
    writeUint32Atomic(offset, value, type) {
      this.writeUint32(offset, type ? atomic(this.readUint32(offset), type, value) : value);
    },
    writeUint32(offset, value) {
      if (offset === 0x0) this.reset = value & RESETS_ALL;
      else if (offset === 0x4) this.wdsel = value & RESETS_ALL;
      else if (offset === 0x8) return; // RESET_DONE is read-only
      else stop(`RESETS has no register at +0x${offset.toString(16)} (only RESET, WDSEL, RESET_DONE)`);
    },
  };
}

// The SSI (DW_apb_ssi at 0x18000000) and a flash behind it that answers
// XIP reads with a standard-SPI 03h (no wait cycles) or 0Bh (8 wait
// cycles) command. Quad-I/O (SPI_FRF 2, EBh) is not modelled, nor are
// direct-mode transfers through DR0 or the flash's timing.
const SSI = { CTRLR0: 0x00, CTRLR1: 0x04, SSIENR: 0x08, BAUDR: 0x14, SR: 0x28, IDR: 0x58, VERSION: 0x5c, DR0: 0x60, RX_SAMPLE_DLY: 0xf0, SPI_CTRLR0: 0xf4 };
const SSI_NAMES = Object.fromEntries(Object.entries(SSI).map(([k, v]) => [v, k]));
const SSI_SET_UP = new Set([SSI.CTRLR0, SSI.CTRLR1, SSI.BAUDR, SSI.SPI_CTRLR0, 0x18, 0x1c]); // TXFTLR, RXFTLR too
const FLASH_SCK_MAX = { 0x03: 50e6, 0x0b: 104e6 }; // Winbond W25Q: Read Data 50 MHz, Fast Read 104 MHz and up

function makeSsi(mcu, stop, onXip) {
  const ssi = {
    regs: new Map([[SSI.SPI_CTRLR0, 0x03000000]]), // CTRLR0, BAUDR... 0; SPI_CTRLR0's reset value
    enabled: false,
    problem: 'the SSI is disabled (SSIENR 0): boot2 has not set up execute-in-place',
    reg(o) { return this.regs.get(o) ?? 0; },
    // what is wrong with the set-up for XIP reads, or null
    check() {
      const c0 = this.reg(SSI.CTRLR0), sc = this.reg(SSI.SPI_CTRLR0), div = this.reg(SSI.BAUDR) & 0xffff;
      const frf = c0 >>> 21 & 3, tmod = c0 >>> 8 & 3, dfs32 = c0 >>> 16 & 31, mot = c0 >>> 4 & 3;
      const cmd = sc >>> 24, wait = sc >>> 11 & 31, instL = sc >>> 8 & 3, addrL = sc >>> 2 & 15, trans = sc & 3;
      const x2 = (v) => `0x${v.toString(16).padStart(2, '0')}`;
      if (div < 2 || div & 1) return `BAUDR ${div}: the SSI needs an even clock divider of at least 2`;
      if (frf !== 0) return `CTRLR0 SPI_FRF ${frf} (${['standard', 'dual', 'quad', 'reserved'][frf]}): the flash model answers only standard SPI reads (quad-I/O is not modelled)`;
      if (mot !== 0) return `CTRLR0 FRF ${mot}: not Motorola SPI, which the flash speaks`;
      if (tmod !== 3) return `CTRLR0 TMOD ${tmod}: XIP needs 3 (EEPROM read: command and address out, then data in)`;
      if (dfs32 !== 31) return `CTRLR0 DFS_32 ${dfs32}: XIP needs 32-bit frames (31)`;
      if (this.reg(SSI.CTRLR1) & 0xffff) return `CTRLR1 NDF ${this.reg(SSI.CTRLR1) & 0xffff}: XIP needs 0`;
      if (cmd !== 0x03 && cmd !== 0x0b) return `XIP read with SSI command ${x2(cmd)} that the flash model does not answer (03h or 0Bh)`;
      const wantWait = cmd === 0x03 ? 0 : 8;
      if (wait !== wantWait) return `XIP command ${x2(cmd)} with WAIT_CYCLES ${wait}: the flash sends data after ${wantWait} dummy clocks, so the words would be misread`;
      if (instL !== 2) return `SPI_CTRLR0 INST_L ${instL}: the flash needs an 8-bit instruction (2)`;
      if (addrL !== 6) return `SPI_CTRLR0 ADDR_L ${addrL} (${addrL * 4} bits): the flash takes 24-bit addresses (6)`;
      if (trans !== 0) return `SPI_CTRLR0 TRANS_TYPE ${trans}: standard SPI needs 0 (command and address in standard format)`;
      return this.sckProblem();
    },
    sckProblem() {
      const cmd = this.reg(SSI.SPI_CTRLR0) >>> 24, div = this.reg(SSI.BAUDR) & 0xffff, sck = mcu.clkSys / div;
      if (sck > FLASH_SCK_MAX[cmd])
        return `flash SCK ${(sck / 1e6).toFixed(3)} MHz (clk_sys ${(mcu.clkSys / 1e6).toFixed(3)} MHz / BAUDR ${div}) is over the ${FLASH_SCK_MAX[cmd] / 1e6} MHz the flash allows for command 0x${cmd.toString(16).padStart(2, '0')}: reads would return wrong data`;
      return null;
    },
    readUint32(offset) {
      offset &= 0xfff;
      switch (offset) {
        case SSI.SR: return 0x6; // TFE | TFNF: idle, FIFOs empty
        case SSI.IDR: return 0x51535049;
        case SSI.VERSION: return 0x3430312a;
        case SSI.SSIENR: return this.enabled ? 1 : 0;
        case SSI.DR0: return stop('SSI DR0 read: direct-mode flash transfers are not modelled (only XIP reads)');
      }
      return this.reg(offset);
    },
    writeUint32Atomic(offset, value, type) {
      this.writeUint32(offset, type ? atomic(this.readUint32(offset), type, value) : value);
    },
    writeUint32(offset, value) {
      value >>>= 0;
      if (offset === SSI.DR0) return stop('SSI DR0 write: direct-mode flash transfers (commands other than XIP reads) are not modelled');
      if (offset === SSI.SSIENR) {
        this.enabled = !!(value & 1);
        this.problem = this.enabled ? this.check() : 'the SSI is disabled (SSIENR 0)';
        onXip(this.problem === null);
        return;
      }
      if (this.enabled && SSI_SET_UP.has(offset))
        return stop(`SSI ${SSI_NAMES[offset] ?? `+0x${offset.toString(16)}`} written while the SSI is enabled: the DW_apb_ssi ignores it (write SSIENR 0 first)`);
      this.regs.set(offset, value);
    },
  };
  return ssi;
}

// ---- the XIP cache, modelled (--xip-model) ----------------------------------

// The RP2040's XIP cache as the board notes give it: 16 KiB, two ways,
// 8-byte lines, LRU assumed. Counts reads and misses of flash addresses.
function makeXipCache() {
  const SETS = 1024, tags = new Int32Array(SETS * 2).fill(-1), older = new Uint8Array(SETS);
  return {
    reads: 0, misses: 0,
    read(flashAddr) {
      this.reads++;
      const line = flashAddr >>> 3, set = line & (SETS - 1), tag = line >>> 10, i = set * 2;
      if (tags[i] === tag) { older[set] = 1; return; }
      if (tags[i + 1] === tag) { older[set] = 0; return; }
      this.misses++;
      const way = older[set]; // the least recently used way
      tags[i + way] = tag;
      older[set] = way ^ 1;
    },
  };
}
// A miss with boot2's 03h reads at clk_sys / 4: 8 command and 24 address
// clocks, then 64 data clocks for the line, each 4 clk_sys cycles.
const XIP_MISS_CYCLES_03H = (8 + 24 + 64) * 4;

// ---- running the firmware --------------------------------------------------

function run(elfPath, uf2Path, { noCrystal = false, xipModel = false } = {}) {
  if (!existsSync(uf2Path)) fail(`${uf2Path}: missing: the flash image comes from the UF2 beside ${elfPath} (build it: uf2.mjs pack)`);
  let img;
  try {
    img = readUf2(readFileSync(uf2Path), uf2Path);
  } catch (e) {
    fail(e.message);
  }
  // the boot ROM's check: nothing runs without it
  const crc = boot2Crc(img.bytes);
  if (!crc.ok)
    fail(`${uf2Path}: boot2 CRC ${hex(crc.stored)} does not match ${hex(crc.computed)} (of flash bytes 0..251): the chip would drop into USB boot (BOOTSEL mode); nothing of the image runs`);
  const elf = readElf(elfPath);
  for (const s of elf.segments) {
    if (s.paddr < FLASH_BASE || s.paddr >= FLASH_BASE + 0x1000000) continue;
    const at = s.paddr - FLASH_BASE;
    const got = img.bytes.subarray(at, at + s.bytes.length);
    if (got.length !== s.bytes.length || !s.bytes.equals(got))
      fail(`${uf2Path} does not hold ${elfPath}'s bytes at ${hex(s.paddr)} (a stale UF2? rebuild it)`);
  }
  const markSym = elf.symbols.get(MARK_SYMBOL);
  const markPC = markSym === undefined ? -1 : (markSym & ~1) >>> 0;
  const passSym = elf.symbols.get(PASS_SYMBOL);
  const passPC = passSym === undefined ? -1 : (passSym & ~1) >>> 0;

  const mcu = new RP2040();
  const core = mcu.core, clock = mcu.clock;
  let at = BOOT2_SRAM, atCore = 0; // the PC and core of the instruction being executed
  const where = () => `at PC ${hex(at)} on core ${atCore}`;
  const stop = (msg) => {
    throw new RunFailure(`${where()}: ${msg}`);
  };

  // warnings: nothing mapped, or an instruction rp2040js does not know,
  // fail; the rest (unimplemented registers of blocks it stubs) stay quiet
  mcu.logger = {
    debug() {},
    info() {},
    warn(component, msg) {
      let m;
      if ((m = /^Read from invalid memory address: ([0-9a-f]+)/.exec(msg)) || (m = /^Write to undefined address: ([0-9a-f]+)/.exec(msg))) {
        const a = parseInt(m[1], 16), kind = msg.startsWith('Read') ? 'read of' : 'write to';
        const what = a >= 0x14000000 && a < 0x18000000 ? 'the XIP cache controls and cache-as-SRAM, which rp2040js does not model'
          : 'an address where nothing is mapped: on the chip a bus error (HardFault)';
        stop(`${kind} ${hex(a)}, ${what}`);
      }
      if (/is not implemented yet/.test(msg))
        stop(`instruction 0x${mcu.readUint16(at).toString(16).padStart(4, '0')} is undefined (or unknown to rp2040js): on the chip a HardFault`);
    },
    error(component, msg) {
      if (/not 32 bit aligned/.test(msg)) stop(`${msg}: an unaligned word access, a HardFault on the Cortex-M0+`);
      stop(`${component}: ${msg}`);
    },
  };
  mcu.onBreak = (code) => {
    const op = mcu.readUint16(at);
    if (op >> 8 === 0xbe) stop(`bkpt 0x${code.toString(16)}: with no debugger attached the chip takes a HardFault (no semihosting on the board)`);
    stop(`udf 0x${code.toString(16)}: an undefined instruction, a HardFault on the chip`);
  };

  // RESETS and the blocks it holds
  const resets = makeResets(stop);
  mcu.peripherals[0x4000c] = resets;
  for (const [name, bit, base] of BLOCKS) {
    const p = mcu.peripherals[base >>> 12];
    if (!p) continue;
    const rd = p.readUint32, wr = p.writeUint32Atomic, mask = 1 << bit, clkRegs = CLK_PERI_REGS[name];
    const inReset = (kind, offset) =>
      stop(`${kind} ${name} (${hex(base + offset)}) while RESETS holds it in reset (bit ${bit}): on the chip the access does not reach it (take it out of reset and wait for RESET_DONE first)`);
    p.readUint32 = function (offset) {
      if (resets.reset & mask) inReset('read of', offset);
      return rd.call(this, offset);
    };
    p.writeUint32Atomic = function (offset, value, type) {
      if (resets.reset & mask) inReset('write to', offset);
      if (clkRegs && clkRegs[offset] && mcu.clocks.periFreq === 0)
        stop(`write to ${name} ${clkRegs[offset]} (${hex(base + offset)}) while clk_peri is stopped: on the chip the ${name.slice(0, -1)} sends nothing (enable CLK_PERI_CTRL first)`);
      return wr.call(this, offset, value, type);
    };
  }

  // XIP flash: guarded accessors until the SSI is set up for it, then
  // rp2040js's own (fast) ones
  const XIP_LO = 0x10000000, XIP_HI = 0x14000000;
  const proto = Object.getPrototypeOf(mcu);
  const xipFault = (a, fetch) => stop(`${fetch ? 'instruction fetch from' : 'read of'} XIP flash ${hex(a)} with the SSI not set up for it (${ssi.problem}): on the chip the image's bytes would not come back`);
  const guarded = {
    readUint32(a) {
      if (a >>> 0 >= XIP_LO && a >>> 0 < XIP_HI) xipFault(a >>> 0, false);
      return proto.readUint32.call(this, a);
    },
    readUint16(a) {
      if (a >>> 0 >= XIP_LO && a >>> 0 < XIP_HI) xipFault(a >>> 0, a === at || a === at + 2);
      return proto.readUint16.call(this, a);
    },
    readUint8(a) {
      if (a >>> 0 >= XIP_LO && a >>> 0 < XIP_HI) xipFault(a >>> 0, false);
      return proto.readUint8.call(this, a);
    },
  };
  // --xip-model: once XIP runs, every read goes through two models of the
  // XIP cache: `image`, the flash reads this image makes, and `inFlash`,
  // the ones it would make if its code and scene tables ran from flash
  // where they are loaded (their SRAM addresses mapped back)
  const xip = { image: makeXipCache(), inFlash: makeXipCache() };
  const ranges = [['__code_start', '__code_end', '__code_load'], ['__scene_start', '__scene_end', '__scene_load']]
    .map((names) => names.map((n) => elf.symbols.get(n)))
    .filter(([a, b, l]) => a !== undefined && b !== undefined && l !== undefined && a !== l);
  const modelRead = (a) => {
    a >>>= 0;
    if (a >= XIP_LO && a < XIP_HI) {
      const f = a & 0xffffff;
      xip.image.read(f);
      xip.inFlash.read(f);
      return;
    }
    for (const [lo, hi, load] of ranges)
      if (a >= lo && a < hi) { xip.inFlash.read((load + (a - lo)) & 0xffffff); return; }
  };
  const modelled = {
    readUint32(a) { modelRead(a); return proto.readUint32.call(this, a); },
    readUint16(a) { modelRead(a); return proto.readUint16.call(this, a); },
    readUint8(a) { modelRead(a); return proto.readUint8.call(this, a); },
  };
  const setXip = (ready) => {
    const src = ready ? (xipModel ? modelled : proto) : guarded;
    mcu.readUint32 = src.readUint32;
    mcu.readUint16 = src.readUint16;
    mcu.readUint8 = src.readUint8;
  };
  const ssi = makeSsi(mcu, stop, setXip);
  mcu.peripherals[0x18000] = ssi;
  // --no-crystal: a board whose crystal never starts (XOSC STATUS never
  // reports STABLE), to see the firmware's bounded wait and its message
  if (noCrystal) {
    const xosc = mcu.peripherals[0x40024], read = xosc.readUint32.bind(xosc);
    xosc.readUint32 = (offset) => (offset === 0x04 ? read(offset) & 0x7fffffff : read(offset));
  }
  setXip(false);

  // The TIMER counts the watchdog's ticks: microseconds only once the
  // tick is enabled with CYCLES = clk_ref in MHz (at reset: enabled,
  // CYCLES 0). rp2040js counts microseconds whatever the tick, so a read
  // fails here where the chip's count would not be microseconds.
  const WATCHDOG_TICK = 0x2c, TICK_ENABLE = 1 << 9, TICK_CYCLES = 0x1ff;
  const watchdog = mcu.peripherals[0x40058], timer = mcu.peripherals[0x40054];
  let tick = TICK_ENABLE;
  const wdWrite = watchdog.writeUint32Atomic, wdRead = watchdog.readUint32;
  watchdog.writeUint32Atomic = function (offset, value, type) {
    if (offset === WATCHDOG_TICK) tick = (type ? atomic(tick, type, value) : value) & (TICK_ENABLE | TICK_CYCLES);
    return wdWrite.call(this, offset, value, type);
  };
  watchdog.readUint32 = function (offset) {
    return offset === WATCHDOG_TICK ? tick | (tick & TICK_ENABLE ? 1 << 10 : 0) : wdRead.call(this, offset); // (RUNNING)
  };
  const timerRead = timer.readUint32;
  timer.readUint32 = function (offset) {
    const v = timerRead.call(this, offset); // (in reset: fails there first)
    if (offset === 0x08 || offset === 0x0c || offset === 0x24 || offset === 0x28) { // TIMEHR, TIMELR, TIMERAWH, TIMERAWL
      const ref = mcu.clocks.refFreq, cycles = tick & TICK_CYCLES;
      if (!(tick & TICK_ENABLE) || cycles * 1e6 !== ref)
        stop(`TIMER read with the watchdog's tick ${tick & TICK_ENABLE ? `every ${cycles} cycles` : 'disabled'} of clk_ref (${(ref / 1e6).toFixed(3)} MHz): on the chip the TIMER would not count microseconds (WATCHDOG TICK: ENABLE and CYCLES = clk_ref in MHz)`);
    }
    return v;
  };

  // clocks as at reset: clk_ref and clk_sys from the ring oscillator,
  // clk_peri stopped (rp2040js computes them from its CLOCKS registers)
  mcu.updateClocks();
  if (mcu.clkSys !== mcu.roscFreq || mcu.clocks.periFreq !== 0)
    fail(`rp2040js gives clk_sys ${mcu.clkSys} Hz, clk_peri ${mcu.clocks.periFreq} Hz at reset: expected the ring oscillator's ${mcu.roscFreq} Hz and a stopped clk_peri`);
  let nsPerCycle = 1e9 / mcu.clkSys;
  mcu.addClockListener((hz) => {
    nsPerCycle = 1e9 / hz;
    if (ssi.enabled && ssi.problem === null) {
      const p = ssi.sckProblem();
      if (p) stop(p);
    }
  });

  // the boot ROM (CRC checked above): boot2 copied to SRAM and run
  mcu.flash.set(img.bytes, 0);
  mcu.sram.set(img.bytes.subarray(0, BOOT2_SIZE), BOOT2_SRAM - SRAM_BASE);
  core.SP = SRAM_END;
  core.PC = BOOT2_SRAM;

  // the SPI log (st7789.mjs): each byte with the data/command and chip
  // select levels; chip select rising as an event. Chip select may only
  // fall once SPI0 runs as the panel needs it: enabled, master, 8-bit
  // frames, data sampled on the rising edge (mode 0 or 3), at most
  // 62.5 MHz, its clock pin handed to it (else the clock line can move
  // while the panel listens, and it reads a phantom bit).
  const serial = [], spi = [];
  mcu.uart[0].onByte = (v) => serial.push(v);
  const panel = makePanelClock(mcu);
  mcu.spi[0].onTransmit = (v) => {
    panel.byte(now); // (the clock: either core may have started the transfer)
    spi.push((mcu.gpio[PIN_DC].outputValue ? 1 : 0) | (mcu.gpio[PIN_CS].outputValue ? 2 : 0), v);
    mcu.spi[0].completeTransmit(0);
  };
  let csHigh = null;
  mcu.gpio[PIN_CS].addListener(() => {
    const pin = mcu.gpio[PIN_CS];
    if (!pin.outputEnable) return;
    const high = pin.outputValue;
    if (high === csHigh) return;
    csHigh = high;
    if (high) { spi.push(0x80, 0); return; }
    const s0 = mcu.spi[0], c0 = s0.control0 ?? 0, mode = (c0 >> 6) & 3;
    const why = !s0.enabled ? 'SPI0 is not enabled'
      : s0.control1 & 4 ? 'SPI0 is not the master'
      : s0.dataBits !== 8 ? `SPI0 sends ${s0.dataBits}-bit frames, not 8`
      : mode === 1 || mode === 2 ? `SPI0 is in a mode (SPO ${mode >> 1}, SPH ${mode & 1}) that shifts data on the rising edge, where the ST7789 samples it`
      : !(s0.clockFrequency > 0 && s0.clockFrequency <= SPI_MAX_HZ) ? `SPI0's clock is ${(s0.clockFrequency / 1e6).toFixed(1)} MHz, outside the ST7789's 62.5 MHz`
      : mcu.gpio[PIN_SCK].functionSelect !== 1 ? `GP${PIN_SCK} is not SPI0's clock yet`
      : null;
    if (why) stop(`chip select (GP${PIN_CS}) went low while ${why}: on the chip the panel could read a phantom bit`);
  });

  // the two cores (core1.mjs): step the one that has used fewer cycles,
  // core 0 on ties; a sleeping core does not step. The clock runs to the
  // slower running core's cycles; a core woken from sleep takes up the
  // clock's count (its sleeping cycles count, as on SysTick)
  const c1 = attachCore1(mcu, stop), core1 = c1.core1;
  const guardLo = elf.symbols.get(GUARD_SYMBOLS[0]), guardHi = elf.symbols.get(GUARD_SYMBOLS[1]);
  if (guardLo !== undefined && guardHi !== undefined) c1.guard(guardLo, guardHi);
  const ppbs = [mcu.ppb, c1.bus.ppb], cores = [core, core1];
  const canWake = (c) => (ppbs[c].systickIntEnable && ppbs[c].systickTimer.enable) || cores[c].enabledInterrupts !== 0;
  const slept = [0, 0];
  let n0 = 0, n1 = 0; // instructions
  let ending = null, now = 0, doneAt = -1;
  const marks = [[], []];
  const t0 = process.hrtime.bigint();
  try {
    while (ending === null) {
      for (let i = 0; i < 1000000; i++) {
        // an alarm's interrupt (SysTick's) pends without waking the core
        if (core.waiting && core.interruptsUpdated && core.checkForInterrupts()) core.waiting = false;
        if (core1.waiting && core1.interruptsUpdated && core1.checkForInterrupts()) core1.waiting = false;
        const asleep1 = core1.waiting || c1.off;
        let c, id;
        if (core.waiting) {
          if (asleep1) {
            if (!canWake(0) && (c1.off || !canWake(1))) {
              ending = `both cores sleep with nothing to wake them (core 0 at ${hex(core.PC)}, core 1 ${c1.state()})`;
              break;
            }
            if (!clock.nextAlarm) {
              ending = 'both cores sleep, interrupts enabled but nothing pending or scheduled';
              break;
            }
            // sleep to the next alarm; clk_sys (and SysTick) keep running
            const cycles = Math.max(1, Math.ceil(clock.nanosToNextAlarm / nsPerCycle - 1e-9));
            now += cycles;
            clock.tick(cycles * nsPerCycle);
            continue;
          }
          // core 0 asleep for good (WFI, nothing to wake it) while core 1 runs
          if (doneAt !== core.cycles) {
            doneAt = core.cycles;
            if (!canWake(0) && !c1.inWfe(0))
              throw new RunFailure(`core 1 is still busy (${c1.state()}) when core 0 sleeps for good (WFI with nothing to wake it, at PC ${hex(core.PC)}, after its last output): core 1 must have finished before the frame is reported`);
          }
          c = core1; id = 1;
        } else if (asleep1) {
          // core 0 alone, as with one core, until it sleeps or core 1 wakes
          if (core.cycles < now) {
            slept[0] += now - core.cycles;
            core.cycles = now;
          }
          atCore = 0;
          for (let k = 0; k < 10000; k++) {
            const pc = core.PC;
            if (pc === markPC || pc === passPC) {
              // an interrupt taken before it would run the handler first
              if (core.interruptsUpdated && core.checkForInterrupts()) continue;
              if (pc === passPC) panel.pass(core, 0, spi.length);
              else {
                marks[0].push([n0, core.cycles, xip.image.reads, xip.image.misses, xip.inFlash.misses]);
                panel.mark(core.cycles);
              }
            }
            at = pc;
            core.executeInstruction();
            n0++;
            const t = core.cycles;
            clock.tick((t - now) * nsPerCycle);
            now = t;
            if (core.waiting || !(core1.waiting || c1.off) || (core1.waiting && core1.interruptsUpdated)) break;
          }
          continue;
        } else {
          // both run: a core just woken counts from now
          for (const x of cores) {
            if (x.cycles < now) {
              slept[x === core ? 0 : 1] += now - x.cycles;
              x.cycles = now;
            }
          }
          if (core.cycles <= core1.cycles) { c = core; id = 0; } else { c = core1; id = 1; }
        }
        if (c.cycles < now) { // woken: it slept until now
          slept[id] += now - c.cycles;
          c.cycles = now;
        }
        // c runs until it passes the other running core (core 0 on ties),
        // sleeps, or the other's state changes
        const o = cores[1 - id], oWaiting = o.waiting, oUpdated = o.interruptsUpdated;
        const lim = oWaiting ? Infinity : o.cycles; // core 1 steps while below it, core 0 up to a tie
        atCore = id;
        for (let k = 0; k < 10000; k++) {
          const pc = c.PC;
          at = pc;
          if (id && pc < ROM_END) {
            c1.romStep();
          } else {
            if (pc === markPC || pc === passPC) {
              if (c.interruptsUpdated && c.checkForInterrupts()) continue;
              if (pc === passPC) panel.pass(c, id, spi.length);
              else {
                marks[id].push([id ? n1 : n0, c.cycles, xip.image.reads, xip.image.misses, xip.inFlash.misses]);
                if (!id) panel.mark(c.cycles);
              }
            }
            c.executeInstruction();
            if (id) n1++;
            else n0++;
          }
          // the clock to the slower running core
          const t = c.cycles < lim ? c.cycles : lim;
          if (t > now) {
            clock.tick((t - now) * nsPerCycle);
            now = t;
          }
          if ((id ? c.cycles >= lim : c.cycles > lim) || c.waiting || c1.off || o.waiting !== oWaiting || o.interruptsUpdated !== oUpdated) break;
        }
      }
      if (Number(process.hrtime.bigint() - t0) / 1e9 > WALL_LIMIT_S) throw new RunFailure(`no end after ${WALL_LIMIT_S} s of wall time (core 0 at ${hex(core.PC)}, core 1 ${c1.state()})`);
    }
  } catch (e) {
    if (!(e instanceof RunFailure)) throw e;
    return { failure: e.message, serial: Buffer.from(serial), spi: Buffer.from(spi) };
  }
  const perCore = [n0, n1].map((n, id) => ({ instructions: n, cycles: cores[id].cycles - slept[id], slept: slept[id] }));
  perCore[1].state = c1.state();
  perCore[1].launches = c1.launches;
  perCore[1].romCycles = c1.romCycles;
  return {
    serial: Buffer.from(serial), spi: Buffer.from(spi), wall: Number(process.hrtime.bigint() - t0) / 1e9,
    instructions: n0 + n1, cycles: Math.max(now, core.cycles, core1.cycles), perCore,
    marks, markSym, ending, xipModel, clkSys: mcu.clkSys, clkPeri: mcu.clocks.periFreq, panel,
    backlight: mcu.gpio[PIN_BACKLIGHT].outputEnable && mcu.gpio[PIN_BACKLIGHT].outputValue,
    led: mcu.gpio[PIN_LED].outputEnable && mcu.gpio[PIN_LED].outputValue,
  };
}

// ---- the panel's time, and its picture after each progressive pass ------
//
// rp2040js's DMA and SPI move bytes at once, so the panel's time is kept
// here: each byte SPI0 sends takes 8 of its clocks (clk_sys / its
// divider), queued behind the bytes before it, as the chip's DMA sends a
// band while the core renders the next (the core's waits for a busy SPI
// are not modelled: they would add only where the SPI falls behind).
// With progressive display (st7789.c) the firmware calls board_pass_shown
// (pass) when a pass's last transfer is done: the runner keeps the SPI
// log's length there (the panel's picture after that pass) and the time.
function makePanelClock(mcu) {
  return {
    free: 0,     // the cycle at which the SPI has sent every byte so far
    marks: [],   // at each port_cycles_read mark: when the SPI is done
    passes: [],  // { pass, cycles, spiLength, spiDone } at each board_pass_shown
    byte(cycles) {
      this.free = Math.max(this.free, cycles) + (8 * mcu.clkSys) / mcu.spi[0].clockFrequency;
    },
    mark(cycles) {
      // the render's start: st7789.c waited for the panel's clearing to
      // be sent, so the SPI is idle there
      if (this.marks.length === 0) this.free = Math.min(this.free, cycles);
      this.marks.push(Math.max(this.free, cycles));
    },
    pass(core, id, spiLength) {
      this.passes.push({ pass: core.registers[0], core: id, cycles: core.cycles, spiLength, spiDone: Math.max(this.free, core.cycles) });
    },
  };
}

// The frame's time from the render's start to the panel's last byte, and
// with progressive passes the time to pass 1 on the panel and the panel
// after each pass (BASE.passN.stream, the frame in rt's stream format);
// throws what is wrong. Also the times of the events the firmware times
// itself (frame_ms, first_picture_us), on the emulator's one clock in
// microseconds of clk_sys: render start (core 0's first mark) to its end
// (core 0's last) and to the call of board_pass_shown after pass 1, on
// whichever core made it; the DMA is instant there, as the firmware sees
// it under the emulator. { lines, us: { frame_ms, first_picture_us } }
function panelReport(r, base, module, fw, fh, hz) {
  const start = r.marks[0][0][1], end = r.panel.marks[r.panel.marks.length - 1];
  const toUs = (c) => c / (r.clkSys / 1e6);
  const ms = (c) => (hz ? `, ${((c / hz) * 1e3).toFixed(1)} ms at ${hz / 1e6} MHz` : '');
  const frameEnd = r.marks[0][r.marks[0].length - 1][1];
  const lines = [`frame_cycles ${Math.round(end - start)} (render start to the panel's last byte, SPI bytes at SPI0's clock${ms(end - start)}; with the emulator's instant DMA: ${frameEnd - start})`,
    `emulator_frame_us ${toUs(frameEnd - start).toFixed(1)} (render start to its end on core 0, at clk_sys ${r.clkSys / 1e6} MHz, the emulator's instant DMA)`];
  const us = { frame_ms: toUs(frameEnd - start) };
  const { passes } = r.panel;
  if (passes.length === 0) return { lines, us };
  if (passes.map((p) => p.pass).join() !== '1,2,3,4,5,6,7') throw new Error(`progressive passes ended in the order ${passes.map((p) => p.pass).join()}, not 1..7`);
  const first = passes[0];
  lines.push(`first_picture_cycles ${Math.round(first.spiDone - start)} (render start to pass 1's last panel byte at SPI0's clock${ms(first.spiDone - start)}; with the emulator's instant DMA: ${first.cycles - start})`);
  lines.push(`emulator_first_picture_us ${toUs(first.cycles - start).toFixed(1)} (render start to pass 1 on the panel, the emulator's instant DMA; pass 1 ended on core ${first.core})`);
  us.first_picture_us = toUs(first.cycles - start);
  for (const p of passes) {
    const picture = decodePanel(r.spi.subarray(0, p.spiLength), module[0], module[1]);
    const [x0, y0] = checkBorder(picture, fw, fh);
    writeFileSync(`${base}.pass${p.pass}.stream`, panelStream(picture, fw, fh, x0, y0));
  }
  lines.push(`progressive passes 1..7 on the panel: pass ends at ${passes.map((p) => Math.round(p.spiDone - start)).join(', ')} cycles (on cores ${passes.map((p) => p.core).join(', ')}); the frame after each: ${base}.passN.stream`);
  return { lines, us };
}

// The render's counts from the marks: start, (begin, end) pairs of display
// output, end. [instructions, cycles] or a note why there are none.
function renderCounts(marks) {
  if (marks.length < 2 || marks.length % 2) return { note: `${marks.length} call(s) of ${MARK_SYMBOL}: the render's start, output pairs and end need an even count of at least 2` };
  const first = marks[0], last = marks[marks.length - 1];
  const n = first.map((v, i) => last[i] - v);
  for (let k = 1; k < marks.length - 1; k += 2) // (begin, end) of display output
    for (let i = 0; i < n.length; i++) n[i] -= marks[k + 1][i] - marks[k][i];
  const [instructions, cycles, flashReads, flashMisses, inFlashMisses] = n;
  return { instructions, cycles, flashReads, flashMisses, inFlashMisses, pairs: (marks.length - 2) / 2 };
}

function receive(rt, args) {
  const r = spawnSync(rt, ['receive', ...args], { encoding: 'latin1' });
  if (r.error) fail(`${rt}: ${r.error.message}`);
  return r;
}

const USAGE = 'usage: run.mjs [--module PANEL[,flip]] [--no-crystal] [--xip-model] FIRMWARE.elf OUT.png RT [CLOCK_HZ] | --panel SPI_LOG W H OUT.stream [PANEL [FLIP]]';
const argv = process.argv.slice(2);
if (argv[0] === '--panel') {
  const [, log, w, h, out, panel = '320x240', flip = '0'] = argv;
  try {
    const picture = decodePanel(readFileSync(log), panel, Number(flip));
    const [x0, y0] = checkBorder(picture, Number(w), Number(h));
    writeFileSync(out, panelStream(picture, Number(w), Number(h), x0, y0));
  } catch (e) {
    fail(e.message);
  }
  process.exit(0);
}
// the module on the panel's pins (board.mk's PANEL and PANEL_FLIP)
let module = ['320x240', 0], noCrystal = false, xipModel = false;
for (;;) {
  if (argv[0] === '--module') {
    const [name, flip] = (argv[1] ?? '').split(',');
    if (!PANELS[name] || (flip !== undefined && flip !== 'flip')) fail(`--module ${argv[1]}: one of ${Object.keys(PANELS).join(', ')}, optionally with ,flip`);
    module = [name, flip ? 1 : 0];
    argv.splice(0, 2);
  } else if (argv[0] === '--no-crystal') {
    noCrystal = true;
    argv.splice(0, 1);
  } else if (argv[0] === '--xip-model') {
    xipModel = true;
    argv.splice(0, 1);
  } else {
    break;
  }
}
if (argv.length < 3) fail(USAGE);
const [elf, out, rt, hz] = argv;
const base = elf.replace(/\.elf$/, '');
const r = run(elf, `${base}.uf2`, { noCrystal, xipModel });
writeFileSync(`${base}.serial`, r.serial);
writeFileSync(`${base}.spi`, r.spi);
if (r.failure) fail(`${r.failure} (the UART output so far: ${base}.serial)`);
// the UART stream sink's frame opens the console; the panel's run has
// report lines only there
const streamed = r.serial.subarray(0, 4).toString('latin1') === 'RTF1';
const rep = receive(rt, streamed ? [`${base}.serial`, '-o', out] : ['--report-only', `${base}.serial`]);
process.stdout.write(rep.stdout);
process.stderr.write(rep.stderr);
console.log(`LED (GP25) at the end: ${r.led ? 'on' : 'off'}`);
const lines = rep.stdout.trimEnd().split('\n');
const statusLine = /^exit_status (-?\d+)$/;
if (!lines.some((l) => statusLine.test(l))) fail(`the firmware went to sleep without an exit_status line (${r.ending}, after ${r.instructions} instructions)`);
if (!statusLine.test(lines[lines.length - 1])) fail('exit_status is not the firmware\'s last report line');
const status = Number(lines[lines.length - 1].match(statusLine)[1]);
if (status !== 0) {
  console.error(`pico run: firmware exited with status ${status}`);
  process.exit(status > 0 && status < 256 ? status : 1);
}
if (rep.status !== 0) process.exit(rep.status ?? 1);
const value = (key) => (rep.stdout.match(new RegExp(`^${key} (\\d+)$`, 'm')) ?? [])[1];

// the runner's own counts of the render
let systickOff = null;
const timeOff = [];
if (r.markSym === undefined) {
  console.log(`note: ${elf} has no ${MARK_SYMBOL}: no counts of the render from the emulator`);
} else {
  const c = renderCounts(r.marks[0]);
  if (c.note) {
    console.log(`note: ${c.note}: no counts of the render from the emulator`);
  } else {
    console.log(`render_instructions ${c.instructions}`);
    const pixels = Number(value('pixels'));
    if (pixels > 0) console.log(`instructions_per_pixel ${Math.round(c.instructions / pixels)}`);
    else console.log('note: no pixels line in the report: no instructions_per_pixel');
    console.log(`emulator_render_cycles ${c.cycles}`);
    const systick = value('render_cycles');
    if (systick === undefined) {
      console.log('note: no render_cycles in the report: SysTick not compared');
    } else {
      const off = c.cycles ? ((Number(systick) - c.cycles) / c.cycles) * 100 : Infinity;
      console.log(`systick render_cycles ${systick} against the emulator's ${c.cycles}: ${off >= 0 ? '+' : ''}${off.toFixed(4)}%`);
      if (!(Math.abs(off) <= SYSTICK_TOLERANCE)) systickOff = off;
    }
    if (r.xipModel && pixels > 0) {
      const perPx = (v) => (v / pixels).toFixed(2);
      console.log(`xip_render_flash_reads ${c.flashReads}`);
      console.log(`xip_render_misses ${c.flashMisses}`);
      console.log(`xip_model_code_in_flash_misses ${c.inFlashMisses}`);
      console.log(`XIP cache model (16 KiB, 2 ways, 8-byte lines, LRU): this image reads flash ${c.flashReads} times in the render (${c.flashMisses} misses, ${perPx(c.flashMisses)} a pixel); with its code and scene tables in flash it would miss ${c.inFlashMisses} times, ${perPx(c.inFlashMisses)} a pixel: at boot2's 03h reads (${XIP_MISS_CYCLES_03H} cycles a miss) +${perPx(c.inFlashMisses * XIP_MISS_CYCLES_03H)} cycles a pixel, +${(100 * c.inFlashMisses * XIP_MISS_CYCLES_03H / c.cycles).toFixed(1)}%`);
    }
  }
}
if (!streamed) {
  if (value('frame_width') === undefined) fail(`${base}.serial: neither a frame nor a panel's frame_width in the report`);
  const fw = Number(value('frame_width')), fh = Number(value('frame_height'));
  try {
    const picture = decodePanel(r.spi, module[0], module[1]);
    const [x0, y0] = checkBorder(picture, fw, fh);
    writeFileSync(`${base}.panel.stream`, panelStream(picture));
    writeFileSync(`${base}.frame.stream`, panelStream(picture, fw, fh, x0, y0));
    console.log(`panel ${module[0]}${module[1] ? ' flipped' : ''} as the glass shows it: the ${fw}x${fh} frame at ${x0},${y0}, every other pixel black (${base}.panel.stream)`);
  } catch (e) {
    fail(`${base}.spi: ${e.message}`);
  }
  if (!r.backlight) fail(`the backlight (GP${PIN_BACKLIGHT}) is off at the end: the panel shows nothing`);
  if (r.marks[0].length >= 2) {
    let times;
    try {
      times = panelReport(r, base, module, fw, fh, Number(hz));
    } catch (e) {
      fail(`${base}.spi: ${e.message}`);
    }
    for (const l of times.lines) console.log(l);
    // the firmware's own times (the TIMER's microseconds) against the
    // emulator's: within TIME_TOLERANCE, plus half the report's unit
    for (const [key, emuUs] of Object.entries(times.us)) {
      const got = value(key);
      if (got === undefined) {
        console.log(`note: no ${key} in the report: the board's time not compared`);
        continue;
      }
      const unit = key.endsWith('_ms') ? 1000 : 1;
      const off = ((Number(got) * unit - emuUs) / emuUs) * 100, allowed = TIME_TOLERANCE + (100 * unit) / 2 / emuUs;
      console.log(`board ${key} ${got} against the emulator's ${(emuUs / unit).toFixed(unit > 1 ? 3 : 1)}: ${off >= 0 ? '+' : ''}${off.toFixed(2)}%`);
      if (!(Math.abs(off) <= allowed)) timeOff.push(`${key} ${got} is ${off.toFixed(2)}% from the emulator's ${(emuUs / unit).toFixed(unit > 1 ? 3 : 1)}, over the ${allowed.toFixed(2)}% allowed (${TIME_TOLERANCE}% and the report's rounding)`);
    }
  }
  const img = receive(rt, [`${base}.frame.stream`, '-o', out]);
  process.stderr.write(img.stderr);
  if (img.status !== 0) process.exit(img.status ?? 1);
}
// each core's counts: instructions, and cycles spent running (not asleep;
// core 1's include the boot ROM's wait); core 1's render counts when it
// calls port_cycles_read too
for (const [id, p] of r.perCore.entries()) {
  console.log(`core${id}_instructions ${p.instructions}`);
  console.log(`core${id}_cycles ${p.cycles}`);
}
console.log(`core1_launches ${r.perCore[1].launches}`);
console.log(`core 1 at the end: ${r.perCore[1].state}`);
if (r.marks[1].length) {
  const c = renderCounts(r.marks[1]);
  if (c.note) {
    console.log(`note: core 1: ${c.note}: no counts of its render`);
  } else {
    console.log(`core1_render_instructions ${c.instructions}`);
    console.log(`core1_render_cycles ${c.cycles}`);
  }
}
const mhz = (f) => (f ? `${(f / 1e6).toFixed(3)} MHz` : 'stopped');
console.log(`clocks at the end: clk_sys ${mhz(r.clkSys)}, clk_peri ${mhz(r.clkPeri)}`);
const cycles = value('render_cycles');
if (hz && cycles !== undefined)
  console.log(`board render time at ${Number(hz) / 1e6} MHz (SysTick cycles under rp2040js's M0+ timing, code and scene tables in SRAM; display output excluded): ${(Number(cycles) / Number(hz)).toFixed(2)} s`);
console.log(`rp2040js wall time on the host (${r.instructions} instructions, ${r.cycles} cycles in all, ${(r.cycles / r.wall / 1e6).toFixed(1)} M cycles/s): ${r.wall.toFixed(1)} s`);
if (timeOff.length) fail(`the board's own time: ${timeOff.join('; ')}`);
if (systickOff !== null) fail(`SysTick's render_cycles is ${systickOff.toFixed(4)}% from the emulator's count, over the ${SYSTICK_TOLERANCE}% allowed`);
