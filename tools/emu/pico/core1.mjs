// core1.mjs - the RP2040's second core, attached to an rp2040js RP2040
// (1.4.1 models one core) from outside the package.
//
// attachCore1(mcu, stop) gives core 1 its own CortexM0Core, its own SIO
// divider and interpolators (an RPSIO of its own) and its own PPB (NVIC,
// SysTick, VTOR, SCR), on a bus derived from the RP2040 instance
// (Object.create(mcu)), so memory and every other block stay shared: GPIO
// and the 32 spinlocks are core 0's RPSIO's state, reached by both cores.
// What rp2040js lacks is modelled here, from the RP2040 datasheet (2.3.1
// SIO, 2.3.1.4 FIFOs, 2.8.2 launching core 1):
//  - CPUID (SIO 0x000) reads 0 on core 0, 1 on core 1;
//  - the inter-core FIFOs: 32 bits, 8 deep each way. FIFO_ST (0x050) VLD
//    (bit 0, a word to read), RDY (1, room to write), WOF (2, a write when
//    full, dropped), ROE (3, a read when empty, which returns 0 and leaves
//    the FIFO as it was); any write to FIFO_ST clears WOF and ROE; FIFO_WR
//    0x054, FIFO_RD 0x058. SIO_IRQ_PROC0 (IRQ 15, core 0's NVIC only) and
//    SIO_IRQ_PROC1 (IRQ 16, core 1's) are that core's VLD | WOF | ROE;
//  - events: SEV sets both cores' event registers, and wakes the other
//    core from WFE (not from WFI); exception entry and return set it
//    (rp2040js does that, and WFE's consume-or-sleep);
//  - the divider, one per core: the result is valid 8 cycles after the
//    last operand write (counted from the end of the 1-cycle store, on
//    the core that wrote it); DIV_CSR READY reads 0 until then, and a read
//    of DIV_QUOTIENT or DIV_REMAINDER before then fails the run (silicon
//    returns an intermediate value). rp2040js's own 8 cycles charged per
//    operand write are taken back: the wait is the program's;
//  - peripheral interrupts reach both cores' NVICs;
//  - SCR (0xe000ed10) per core (stored: SLEEPDEEP, SEVONPEND have no effect);
//    VTOR ignores bits 7:0 on silicon, so a write with any of them set
//    fails the run;
//  - the boot ROM's core-1 wait, as the ROM does it (no ROM is loaded: its
//    steps run here, at nominal ROM addresses below ROM_END, with cycles
//    charged as its instructions would take): set SCR.SLEEPDEEP, read
//    FIFO_RD once unchecked (ROE set if empty), drain its FIFO, push 0 to
//    core 0 and SEV (the stale 0 core 0 finds after each core-1 reset);
//    then the handshake: wait (WFE) for a word; a 0 goes back to draining
//    and pushing 0; after a 0, the next word must be 1 (else back to
//    draining), then the vector table (stored in VTOR), the stack pointer
//    (MSP) and the entry, each echoed (push when there is room, WFE while
//    there is none, SEV after each push); then SLEEPDEEP cleared and
//    `blx entry`. If the entry returns, core 1 sleeps in a WFI loop;
//  - PSM FRCE_OFF.PROC1 (0x40010004 bit 16): set holds core 1 off, cleared
//    resets it into the ROM's wait (the FIFOs keep their words).
// What fails the run (through stop, which names the PC and core): the
// launch sequence broken (the datasheet's 0, 0, 1, vector table, stack
// pointer, entry: a word out of it, naming the word expected and the one
// received), an entry without its Thumb bit (a HardFault on silicon), a
// vector table not aligned to 256 bytes, an early divider read, and (best
// effort, when the runner is given the image's guarded data: guard()) a
// core's write to that data holding no spinlock while core 1 runs.
// Not modelled: memory ordering (the emulator is sequentially consistent:
// a missing barrier cannot show), SRAM bank contention (silicon's two
// cores stall each other on one bank; here they never do), SEVONPEND,
// the ROM's other entry points (core 1 running ROM code but this wait
// fails the run).
//
// The runner steps the cores (run.mjs): each step of core 1 with its PC
// below ROM_END goes to romStep() instead of executeInstruction().
export const ROM_END = 0x4000;
// the model's ROM states, at nominal addresses in the ROM
const ROM_WAIT = 0x100, ROM_DRAIN = 0x104, ROM_SEND = 0x108, ROM_RECV = 0x10c, ROM_RECV_CHECK = 0x110,
  ROM_LAUNCH = 0x114, ROM_PARK = 0x118;
const ROM_STACK = 0x20042000; // core 1's SP from reset (the ROM's own; it uses no stack in the wait)
const FIFO_DEPTH = 8;
const SIO_CPUID = 0x000, FIFO_ST = 0x050, FIFO_WR = 0x054, FIFO_RD = 0x058;
const DIV_FIRST = 0x060, DIV_LAST_OPERAND = 0x06c, DIV_QUOTIENT = 0x070, DIV_REMAINDER = 0x074, DIV_CSR = 0x078;
const PER_CORE_END = 0x100; // divider 0x060..0x07c, interpolators 0x080..0x0fc
const SPINLOCK0 = 0x100, SPINLOCK31 = 0x17c;
const DIV_CYCLES = 8;
const SIO_STORE_CYCLES = 1; // a store to the SIO (the M0+ I/O port)
const SIO_IRQ_PROC0 = 15;
const PPB_VTOR = 0xd08, PPB_SCR = 0xd10, SCR_SLEEPDEEP = 1 << 2;
const PSM_BASE_PAGE = 0x40010, PSM_FRCE_OFF = 0x4, PSM_PROC1 = 1 << 16;
const OP_WFE = 0xbf20;
const SEQUENCE_NAMES = ['0', '0 (the second of 0, 0, 1)', '1', 'the vector table', 'the stack pointer', 'the entry'];
const hex = (v) => `0x${(v >>> 0).toString(16).padStart(8, '0')}`;

export function attachCore1(mcu, stop) {
  const core0 = mcu.core, sio0 = mcu.sio;
  const CoreClass = core0.constructor, SioClass = sio0.constructor, PpbClass = mcu.ppb.constructor;
  const sioRead = SioClass.prototype.readUint32, sioWrite = SioClass.prototype.writeUint32;
  const ppbRead = PpbClass.prototype.readUint32, ppbWrite = PpbClass.prototype.writeUint32;

  const bus = Object.create(mcu);
  const core1 = new CoreClass(bus);
  bus.core = core1;
  bus.ppb = new PpbClass(bus, 'PPB1');
  const sio1 = new SioClass(bus); // core 1's divider and interpolators
  mcu.addClockListener((hz) => { bus.ppb.systickTimer.frequency = hz; });

  const cores = [core0, core1], ppbs = [mcu.ppb, bus.ppb], sios = [sio0, sio1];
  const m = {
    core1, bus,
    off: false, // PSM FRCE_OFF.PROC1
    launches: 0, romCycles: 0,
    entry: null, // the last entry core 1 was launched at
    scr: [0, 0],
  };

  // ---- FIFOs: fifo[c] holds the words core c reads -------------------------
  const fifo = [[], []], wof = [false, false], roe = [false, false];
  const irq = (c) => cores[c].setInterrupt(SIO_IRQ_PROC0 + c, fifo[c].length > 0 || wof[c] || roe[c]);
  const fifoStatus = (c) => (fifo[c].length ? 1 : 0) | (fifo[1 - c].length < FIFO_DEPTH ? 2 : 0) | (wof[c] ? 4 : 0) | (roe[c] ? 8 : 0);
  const fifoWrite = (c, v) => {
    const tx = fifo[1 - c];
    if (tx.length >= FIFO_DEPTH) wof[c] = true;
    else tx.push(v >>> 0);
    irq(c);
    irq(1 - c);
  };
  const fifoRead = (c) => {
    const rx = fifo[c];
    if (!rx.length) {
      roe[c] = true;
      irq(c);
      return 0;
    }
    const v = rx.shift();
    irq(c);
    return v;
  };
  m.fifo = fifo;

  // ---- events -------------------------------------------------------------
  // a sleeping core's sleep is WFE (woken by an event) or WFI (not)
  const inWfe = (c) => {
    const core = cores[c];
    if (c === 1 && core.PC < ROM_END) return core.PC !== ROM_PARK;
    return core.readUint16((core.PC - 2) >>> 0) === OP_WFE;
  };
  const sev = (c) => {
    cores[c].eventRegistered = true;
    const o = cores[1 - c];
    if (o === core1 && m.off) return;
    if (o.waiting && inWfe(1 - c)) o.waiting = false; // the event wakes it and is consumed
    else o.eventRegistered = true;
  };
  m.inWfe = inWfe;
  // rp2040js's SEV only logs: each core gets a logger of its own that
  // turns that into the event (the rest goes to the RP2040's logger)
  for (const c of [0, 1]) {
    Object.defineProperty(cores[c], 'logger', {
      value: {
        debug: (n, msg) => mcu.logger.debug(n, msg),
        info: (n, msg) => (msg === 'SEV' ? sev(c) : mcu.logger.info(n, msg)),
        warn: (n, msg) => mcu.logger.warn(n, msg),
        error: (n, msg) => mcu.logger.error(n, msg),
      },
    });
  }

  // ---- SIO: per-core registers here, the rest (GPIO, spinlocks) shared ----
  const divReady = [0, 0];
  // which core claimed each spinlock (-1: free), and how many each holds
  const lockOwner = new Int8Array(32).fill(-1), held = [0, 0];
  const sioReadFor = (c) => (offset) => {
    const core = cores[c];
    switch (offset) {
      case SIO_CPUID: return c;
      case FIFO_ST: return fifoStatus(c);
      case FIFO_RD: return fifoRead(c);
      case FIFO_WR: return 0;
      case DIV_QUOTIENT:
      case DIV_REMAINDER:
        if (core.cycles < divReady[c])
          stop(`core ${c} reads the divider's ${offset === DIV_QUOTIENT ? 'DIV_QUOTIENT' : 'DIV_REMAINDER'} ${core.cycles - (divReady[c] - DIV_CYCLES)} cycles after its last operand write: the result is valid after ${DIV_CYCLES} (silicon returns an intermediate value; wait for DIV_CSR READY)`);
        return sioRead.call(sios[c], offset);
      case DIV_CSR: {
        const v = sioRead.call(sios[c], offset);
        return core.cycles < divReady[c] ? v & ~1 : v;
      }
    }
    if (offset >= SPINLOCK0 && offset <= SPINLOCK31) {
      const v = sioRead.call(sio0, offset);
      if (v) { // claimed
        held[c]++;
        lockOwner[(offset - SPINLOCK0) >> 2] = c;
      }
      return v;
    }
    return sioRead.call(offset >= DIV_FIRST && offset < PER_CORE_END ? sios[c] : sio0, offset);
  };
  const sioWriteFor = (c) => (offset, value) => {
    const core = cores[c];
    switch (offset) {
      case FIFO_ST: wof[c] = roe[c] = false; irq(c); return;
      case FIFO_WR: fifoWrite(c, value); return;
      case FIFO_RD: case SIO_CPUID: return; // read-only
    }
    if (offset >= DIV_FIRST && offset < PER_CORE_END) {
      sioWrite.call(sios[c], offset, value);
      if (offset <= DIV_LAST_OPERAND) {
        core.cycles -= DIV_CYCLES; // rp2040js charged them to the write
        divReady[c] = core.cycles + SIO_STORE_CYCLES + DIV_CYCLES;
      } else if (offset === DIV_QUOTIENT || offset === DIV_REMAINDER) {
        divReady[c] = 0; // a restored result is valid at once
      }
      return;
    }
    if (offset >= SPINLOCK0 && offset <= SPINLOCK31) { // released, whoever held it
      const n = (offset - SPINLOCK0) >> 2;
      if (lockOwner[n] >= 0) held[lockOwner[n]]--;
      lockOwner[n] = -1;
    }
    sioWrite.call(sio0, offset, value);
  };
  sio0.readUint32 = sioReadFor(0);
  sio0.writeUint32 = sioWriteFor(0);
  bus.sio = { readUint32: sioReadFor(1), writeUint32: sioWriteFor(1), interp0: sio1.interp0, interp1: sio1.interp1 };

  // ---- PPB: SCR, and VTOR's alignment --------------------------------------
  const setVtor = (c, value) => {
    if (value & 0xff)
      stop(`core ${c} sets VTOR to ${hex(value)}, not aligned to 256 bytes: silicon ignores VTOR bits 7:0 and would take its vectors from ${hex(value & ~0xff)}`);
    cores[c].VTOR = value >>> 0;
  };
  for (const c of [0, 1]) {
    const ppb = ppbs[c];
    ppb.readUint32 = (offset) => (offset === PPB_SCR ? m.scr[c] : ppbRead.call(ppb, offset));
    ppb.writeUint32 = (offset, value) => {
      if (offset === PPB_SCR) m.scr[c] = value & 0x16; // SLEEPONEXIT, SLEEPDEEP, SEVONPEND
      else if (offset === PPB_VTOR) setVtor(c, value);
      else ppbWrite.call(ppb, offset, value);
    };
  }

  // ---- interrupts of the shared blocks reach both NVICs ---------------------
  mcu.setInterrupt = (n, value) => {
    core0.setInterrupt(n, value);
    core1.setInterrupt(n, value);
  };

  // ---- core 1's reset, and PSM FRCE_OFF.PROC1 ---------------------------------
  let rom = { word: 0, then: ROM_RECV, step: 0, seq: 0 };
  const resetCore1 = () => {
    const c = core1;
    c.registers.fill(0);
    c.SP = ROM_STACK;
    c.bankedSP = 0;
    c.PC = ROM_WAIT;
    c.APSR = 0;
    c.PM = false;
    c.SPSEL = 0;
    c.nPRIV = false;
    c.currentMode = 0;
    c.IPSR = 0;
    c.pendingInterrupts = 0;
    c.enabledInterrupts = 0;
    c.interruptPriorities = [0xffffffff, 0, 0, 0];
    c.pendingNMI = c.pendingPendSV = c.pendingSVCall = c.pendingSystick = false;
    c.interruptsUpdated = false;
    c.eventRegistered = false;
    c.waiting = false;
    c.VTOR = 0;
    c.SHPR2 = c.SHPR3 = 0;
    bus.ppb.reset();
    m.scr[1] = 0;
    wof[1] = roe[1] = false;
    irq(1);
    divReady[1] = 0;
    rom = { word: 0, then: ROM_RECV, step: 0, seq: 0 };
  };
  resetCore1();
  core1.cycles = 0;
  const psm = mcu.peripherals[PSM_BASE_PAGE];
  const psmWrite = psm.writeUint32.bind(psm);
  psm.writeUint32 = (offset, value) => {
    psmWrite(offset, value);
    if (offset !== PSM_FRCE_OFF) return;
    const off = !!(psm.frceOff & PSM_PROC1);
    if (off === m.off) return;
    m.off = off;
    if (!off) resetCore1();
  };

  // ---- the ROM's wait, one step at a time ------------------------------------
  const cycles = (n) => {
    core1.cycles += n;
    m.romCycles += n;
  };
  // WFE: consume the event, or sleep until one (the next step runs after)
  const wfe = (next) => {
    cycles(2);
    core1.PC = next;
    if (core1.eventRegistered) core1.eventRegistered = false;
    else core1.waiting = true;
  };
  const send = (word, then) => {
    rom.word = word >>> 0;
    rom.then = then;
    core1.PC = ROM_SEND;
  };
  // the datasheet's sequence as the sender must follow it
  const checkSequence = (w) => {
    const s = rom.seq;
    const ok = s < 2 ? w === 0 : s === 2 ? w === 1 : w !== 0;
    if (!ok)
      stop(`core 1's launch: the boot ROM expected ${SEQUENCE_NAMES[s]} (word ${s + 1} of 0, 0, 1, vector table, stack pointer, entry), received ${hex(w)}${w === 0 && s > 2 ? ' (the sequence restarted: did the sender drain its FIFO and SEV before each 0, and compare each echo?)' : ''}`);
    rom.seq = w === 0 ? (s === 0 ? 1 : 2) : s + 1;
  };
  m.romStep = () => {
    const c = core1;
    switch (c.PC) {
      case ROM_WAIT: // SCR.SLEEPDEEP, one unchecked FIFO read
        m.scr[1] = SCR_SLEEPDEEP;
        fifoRead(1);
        cycles(8);
        c.PC = ROM_DRAIN;
        return;
      case ROM_DRAIN: // drain, then push 0 and receive
        if (fifo[1].length) {
          fifoRead(1);
          cycles(5);
          return;
        }
        cycles(3 + 5);
        rom.step = 0;
        send(0, ROM_RECV);
        return;
      case ROM_SEND:
        if (!(fifoStatus(1) & 2)) {
          cycles(4);
          wfe(ROM_SEND);
          return;
        }
        fifoWrite(1, rom.word);
        sev(1);
        cycles(8);
        c.PC = rom.then;
        return;
      case ROM_RECV:
        wfe(ROM_RECV_CHECK);
        return;
      case ROM_RECV_CHECK: {
        if (!(fifoStatus(1) & 1)) {
          cycles(4);
          c.PC = ROM_RECV;
          return;
        }
        const w = fifoRead(1);
        cycles(6);
        checkSequence(w);
        if (w === 0) { // back to draining and pushing 0
          c.PC = ROM_DRAIN;
          return;
        }
        cycles(2); // return from the receive
        switch (rom.step) {
          case 0: // after a 0: 1, or back to the handshake
            cycles(2);
            if (w !== 1) {
              cycles(1);
              c.PC = ROM_DRAIN;
              return;
            }
            cycles(3);
            rom.step = 1;
            send(w, ROM_RECV);
            return;
          case 1: // the vector table
            setVtor(1, w);
            cycles(2 + 3);
            rom.step = 2;
            send(w, ROM_RECV);
            return;
          case 2: // the stack pointer
            c.SPmain = w;
            cycles(3 + 3);
            rom.step = 3;
            send(w, ROM_RECV);
            return;
          default: // the entry
            m.entry = w;
            cycles(1 + 3);
            rom.step = 4;
            send(w, ROM_LAUNCH);
            return;
        }
      }
      case ROM_LAUNCH: { // SLEEPDEEP cleared, blx entry
        m.scr[1] = 0;
        cycles(1 + 2 + 2);
        const entry = m.entry >>> 0;
        if (!(entry & 1))
          stop(`core 1's entry ${hex(entry)} has no Thumb bit: the ROM's blx would switch to the ARM state, a HardFault on the Cortex-M0+ (send the function's address with bit 0 set)`);
        c.LR = ROM_PARK | 1;
        c.PC = entry & ~1;
        rom.seq = 0;
        m.launches++;
        return;
      }
      case ROM_PARK: // the entry returned: WFI for good
        cycles(2);
        c.waiting = true;
        return;
    }
    stop(`core 1 executes the boot ROM at ${hex(c.PC)}, which is not modelled (only its wait for the launch sequence is)`);
  };
  // The image's spinlock-guarded data, [lo, hi) (best effort): while core
  // 1 runs launched code, a core's write there holding no spinlock fails.
  // Core 0 then gets a bus of its own too, so that a write's bus names
  // its core (and a DMA transfer's, the RP2040's, none).
  m.guard = (lo, hi) => {
    const bus0 = Object.create(mcu);
    core0.rp2040 = bus0;
    const proto = Object.getPrototypeOf(mcu);
    const check = (self, a) => {
      a >>>= 0;
      if (a < lo || a >= hi || self === mcu || m.off || core1.PC < ROM_END) return;
      const c = self === bus ? 1 : 0;
      if (!held[c])
        stop(`core ${c} writes ${hex(a)}, in the data the image guards by spinlock (${hex(lo)}..${hex(hi)}), holding no spinlock while core 1 runs`);
    };
    for (const w of ['writeUint32', 'writeUint16', 'writeUint8']) {
      const f = proto[w];
      mcu[w] = function (a, v) {
        check(this, a);
        return f.call(this, a, v);
      };
    }
  };
  // where core 1 is, in words, for the report
  m.state = () => {
    if (m.off) return 'held off (PSM FRCE_OFF.PROC1)';
    const pc = core1.PC;
    if (pc === ROM_PARK) return 'parked in the boot ROM (its entry returned)';
    if (pc < ROM_END) return m.launches ? 'back in the boot ROM\'s wait' : 'in the boot ROM\'s wait (never launched)';
    return `${core1.waiting ? (inWfe(1) ? 'sleeping (WFE)' : 'sleeping (WFI)') : 'running'} at ${hex(pc)}`;
  };
  return m;
}
