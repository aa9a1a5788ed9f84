#!/usr/bin/env node
// run.mjs - runs the Pico firmware under rp2040js (the RP2040 emulator;
// pinned in package.json, installed into node_modules/ by npm ci).
//
//   node run.mjs FIRMWARE.elf OUT.png RT [CLOCK_HZ]
//       Loads the ELF into flash and starts it without the boot ROM (SP
//       and PC from the vector table), one core, until the firmware exits
//       by semihosting (bkpt 0xab). UART0 goes to FIRMWARE.serial, what
//       SPI0 sends (each byte with the data/command line, GP16) to
//       FIRMWARE.spi. Prints the report (RT receive) and writes OUT.png:
//       from the UART stream when the console opens with a frame (the
//       stream sink), else from the panel (the ST7789 sink, whose report
//       gives frame_width and frame_height). Then the render's time at
//       CLOCK_HZ from its cycles, and the host's wall time.
//   node run.mjs --panel FIRMWARE.spi W H OUT.stream
//       Only the panel's decoding: the top left WxH pixels of the panel as
//       an rgb565be frame in rt's stream format (platform/firmware/sink.h).
//
// The panel decoder is strict, so a damaged transfer gives no image: a
// command it does not know, a window outside the 320x240 panel, a RAMWR
// whose data does not fill its window exactly, pixels before sleep out,
// 16-bit colour and display on, or a frame pixel never written: each
// fails with the byte offset in the SPI log.
//
// Counters: a block at 0x40068000 (an APB slot the RP2040 leaves empty)
// gives the firmware the emulator's instruction and cycle totals (board.c).
// Cycles are rp2040js's Cortex-M0+ model: no flash wait states, no XIP
// cache. Exit status: the firmware's, or 1 when the run or a decoder fails.
import { spawnSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { ConsoleLogger, LogLevel, RP2040 } from 'rp2040js';
import { decodePanel, panelStream } from './st7789.mjs';

const PIN_DC = 16;
const FLASH = 0x10000000, FLASH_SIZE = 16 << 20;
const NS_PER_CYCLE = 8; // rp2040js's clocks assume 125 MHz
const WALL_LIMIT_S = 900;

function fail(msg) {
  console.error(`pico run: ${msg}`);
  process.exit(1);
}

// ---- running the firmware --------------------------------------------------

function loadElf(mcu, path) {
  const f = readFileSync(path);
  if (f.readUInt32BE(0) !== 0x7f454c46 || f[4] !== 1 || f[5] !== 1) fail(`${path}: not a 32-bit little-endian ELF`);
  const phoff = f.readUInt32LE(0x1c), phsize = f.readUInt16LE(0x2a), phnum = f.readUInt16LE(0x2c);
  for (let i = 0; i < phnum; i++) {
    const p = phoff + i * phsize;
    const type = f.readUInt32LE(p), off = f.readUInt32LE(p + 4), paddr = f.readUInt32LE(p + 12), filesz = f.readUInt32LE(p + 16);
    if (type !== 1 || filesz === 0) continue; // PT_LOAD with bytes
    if (paddr < FLASH || paddr + filesz > FLASH + FLASH_SIZE) fail(`${path}: a segment at 0x${paddr.toString(16)} is not in flash`);
    mcu.flash.set(f.subarray(off, off + filesz), paddr - FLASH);
  }
}

function run(elf) {
  const mcu = new RP2040();
  mcu.logger = new ConsoleLogger(LogLevel.Error);
  loadElf(mcu, elf);
  const core = mcu.core, clock = mcu.clock;
  core.SP = mcu.readUint32(FLASH);
  core.PC = mcu.readUint32(FLASH + 4) & ~1;

  const serial = [], spi = [];
  mcu.uart[0].onByte = (v) => serial.push(v);
  mcu.spi[0].onTransmit = (v) => {
    spi.push(mcu.gpio[PIN_DC].outputValue ? 1 : 0, v);
    mcu.spi[0].completeTransmit(0);
  };
  let instructions = 0, latched = [0, 0];
  mcu.peripherals[0x40068] = {
    readUint32(offset) {
      if (offset === 0) latched = [instructions, core.cycles];
      const v = latched[offset >> 3] ?? 0;
      return (offset & 4 ? Math.floor(v / 2 ** 32) : v % 2 ** 32) >>> 0;
    },
    writeUint32Atomic() {},
    writeUint32() {},
  };
  let status = null;
  mcu.onBreak = (code) => {
    const r0 = core.registers[0], r1 = core.registers[1];
    if (code === 0xab && r0 === 0x20) status = mcu.readUint32(r1 + 4) | 0; // SYS_EXIT_EXTENDED
    else if (code === 0xab && r0 === 0x18) status = r1 === 0x20026 ? 0 : 1; // SYS_EXIT
    else { status = 1; console.error(`pico run: bkpt 0x${code.toString(16)} at 0x${core.PC.toString(16)}`); }
  };

  const t0 = process.hrtime.bigint();
  while (status === null) {
    for (let i = 0; i < 1000000 && status === null; i++) {
      if (core.waiting) fail('the core waits for an interrupt (WFI) and none is coming');
      const before = core.cycles;
      core.executeInstruction();
      instructions++;
      clock.tick((core.cycles - before) * NS_PER_CYCLE);
    }
    if (Number(process.hrtime.bigint() - t0) / 1e9 > WALL_LIMIT_S) fail(`no exit after ${WALL_LIMIT_S} s`);
  }
  return { status, serial: Buffer.from(serial), spi: Buffer.from(spi), wall: Number(process.hrtime.bigint() - t0) / 1e9, instructions, cycles: core.cycles };
}

function receive(rt, args) {
  const r = spawnSync(rt, ['receive', ...args], { encoding: 'latin1' });
  if (r.error) fail(`${rt}: ${r.error.message}`);
  return r;
}

const argv = process.argv.slice(2);
if (argv[0] === '--panel') {
  const [, log, w, h, out] = argv;
  try {
    writeFileSync(out, panelStream(decodePanel(readFileSync(log)), Number(w), Number(h)));
  } catch (e) {
    fail(e.message);
  }
  process.exit(0);
}
if (argv.length < 3) fail('usage: run.mjs FIRMWARE.elf OUT.png RT [CLOCK_HZ] | --panel SPI_LOG W H OUT.stream');
const [elf, out, rt, hz] = argv;
const base = elf.replace(/\.elf$/, '');
const r = run(elf);
writeFileSync(`${base}.serial`, r.serial);
writeFileSync(`${base}.spi`, r.spi);
// the UART stream sink's frame opens the console; the panel's run has
// report lines only there
const streamed = r.serial.subarray(0, 4).toString('latin1') === 'RTF1';
const rep = receive(rt, streamed ? [`${base}.serial`, '-o', out] : ['--report-only', `${base}.serial`]);
process.stdout.write(rep.stdout);
process.stderr.write(rep.stderr);
if (r.status !== 0) {
  console.error(`pico run: firmware exited with status ${r.status}`);
  process.exit(r.status > 0 && r.status < 256 ? r.status : 1);
}
if (rep.status !== 0) process.exit(rep.status ?? 1);
const value = (key) => (rep.stdout.match(new RegExp(`^${key} (\\d+)$`, 'm')) ?? [])[1];
if (!streamed) {
  if (value('frame_width') === undefined) fail(`${base}.serial: neither a frame nor a panel's frame_width in the report`);
  try {
    writeFileSync(`${base}.panel.stream`, panelStream(decodePanel(r.spi), Number(value('frame_width')), Number(value('frame_height'))));
  } catch (e) {
    fail(`${base}.spi: ${e.message}`);
  }
  const img = receive(rt, [`${base}.panel.stream`, '-o', out]);
  process.stderr.write(img.stderr);
  if (img.status !== 0) process.exit(img.status ?? 1);
}
const cycles = value('render_cycles');
if (hz && cycles !== undefined)
  console.log(`board render time at ${Number(hz) / 1e6} MHz (rp2040js cycles: no flash wait states or XIP cache modelled; display output excluded): ${(Number(cycles) / Number(hz)).toFixed(2)} s`);
console.log(`rp2040js wall time on the host (${r.instructions} instructions, ${r.cycles} cycles in all, ${(r.cycles / r.wall / 1e6).toFixed(1)} M cycles/s): ${r.wall.toFixed(1)} s`);
