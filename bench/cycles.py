#!/usr/bin/env python3
"""Estimate the cycles of a firmware run under QEMU from its dynamic instruction mix.

    bench/cycles.py FIRMWARE.elf [--machine mps2-an385] [--core m3]
                    [--from-symbol rt_render [--exclude-symbol stream_flush ...]]
                    [--pixels N] [--clock-hz HZ] [--json OUT.json]
    bench/cycles.py --log QEMU.log [--stream UART.out] FIRMWARE.elf ...   (a saved log)

How it counts
-------------
QEMU 7.2 (no TCG plugins) runs the firmware with

    -d in_asm,exec,nochain -D <named pipe> -icount shift=0

`in_asm` prints each translation block (TB) once, when it is translated;
`exec` with `nochain` prints one "Trace 0: <host ptr> [cs_base/PC/flags/cflags]"
line for every execution of a block. The log is read through a named pipe
while QEMU runs and is never stored: the parser keeps one counter per pair of
consecutive blocks (an edge), so memory stays small whatever the run length.

- A translation is bound to the first Trace line after its in_asm listing;
  the Trace line itself (host pointer, PC, flags, cflags) is the block's key.
  QEMU may hold several translations of one PC (under -icount a block that
  touches I/O is re-translated with fewer instructions, CF_LAST_IO); each has
  its own host pointer, so each is counted with its own instructions.
- "cpu_io_recompile: rewound execution of TB": the last block ran only up to
  the I/O instruction (the next Trace line's PC, a one-instruction block that
  then executes it). Only the instructions before it are counted.
- "Stopped execution of TB chain before": the last logged block did not run at
  all (icount budget or an exit request); it is not counted. Its Trace line
  may have changed the region state (a call's entry, a return): when the same
  PC is logged next, re-executed, that change is not made a second time.
- A block's last instruction, when it is a branch, is taken when the next
  block's PC is not the fall-through address.
- --from-symbol F counts only inside the dynamic extent of F: from a block at
  F's address (entered by a call: BL/BLX, or JAL/JALR on RISC-V) until the
  block at the return address (the call's fall-through) runs after a return
  (class Extents: a shadow stack of the tracked functions' frames, which
  bench/profile.py extends to ray kinds). Every entry is counted.
  --exclude-symbol G (repeatable) counts G's extents inside F apart, the way
  the firmware's report subtracts its display sink (stream_begin,
  stream_flush) from render_instructions.

The instruction total is exact (the self-test bench/cycles_selftest.py checks
hand-counted loops on every board, with and without I/O in the loop). The
cycle figure is a model.

Cycle models (zero-wait-state memory assumed everywhere: no flash wait states,
no bus contention, no caches missing; interrupts and exception entry not
modelled). Each variable figure has a min / typ / max; the report gives the
cycles with all three, "typ" being the estimate.

Cortex-M3 (ARM Cortex-M3 TRM, DDI 0337, "Instruction set summary" table and
"Load/store timings"), machines mps2-an385, lm3s6965evb:
  data processing, MOV/MOVW/MOVT, shifts, extends, bitfield, CLZ, IT, NOP   1
  MUL 1; MLA, MLS 2
  SMULL, UMULL 3..5, typ 5; SMLAL, UMLAL 4..7, typ 7 (early termination on
    small operands; Q11.20 operands are usually wide, hence typ = worst case)
  SDIV, UDIV 2..12, typ 7 (early termination on leading zeros/ones)
  LDR/LDRB/LDRH/LDRSB/LDRSH 2, 1 when it follows a single load whose
    destination it does not use as an address ("neighbouring load/store
    pipelining"); STR* with immediate offset 1, with register offset 2
    (1 after a load); LDRD, STRD 3
  +1 when a load/store address register was written by the instruction just
    before it (no forwarding path to the address generator)
  LDM, STM, PUSH, POP 1+N (N registers); with PC in the list 1+N+P
  B, B<cond>, CBZ, CBNZ, BL: 1 not taken, 1+P taken; BX, BLX, MOV/ADD PC 1+P;
    LDR PC 2+P; TBB/TBH 3+P. P is the pipeline refill, 1..3: the TRM says
    "normally" 1 for an immediate branch (2 cycles total), 2 for a register
    branch (3 total), 3 after a load to PC; those are the typ values.
  ISB 4, other barriers and system instructions 1
Cortex-M4 / M4F (Cortex-M4 TRM, DDI 0439, table 3-1; FPU: table 7-1),
machine mps2-an386: as M3 except every multiply (MUL, MLA, MLS, SMULL, UMULL,
  SMLAL, UMLAL, DSP multiplies) 1 cycle. FPU: VADD/VSUB/VMUL/VNMUL/VABS/VNEG/
  VCMP/VCVT/VMOV/VMRS/VMSR 1; VMOV of two core registers 2; VMLA/VMLS/VNMLA/
  VNMLS/VFMA/VFMS/VFNMA/VFNMS 3; VDIV, VSQRT 14; VLDR, VSTR 2 (3 for a
  double); VLDM/VSTM/VPUSH/VPOP 1+N (N single-precision registers).
Cortex-M0 (Cortex-M0 TRM, DDI 0432, table 3-1; the micro:bit's nRF51 has the
single-cycle multiplier), machine microbit:
  data processing 1; MULS 1 (1..32: 32 with the small multiplier);
  LDR*/STR* 2; LDM, STM, PUSH, POP 1+N; POP {..,PC} 4+N (N without PC);
  B<cond> 1 not taken, 3 taken; B 3; BL 4; BX, BLX, MOV/ADD PC 3;
  DMB/DSB/ISB, MRS, MSR 4; others 1. No pipelining of loads.
SiFive E31 (SiFive E31 Core Complex Manual, "Instruction Fetch Unit" and
"Execution Pipeline"), rv32imac, machine sifive_e: single issue, in order, one
instruction per cycle, fully bypassed, interlocks on read-after-write:
  result latency: ALU 1, LW 2, LB/LBU/LH/LHU 3, CSR read 3, MUL/MULH/MULHU/
  MULHSU 5, DIV/DIVU/REM/REMU 2..33 (typ 18). The manual (FE310-G000 edition,
  the core QEMU's sifive_e models) says the multiplier does 8 bits and the
  divider 1 bit per cycle, and that the multiplier "can only execute one
  operation at a time and will block until the previous operation completes":
  typ and max block a multiply or divide until the previous one is done and
  wait, at the end of a block, for one still in flight; min takes a fully
  pipelined multiplier (one per cycle, latency 5) and no wait at block ends.
  Stalls are simulated inside each block (a value loaded at the end of one
  block and used at the start of the next is not seen).
  Control flow: a correctly predicted branch or jump costs nothing extra, a
  mispredicted one 3 cycles. Direction of conditional branches: typ = static
  backward-taken/forward-not-taken (BTFN) rule standing in for the BHT; min =
  every branch predicted, max = every conditional branch mispredicted.
  JAL: BTB hit (0). JALR that is a return (ret): return-address stack (0);
  other JALR: 3 (typ, max), 0 (min).

Not modelled (limitations): flash wait states and any memory or bus
contention; unaligned accesses; exception entry and return (12 cycles or so
on Cortex-M), WFI/WFE waits; on ARM, an instruction of an IT block whose
condition fails is charged as if it ran; load pipelining and address
interlocks across a block boundary (a block nearly always ends with a branch,
so little is missed); on the E31, instruction-cache misses and a real BHT.
A block that faults in the middle (a data abort) would be counted whole;
code that is written at run time would confuse the translation binding.

Output: instructions, per-class counts and cycles, estimated cycles (min, typ,
max), cycles per instruction, per pixel with --pixels (or the firmware's own
"pixels" record), and the cycles of the busiest functions.
Pure Python 3, standard library only.
"""
import argparse
import bisect
import collections
import itertools
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time

try:
    import fcntl
except ImportError:  # not POSIX: the pipe keeps its default size
    fcntl = None

# ---------------------------------------------------------------------------
# machines and cores

MACHINES = {
    "mps2-an385": ("m3", "qemu-system-arm"),
    "lm3s6965evb": ("m3", "qemu-system-arm"),
    "lm3s811evb": ("m3", "qemu-system-arm"),
    "mps2-an386": ("m4", "qemu-system-arm"),
    # the Cortex-M33 priced with the M4's timings (its own are not
    # modelled); its instruction counts are exact either way
    "mps2-an521": ("m4", "qemu-system-arm"),
    "microbit": ("m0", "qemu-system-arm"),
    # a board named otherwise than its QEMU machine (QEMU_MACHINE)
    "stm32f4": ("m4", "qemu-system-arm"),
    "sifive_e": ("e31", "qemu-system-riscv32"),
}
QEMU_MACHINE = {"stm32f4": "netduinoplus2"}
CORE_ISA = {"m0": "arm", "m3": "arm", "m4": "arm", "e31": "riscv"}
NM = {"arm": ["arm-none-eabi-nm", "nm"], "riscv": ["riscv64-unknown-elf-nm", "riscv32-unknown-elf-nm", "nm"]}

# Variable costs: (min, typ, max). See the module docstring for the sources.
PARAMS = {
    "m3": {"mla": (2, 2, 2), "mull": (3, 5, 5), "mlal": (4, 7, 7), "div": (2, 7, 12),
           "P_imm": (1, 1, 3), "P_reg": (1, 2, 3), "P_load": (1, 3, 3)},
    "m4": {"mla": (1, 1, 1), "mull": (1, 1, 1), "mlal": (1, 1, 1), "div": (2, 7, 12),
           "P_imm": (1, 1, 3), "P_reg": (1, 2, 3), "P_load": (1, 3, 3)},
    "m0": {"muls": (1, 1, 32)},
    "e31": {"div": (2, 18, 33), "mul_block": (0, 1, 1), "drain": (0, 1, 1), "mispredict": (0, 3, 3),
            "indirect": (0, 3, 3)},
}
PSETS = ("min", "typ", "max")

# ---------------------------------------------------------------------------
# instructions


class Insn:
    __slots__ = ("addr", "size", "mnem", "ops", "cls", "sub", "br", "cond", "call", "ret",
                 "nregs", "defs", "uses", "aregs", "target", "wide")

    def __init__(self, addr, size, mnem, ops):
        self.addr, self.size, self.mnem, self.ops = addr, size, mnem, ops
        self.cls = "other"
        self.sub = ""
        self.br = None       # None or "cond", "jump", "jump_reg", "pc_load", "tb"
        self.cond = False
        self.call = False
        self.ret = False
        self.nregs = 0
        self.defs = ()
        self.uses = ()
        self.aregs = ()      # address registers of a load/store
        self.target = None   # static branch target
        self.wide = False    # 64-bit FPU transfer


CONDS = ("eq", "ne", "cs", "hs", "cc", "lo", "mi", "pl", "vs", "vc", "hi", "ls", "ge", "lt", "gt", "le", "al")
ARM_ALIAS = {"sb": "r9", "sl": "r10", "fp": "r11", "ip": "r12", "sp": "r13", "lr": "r14", "pc": "r15"}
ARM_REG_RE = re.compile(r"\b(r1[0-5]|r[0-9]|sb|sl|fp|ip|sp|lr|pc)\b")

# base mnemonic -> (class, accepts the S suffix)
ARM_BASES = {}
for _b in ("adc add and asr bic eor lsl lsr mov mvn orn orr ror rrx rsb sbc sub neg").split():
    ARM_BASES[_b] = ("alu", True)
for _b in ("addw subw adr movw movt cmp cmn tst teq bfc bfi ubfx sbfx clz rbit rev rev16 revsh "
           "sxtb sxth uxtb uxth sxtab sxtah uxtab uxtah sxtb16 uxtb16 ssat usat ssat16 usat16 nop "
           "sel pkhbt pkhtb qadd qsub qdadd qdsub qadd8 qadd16 qsub8 qsub16 qasx qsax "
           "sadd8 sadd16 ssub8 ssub16 sasx ssax uadd8 uadd16 usub8 usub16 uasx usax "
           "shadd8 shadd16 shsub8 shsub16 uhadd8 uhadd16 uhsub8 uhsub16 uqadd8 uqadd16 uqsub8 uqsub16 "
           "usad8 usada8 yield sev").split():
    ARM_BASES[_b] = ("alu", False)
ARM_BASES["mul"] = ("mul", True)
for _b in "mla mls".split():
    ARM_BASES[_b] = ("mla", False)
for _b in ("smulbb smulbt smultb smultt smulwb smulwt smlabb smlabt smlatb smlatt smlawb smlawt "
           "smuad smuadx smusd smusdx smlad smladx smlsd smlsdx smmul smmulr smmla smmlar smmls smmlsr").split():
    ARM_BASES[_b] = ("mul", False)
for _b in "smull umull".split():
    ARM_BASES[_b] = ("mull", True)
for _b in "smlal umlal umaal smlalbb smlalbt smlaltb smlaltt smlald smlaldx smlsld smlsldx".split():
    ARM_BASES[_b] = ("mlal", True)
for _b in "sdiv udiv".split():
    ARM_BASES[_b] = ("div", False)
for _b in "ldr ldrb ldrh ldrsb ldrsh ldrt ldrbt ldrht ldrsbt ldrsht ldrex ldrexb ldrexh pld pli".split():
    ARM_BASES[_b] = ("load", False)
for _b in "str strb strh strt strbt strht strex strexb strexh".split():
    ARM_BASES[_b] = ("store", False)
ARM_BASES["ldrd"] = ("load_multi", False)
ARM_BASES["strd"] = ("store_multi", False)
for _b in "ldm ldmia ldmfd ldmdb ldmea pop".split():
    ARM_BASES[_b] = ("load_multi", False)
for _b in "stm stmia stmea stmdb stmfd push".split():
    ARM_BASES[_b] = ("store_multi", False)
for _b in "b bl blx bx cbz cbnz tbb tbh".split():
    ARM_BASES[_b] = ("branch", False)
for _b in "dmb dsb isb mrs msr cpsid cpsie svc bkpt wfi wfe udf clrex".split():
    ARM_BASES[_b] = ("system", False)
_ARM_BASES_BY_LEN = sorted(ARM_BASES, key=len, reverse=True)
_ARM_SPLIT_CACHE = {}


def arm_split(m):
    """'addseq' -> ('add', True, 'eq'); None when unknown."""
    if m in _ARM_SPLIT_CACHE:
        return _ARM_SPLIT_CACHE[m]
    res = None
    for b in _ARM_BASES_BY_LEN:
        if m.startswith(b):
            rest = m[len(b):]
            s = False
            if rest.startswith("s") and ARM_BASES[b][1] and (rest == "s" or rest[1:] in CONDS):
                s, rest = True, rest[1:]
            if rest == "" or rest in CONDS:
                res = (b, s, rest)
                break
    _ARM_SPLIT_CACHE[m] = res
    return res


def arm_regs(text):
    return [ARM_ALIAS.get(r, r) for r in ARM_REG_RE.findall(text)]


def arm_reglist(ops):
    """Registers in the {..} list (ranges expanded), and whether PC is one of them."""
    m = re.search(r"\{([^}]*)\}", ops)
    if not m:
        return 0, False, []
    n, pc, regs = 0, False, []
    for part in m.group(1).split(","):
        part = part.strip()
        if "-" in part:
            a, b = part.split("-")
            ka, kb = re.match(r"([a-z]+)(\d+)", a.strip()), re.match(r"([a-z]+)(\d+)", b.strip())
            if ka and kb:
                cnt = int(kb.group(2)) - int(ka.group(2)) + 1
                n += cnt * (2 if ka.group(1) == "d" else 1)
                if ka.group(1) == "r":
                    regs += ["r%d" % i for i in range(int(ka.group(2)), int(kb.group(2)) + 1)]
                continue
        if not part:
            continue
        n += 2 if part.startswith("d") else 1
        r = ARM_ALIAS.get(part, part)
        regs.append(r)
        if r == "r15":
            pc = True
    return n, pc, regs


def arm_target(ops):
    m = re.search(r"#(0x[0-9a-f]+|\d+)\s*$", ops)
    return int(m.group(1), 0) if m else None


def decode_arm(insn):
    m = insn.mnem.lower()
    ops = insn.ops.lower()
    for suf in (".w", ".n"):
        if m.endswith(suf):
            m = m[:-2]
    if m.startswith("v"):
        return decode_vfp(insn, m, ops)
    if re.fullmatch(r"it[te]{0,3}", m):
        insn.cls, insn.sub = "alu", "it"
        return
    sp = arm_split(m)
    if sp is None:
        insn.cls, insn.sub = "other", m
        return
    base, _s, cond = sp
    insn.cond = cond not in ("", "al")
    insn.sub = base
    cls = ARM_BASES[base][0]
    regs = arm_regs(ops)
    if cls in ("alu", "mul", "mla", "mull", "mlal", "div"):
        insn.cls = "mul_long" if cls in ("mull", "mlal") else ("mul" if cls == "mla" else cls)
        if cls == "alu" and base in ("cmp", "cmn", "tst", "teq", "nop", "yield", "sev"):
            insn.defs = ()
        elif cls in ("mull", "mlal"):
            insn.defs = tuple(regs[:2])
        else:
            insn.defs = tuple(regs[:1])
        if cls == "alu" and insn.defs == ("r15",):
            insn.br = "jump_reg"
        return
    if cls in ("load", "store"):
        insn.cls = cls
        inner = re.search(r"\[([^\]]*)\]", ops)
        insn.aregs = tuple(arm_regs(inner.group(1))) if inner else ()
        # register offset: a second register inside the brackets
        insn.sub = base + ("_reg" if len(insn.aregs) > 1 else "")
        if cls == "load":
            insn.defs = tuple(regs[:1])
            if regs[:1] == ["r15"]:
                insn.br = "pc_load"
                insn.ret = insn.aregs[:1] == ("r13",)
        return
    if cls in ("load_multi", "store_multi"):
        insn.cls = cls
        if base in ("ldrd", "strd"):
            inner = re.search(r"\[([^\]]*)\]", ops)
            insn.aregs = tuple(arm_regs(inner.group(1))) if inner else ()
            insn.nregs = 2
            insn.sub = base
            if base == "ldrd":
                insn.defs = tuple(regs[:2])
            return
        n, pc, lst = arm_reglist(ops)
        insn.nregs = n
        insn.aregs = ("r13",) if base in ("push", "pop") else tuple(regs[:1])
        if cls == "load_multi":
            insn.defs = tuple(lst)
            if pc:
                insn.br = "pc_load"
                insn.ret = True
        insn.sub = "pop" if base == "pop" else ("push" if base == "push" else base[:3])
        return
    if cls == "branch":
        insn.cls = "branch"
        if base == "b":
            insn.br = "cond" if insn.cond else "jump"
            insn.target = arm_target(ops)
        elif base in ("cbz", "cbnz"):
            insn.br = "cond"
            insn.cond = True
            insn.target = arm_target(ops)
        elif base == "bl":
            insn.br, insn.call = "jump", True
            insn.target = arm_target(ops)
        elif base == "blx":
            insn.br, insn.call = "jump_reg", True
        elif base == "bx":
            insn.br = "jump_reg"
            insn.ret = ops.strip() == "lr"
        elif base in ("tbb", "tbh"):
            insn.br = "tb"
        return
    insn.cls = "system"
    if base == "mrs":
        insn.defs = tuple(regs[:1])


VFP_ALU = set("vadd vsub vmul vnmul vabs vneg vcmp vcmpe vcvt vcvtr vcvta vcvtn vcvtp vcvtm vmov vmrs vmsr "
              "vsel vseleq vselge vselgt vselvs vmaxnm vminnm vrinta vrintn vrintp vrintm vrintr vrintx vrintz".split())
VFP_MAC = set("vmla vmls vnmla vnmls vfma vfms vfnma vfnms".split())


def decode_vfp(insn, m, ops):
    parts = m.split(".")
    base = parts[0]
    # a condition suffix inside an IT block: vaddeq.f32
    if base not in VFP_ALU and base not in VFP_MAC and base[-2:] in CONDS and len(base) > 3:
        insn.cond = True
        base = base[:-2]
    insn.sub = base
    dbl = "f64" in parts or re.search(r"\bd\d+\b", ops.split(",")[0] if ops else "") is not None
    if base in ("vldr", "vstr"):
        insn.cls = "fpu_load" if base == "vldr" else "fpu_store"
        insn.wide = dbl
        inner = re.search(r"\[([^\]]*)\]", ops)
        insn.aregs = tuple(arm_regs(inner.group(1))) if inner else ()
        return
    if base in ("vldm", "vldmia", "vldmdb", "vpop", "vstm", "vstmia", "vstmdb", "vpush"):
        insn.cls = "fpu_load" if base.startswith(("vldm", "vpop")) else "fpu_store"
        insn.nregs = arm_reglist(ops)[0]
        insn.sub = "vldm" if insn.cls == "fpu_load" else "vstm"
        insn.aregs = ("r13",) if base in ("vpush", "vpop") else tuple(arm_regs(ops)[:1])
        return
    if base in ("vdiv", "vsqrt"):
        insn.cls = "fpu_divsqrt"
        return
    if base in VFP_MAC:
        insn.cls = "fpu_mac"
        return
    if base in VFP_ALU:
        insn.cls = "fpu_alu"
        if base == "vmov":
            core = arm_regs(ops)
            insn.wide = len(core) >= 2
            # vmov r0, s15 writes a core register
            if ops and ARM_REG_RE.match(ops.strip()):
                insn.defs = tuple(core[:2] if insn.wide else core[:1])
        elif base == "vmrs":
            r = arm_regs(ops)
            insn.defs = tuple(r[:1])
        return
    insn.cls, insn.sub = "other", m


RV_ALU = set("lui auipc addi slti sltiu xori ori andi slli srli srai add sub sll slt sltu xor srl sra or and "
             "mv li nop not neg seqz snez sltz sgtz".split())
RV_BR = set("beq bne blt bge bltu bgeu beqz bnez blez bgez bltz bgtz bgt ble bgtu bleu".split())
RV_LOAD = {"lw": "lw", "lh": "lbh", "lhu": "lbh", "lb": "lbh", "lbu": "lbh", "lr.w": "lw"}
RV_STORE = set("sw sh sb sc.w".split())
RV_MUL = set("mul mulh mulhu mulhsu".split())
RV_DIV = set("div divu rem remu".split())
RV_REG_RE = re.compile(r"\b(zero|ra|sp|gp|tp|fp|t[0-6]|s1[01]|s[0-9]|a[0-7]|x\d+)\b")


def rv_regs(text):
    return [("s0" if r == "fp" else r) for r in RV_REG_RE.findall(text)]


def decode_riscv(insn):
    m = insn.mnem.lower()
    if m.startswith("c."):
        m = m[2:]
    ops = insn.ops.split("#")[0]
    tm = re.search(r"#\s*(0x[0-9a-f]+)", insn.ops)
    regs = rv_regs(ops)
    insn.sub = m
    if m in RV_ALU:
        insn.cls = "alu"
        insn.defs, insn.uses = tuple(regs[:1]), tuple(regs[1:])
    elif m in RV_LOAD:
        insn.cls, insn.sub = "load", RV_LOAD[m]
        insn.defs, insn.uses = tuple(regs[:1]), tuple(regs[1:])
    elif m in RV_STORE:
        insn.cls = "store"
        insn.defs, insn.uses = (tuple(regs[:1]) if m == "sc.w" else ()), tuple(regs)
    elif m in RV_MUL:
        insn.cls = "mul" if m == "mul" else "mul_long"
        insn.defs, insn.uses = tuple(regs[:1]), tuple(regs[1:])
    elif m in RV_DIV:
        insn.cls = "div"
        insn.defs, insn.uses = tuple(regs[:1]), tuple(regs[1:])
    elif m in RV_BR:
        insn.cls, insn.br, insn.cond = "branch", "cond", True
        insn.uses = tuple(regs)
        insn.target = int(tm.group(1), 16) if tm else None
    elif m in ("j", "jal"):
        insn.cls, insn.br = "branch", "jump"
        insn.target = int(tm.group(1), 16) if tm else None
        rd = regs[0] if (m == "jal" and regs) else "zero"
        insn.call = rd in ("ra", "t0")
        insn.defs = (rd,)
    elif m in ("jr", "jalr", "ret"):
        insn.cls, insn.br = "branch", "jump_reg"
        if m == "ret":
            insn.ret, insn.uses = True, ("ra",)
        elif m == "jr":
            insn.uses = tuple(regs[:1])
            insn.ret = regs[:1] in (["ra"], ["t0"])  # the link registers the RAS pops on
        else:
            # "jalr ra,a5,0" or "jalr a5"
            if len(regs) >= 2:
                insn.defs, insn.uses = (regs[0],), (regs[1],)
            else:
                insn.defs, insn.uses = ("ra",), tuple(regs)
            insn.call = insn.defs[0] in ("ra", "t0")
            insn.ret = insn.defs[0] == "zero" and insn.uses in (("ra",), ("t0",))
    elif m.startswith("csr") or m in ("rdcycle", "rdtime", "rdinstret", "frrm", "fsrm"):
        insn.cls = "system"
        insn.sub = "csr"
        insn.defs, insn.uses = tuple(regs[:1]), tuple(regs[1:])
    elif m.startswith("amo"):
        insn.cls, insn.sub = "load", "amo"
        insn.defs, insn.uses = tuple(regs[:1]), tuple(regs[1:])
    elif m in ("ecall", "ebreak", "fence", "fence.i", "wfi", "mret", "sret", "unimp"):
        insn.cls = "system"
    else:
        insn.cls = "other"
    insn.defs = tuple(r for r in insn.defs if r not in ("zero", "x0"))


# ---------------------------------------------------------------------------
# cycle models: per-instruction costs inside a block, and branch costs on edges

def arm_block_costs(insns, core, p):
    """Cumulative cycles after each instruction, and cycles by class, for one block
    (branch refills excluded: they depend on the next block)."""
    cum, by = [0], collections.Counter()
    prev = None
    for ins in insns:
        c, stall = arm_insn_cost(ins, prev, core, p)
        by[ins.cls] += c
        if stall:
            by["stall:agu"] += stall
        cum.append(cum[-1] + c + stall)
        prev = ins
    return cum, by


def arm_insn_cost(ins, prev, core, p):
    cls, sub = ins.cls, ins.sub
    stall = 0
    if core == "m0":
        if cls in ("load", "store"):
            c = 2
        elif cls in ("load_multi", "store_multi"):
            c = 1 + ins.nregs - (1 if ins.br == "pc_load" else 0)
        elif cls == "mul":
            c = p["muls"]
        elif cls == "system":
            c = 4 if sub in ("dmb", "dsb", "isb", "mrs", "msr") else (2 if sub in ("wfi", "wfe") else 1)
        else:
            c = 1
        return c, 0
    # Cortex-M3 / M4
    if cls == "alu":
        c = 1
    elif cls == "mul":
        c = p["mla"] if sub in ("mla", "mls") else 1
    elif cls == "mul_long":
        c = p["mlal"] if sub in ("smlal", "umlal", "umaal") or sub.startswith("sml") else p["mull"]
    elif cls == "div":
        c = p["div"]
    elif cls == "load":
        c = 2
        if prev is not None and prev.cls == "load" and prev.br is None and not (set(prev.defs) & set(ins.aregs)):
            c = 1
    elif cls == "store":
        c = 2 if sub.endswith("_reg") else 1
        if prev is not None and prev.cls == "load" and prev.br is None and not (set(prev.defs) & set(ins.aregs)):
            c = 1
    elif cls in ("load_multi", "store_multi"):
        c = 3 if sub in ("ldrd", "strd") else 1 + ins.nregs
    elif cls == "branch":
        c = 3 if ins.br == "tb" else 1
    elif cls == "system":
        c = 4 if sub == "isb" else 1
    elif cls == "fpu_load" or cls == "fpu_store":
        c = 1 + ins.nregs if sub in ("vldm", "vstm") else (3 if ins.wide else 2)
    elif cls == "fpu_alu":
        c = 2 if (sub == "vmov" and ins.wide) else 1
    elif cls == "fpu_mac":
        c = 3
    elif cls == "fpu_divsqrt":
        c = 14
    else:
        c = 1
    if ins.aregs and prev is not None and prev.cls in ("alu", "mul", "mul_long", "div") \
            and set(prev.defs) & set(ins.aregs):
        stall = 1
    return c, stall


def arm_branch_extra(ins, core, p):
    """Cycles a taken control transfer adds on top of the instruction's own cost."""
    br = ins.br
    if core == "m0":
        # B<cond>/B 3, BL 4, BX/BLX/MOV PC 3 in all; POP {..,PC} 4+N
        if br == "pc_load" or (ins.call and ins.sub == "bl"):
            return 3
        return 2
    if br in ("pc_load", "tb"):
        return p["P_load"]
    if br == "jump_reg":
        return p["P_reg"]
    return p["P_imm"]


RV_LAT = {"lw": 2, "lbh": 3, "amo": 3, "csr": 3}


def e31_block_costs(insns, p):
    """In-order scoreboard inside one block: cumulative cycles and cycles by class."""
    ready = {}
    src_kind = {}
    mbusy = 0
    t = 0
    cum, by = [0], collections.Counter()
    for ins in insns:
        start = t
        why = None
        for r in ins.uses:
            if ready.get(r, 0) > start:
                start, why = ready[r], src_kind[r]
        if ins.cls in ("mul", "mul_long", "div") and mbusy > start:
            start, why = mbusy, "muldiv"
        if start > t:
            by["stall:" + ("load-use" if why == "load" else "muldiv")] += start - t
        by[ins.cls] += 1
        if ins.cls in ("mul", "mul_long"):
            lat = 5
            if p["mul_block"]:
                mbusy = start + lat
        elif ins.cls == "div":
            lat = p["div"]
            mbusy = start + lat
        elif ins.cls == "load" or ins.sub == "csr":
            lat = RV_LAT.get(ins.sub, 2)
        else:
            lat = 1
        for r in ins.defs:
            ready[r] = start + lat
            src_kind[r] = "load" if ins.cls == "load" else ("muldiv" if lat > 1 else "alu")
        t = start + 1
        cum.append(t)
    if p["drain"] and mbusy > t:  # a multiply or divide still in flight is waited for
        by["stall:muldiv"] += mbusy - t
        cum[-1] = mbusy
    return cum, by


def e31_branch_extra(ins, dst, taken, p, ps):
    """Misprediction cycles of a block's last instruction."""
    br = ins.br
    if br == "cond":
        if ps == "min":
            return 0
        if ps == "max":
            return p["mispredict"]
        # static backward-taken / forward-not-taken prediction
        tgt = dst if taken else ins.target
        backward = tgt is not None and tgt <= ins.addr
        return p["mispredict"] if taken != backward else 0
    if br == "jump_reg" and not ins.ret:
        return p["indirect"]
    return 0


# ---------------------------------------------------------------------------
# translations


class Block:
    __slots__ = ("pc", "insns", "fall", "last", "cum", "by", "counts", "func", "regs")

    def __init__(self, pc, insns):
        self.pc = pc
        self.insns = insns
        last = insns[-1] if insns else None
        self.last = last
        self.fall = last.addr + last.size if last else pc
        self.cum = {}
        self.by = {}
        self.counts = None
        self.func = None


INSN_LINE = re.compile(rb"^0x([0-9a-f]+):\s+((?:[0-9a-f]{4,8}\s)+)\s*(\S+)\s*(.*?)\s*$")


def parse_insn_line(line):
    m = INSN_LINE.match(line)
    if not m:
        return None
    hexes = m.group(2).split()
    size = sum(len(h) for h in hexes) // 2
    return Insn(int(m.group(1), 16), size, m.group(3).decode(), m.group(4).decode())


SPECIAL = re.compile(rb"\n(?!Trace )")  # a newline before a line that is not a Trace line
TRACE_PC = re.compile(rb"\[[0-9a-f]+/([0-9a-f]+)/")


def trace_pc(line):
    m = TRACE_PC.search(line)
    return int(m.group(1), 16) if m else None


# ---------------------------------------------------------------------------
# the streaming log parser


class Extents:
    """Where the run is: the dynamic extents of chosen functions, followed with a
    shadow call stack that holds their frames only.

    A frame is pushed on a Trace line at a tracked function's entry when the
    block logged before it ends in a call (BL/BLX; JAL/JALR writing ra or t0):
    its return address is that call's fall-through. It is popped on a Trace
    line at its return address when the block before it ends in a return or
    another indirect jump (BX LR, POP/LDM/LDR with PC, ret, jalr): a join point
    of the caller that happens to be a call's fall-through address, reached by
    a branch, is no return. A return to a frame below the top pops every frame
    above it too (calls that never returned to their own caller).

    Functions that are not tracked need no frame: their returns go to their
    own call sites, and a tail call out of a tracked function returns to that
    function's return address all the same. (What would fool it: an indirect
    call site that calls a tracked function and is itself re-entered, by
    recursion, inside that function's extent, calling an untracked one.) An
    entry that does not follow a call (a tail call into a tracked function)
    gets no frame: a warning, and its instructions stay with the caller.

    The base class is --from-symbol / --exclude-symbol: buckets "outside",
    "region" (inside the root's extent) and "excluded" (inside an excluded
    function's extent called from the root's own frame). Subclasses choose
    what can be entered where (enterable), what an entry does (enter) and the
    bucket of each state (label).
    """

    class Frame:
        __slots__ = ("pc", "ret", "kind", "note")

        def __init__(self, pc, ret):
            self.pc, self.ret, self.kind, self.note = pc, ret, None, None

    def __init__(self, root=None, excludes=(), warnings=None):
        self.root = root                   # PC of --from-symbol, or None: count all
        self.excludes = frozenset(excludes)
        self.stack = []
        self.entries = collections.Counter()   # entry PC -> frames pushed
        self.warnings = warnings if warnings is not None else collections.Counter()
        self.changed()

    # -- policy -------------------------------------------------------------------
    def enterable(self):
        """Entry PCs that push a frame (or do something) in the current state."""
        if self.root is None:
            return ()
        if not self.stack:
            return (self.root,)
        if self.stack[-1].pc == self.root:
            return tuple(self.excludes)
        return ()

    def label(self):
        """The bucket of the current state."""
        if self.root is None:
            return "region"
        if not self.stack:
            return "outside"
        return "excluded" if self.stack[-1].pc in self.excludes else "region"

    def enter(self, frame):
        """A call reached an enterable PC: whether the frame is pushed."""
        return True

    def not_a_call(self, pc):
        return "entered --%s-symbol not by a call: ignored" % ("from" if pc == self.root else "exclude")

    # -- mechanism ----------------------------------------------------------------
    def changed(self):
        self.bucket = self.label()
        self.enter_pcs = frozenset(self.enterable())
        self.watch_pcs = self.enter_pcs | frozenset(f.ret for f in self.stack)
        self.watch_list = tuple(self.watch_pcs)

    def step(self, pc, prev):
        """A Trace line at a watched PC; prev is the Block logged before it (None if
        it had no translation listing)."""
        last = prev.last if prev is not None else None
        if last is not None and (last.ret or (last.br in ("jump_reg", "pc_load") and not last.call)):
            for i in range(len(self.stack) - 1, -1, -1):
                if self.stack[i].ret == pc:
                    if i < len(self.stack) - 1:
                        self.warnings["a return went past %d tracked frame(s)" % (len(self.stack) - 1 - i)] += 1
                    del self.stack[i:]
                    self.changed()
                    return
        if pc in self.enter_pcs:
            if last is None or not last.call:
                self.warnings[self.not_a_call(pc)] += 1
                return
            f = self.Frame(pc, prev.fall)
            if self.enter(f):
                self.stack.append(f)
                self.entries[pc] += 1
            self.changed()


class Parser:
    """Reads the QEMU log; keeps, per bucket (outside / region / excluded, or the
    buckets of another Extents), a counter of edges (block key, next block key)
    and of partial executions."""

    def __init__(self, model, entry=None, excludes=(), extents=None):
        self.model = model                 # decodes each translation when it is bound
        self.warnings = collections.Counter()
        self.extents = extents if extents is not None else Extents(entry, excludes)
        self.extents.warnings = self.warnings
        self.edges = collections.defaultdict(collections.Counter)
        self.partial = collections.defaultdict(collections.Counter)
        self.blocks = {}                   # key -> Block
        self.prev = None                   # edge source (None after a stop or a rewind)
        self.last = None                   # the last Trace line
        self.pending = None                # translation waiting for its Trace line
        self.pending_partial = None        # (bucket, key) rewound by cpu_io_recompile
        self.in_block = None               # (symbol, insns) while reading in_asm
        self.stopped = None                # PC of a block that was logged but did not run
        self.stops = 0
        self.rewinds = 0
        self.translations = 0
        self.lines = 0
        self.leftover = b""
        self._wcache = {}

    # -- region state (Extents) ------------------------------------------------
    @property
    def bucket(self):
        return self.extents.bucket

    @property
    def entry(self):
        return self.extents.root

    @property
    def excludes(self):
        return self.extents.excludes

    @property
    def entries(self):
        """Calls of --from-symbol (outside its own extent)."""
        return self.extents.entries[self.extents.root] if self.extents.root is not None else 0

    @property
    def ex_entries(self):
        """Calls of --exclude-symbol functions counted apart."""
        return sum(self.extents.entries[pc] for pc in self.extents.excludes)

    def watch(self):
        """PCs whose Trace line may change the state, for the current state."""
        return self.extents.watch_list

    # -- lines ------------------------------------------------------------------
    def trace_line(self, line):
        pc = trace_pc(line)
        if self.pending is not None:
            bpc, insns, sym = self.pending
            self.pending = None
            if pc == bpc:
                blk = Block(bpc, insns)
                self.model.prepare(blk)
                self.blocks[line] = blk
            else:
                self.warnings["translation not followed by its execution"] += 1
        if self.pending_partial is not None:
            bucket, key = self.pending_partial
            self.pending_partial = None
            self.partial[bucket][(key, pc)] += 1
        self.edges[self.bucket][(self.prev, line)] += 1
        if pc in self.extents.watch_pcs and pc != self.stopped:
            self.extents.step(pc, self.blocks.get(self.last) if self.last is not None else None)
        self.stopped = None
        self.prev = self.last = line

    def other_line(self, line):
        if self.in_block is not None:
            if line.startswith(b"0x"):
                ins = parse_insn_line(line)
                if ins is None:
                    self.warnings["unparsed in_asm line: %r" % line[:60]] += 1
                else:
                    self.in_block[1].append(ins)
                return
            if line.startswith(b"Priv:") or line.startswith(b"OBJD"):
                return
            sym, insns = self.in_block
            self.in_block = None
            if insns:
                self.pending = (insns[0].addr, insns, sym)
                self.translations += 1
            if line.strip() == b"":
                return
        if line.startswith(b"IN:"):
            self.in_block = (line[3:].strip().decode(errors="replace"), [])
        elif line.startswith(b"Stopped execution"):
            self.stops += 1
            if self.prev is not None:
                # the block logged last did not run: its incoming edge stays (it
                # tells the previous block's branch outcome), it has no outgoing one
                m = re.search(rb"before (0x[0-9a-f]+)", line)
                if m and not self.prev.split(b" [")[0].endswith(m.group(1)):
                    self.warnings["Stopped line for another block than the last"] += 1
                self.prev = None
                # its Trace line made any state change already: not again when it
                # runs (or the entry of a block that ends in a call would be taken
                # for a second call)
                self.stopped = trace_pc(self.last)
        elif line.startswith(b"cpu_io_recompile"):
            self.rewinds += 1
            if self.prev is not None:
                # it ran in the current bucket: a state change happens on the
                # Trace line of the block after a boundary, before it can run
                self.pending_partial = (self.bucket, self.prev)
            self.prev = None
        elif line.startswith(b"----") or line.strip() == b"":
            pass
        else:
            self.warnings["unknown log line: %r" % line[:60]] += 1

    def line(self, line):
        if line.startswith(b"Trace "):
            self.trace_line(line)
        else:
            self.other_line(line)

    # -- chunks -----------------------------------------------------------------
    def feed(self, data):
        data = self.leftover + data
        cut = data.rfind(b"\n")
        if cut < 0:
            self.leftover = data
            return
        self.leftover = data[cut + 1:]
        self.chunk(data[:cut + 1])

    def finish(self):
        if self.leftover:
            self.chunk(self.leftover + b"\n")
            self.leftover = b""
        if self.in_block is not None:
            self.other_line(b"")
        if self.prev is not None:
            self.edges[self.bucket][(self.prev, None)] += 1
            self.prev = None

    def chunk(self, data):
        """data: whole lines, ending with a newline."""
        n = len(data)
        self.lines += data.count(b"\n")
        self._wcache = {}
        pos = 0
        special = -1
        while pos < n:
            if self.pending is not None or self.pending_partial is not None or self.in_block is not None:
                end = data.index(b"\n", pos)
                self.line(data[pos:end])
                pos = end + 1
                continue
            # the next line that is not a plain Trace line (remembered: the
            # state may change many times before it)
            if special < pos:
                if pos == 0 and not data.startswith(b"Trace "):
                    special = 0
                else:
                    m = SPECIAL.search(data, pos - 1 if pos else 0)
                    special = m.start() + 1 if m else n
            stop = special
            w = self.find_watch(data, pos, stop)
            if w is not None:
                stop = w
            if stop > pos:
                self.fast(data, pos, stop)
                pos = stop
            if pos < n:
                end = data.index(b"\n", pos)
                self.line(data[pos:end])
                pos = end + 1

    def find_watch(self, data, pos, stop):
        """Start of the first Trace line in data[pos:stop] whose PC is watched.
        The next line of each PC is remembered for the rest of the chunk, so a
        chunk is scanned once per watched PC however many times the state changes."""
        best = None
        for pc in self.watch():
            if pc is None:
                continue
            ls = self._wcache.get(pc)
            if ls is None or ls < pos:
                ls = self._wcache[pc] = self.find_pc(data, pc, pos)
            if ls < stop and (best is None or ls < best):
                best = ls
        return best

    @staticmethod
    def find_pc(data, pc, pos):
        """Start of the first Trace line at or after pos whose PC is pc, or len(data)."""
        pat = b"/%08x/" % pc
        i = data.find(pat, pos)
        while i >= 0:
            ls = max(data.rfind(b"\n", 0, i) + 1, pos)
            if trace_pc(data[ls:data.index(b"\n", i)]) == pc:
                return ls
            i = data.find(pat, i + 1)
        return len(data)

    def fast(self, data, pos, stop):
        """Plain Trace lines that change no state: count their edges in C."""
        lines = data[pos:stop - 1].split(b"\n")
        self.edges[self.bucket].update(zip(itertools.chain((self.prev,), lines), lines))
        self.prev = self.last = lines[-1]
        self.stopped = None


# ---------------------------------------------------------------------------
# symbols


def read_symbols(elf, isa, nm=None):
    tools = [nm] if nm else NM[isa]
    for tool in tools:
        if shutil.which(tool):
            break
    else:
        sys.exit("cycles: no nm found (tried %s); pass --nm" % ", ".join(tools))
    out = subprocess.run([tool, "-n", "--defined-only", elf], check=True, capture_output=True, text=True).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) != 3 or parts[1] not in "tTwW":
            continue
        addr = int(parts[0], 16)
        if isa == "arm":
            addr &= ~1
        syms.append((addr, parts[2]))
    syms.sort()
    return syms


def symbol_addr(syms, name):
    for a, n in syms:
        if n == name:
            return a
    sys.exit("cycles: symbol %s not found in the ELF" % name)


# ---------------------------------------------------------------------------
# running QEMU


DRAWN = b"T\x07\x00drawn 1"   # the report record of a board that holds its frame (sink.h)
# the last report record of a board built for silicon (no semihosting: it
# sleeps after it, and QEMU does not exit on WFI)
EXIT_STATUS = re.compile(rb"T.\x00exit_status (\d+)$")


def run_qemu(args, parser):
    """Start QEMU logging into a named pipe and parse the pipe while it runs."""
    tmp = tempfile.mkdtemp(prefix="cycles-")
    fifo = os.path.join(tmp, "qemu.log")
    os.mkfifo(fifo)
    stream_path = args.stream or os.path.join(tmp, "uart.stream")
    cmd = [args.qemu, "-M", QEMU_MACHINE.get(args.machine, args.machine), "-nographic", "-monitor", "none",
           "-semihosting-config", "enable=on,target=native", "-icount", "shift=0",
           "-kernel", args.elf, "-d", "in_asm,exec,nochain", "-D", fifo] + args.qemu_arg
    t0 = time.time()
    with open(stream_path, "wb") as out, open(os.path.join(tmp, "qemu.err"), "wb") as err:
        proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=out, stderr=err)
        opened = threading.Event()

        held = []

        def watchdog():
            # A board whose sink holds the frame on its panel reports
            # "drawn 1" and idles instead of exiting, one built for
            # silicon ends with "exit_status N" and sleeps: end QEMU there.
            # QEMU may die before it opens the log: unblock our open() then
            deadline = time.time() + args.timeout
            while True:
                try:
                    proc.wait(timeout=0.5)
                    break
                except subprocess.TimeoutExpired:
                    pass
                with open(stream_path, "rb") as s:
                    data = s.read()
                    end = EXIT_STATUS.search(data)
                    if DRAWN in data or end:
                        held.append(int(end.group(1)) if end else 0)
                if held or time.time() > deadline:
                    proc.kill()
                    proc.wait()
                    break
            if not opened.is_set():
                fd = os.open(fifo, os.O_RDWR | os.O_NONBLOCK)
                os.close(fd)
        threading.Thread(target=watchdog, daemon=True).start()
        try:
            read_pipe(fifo, parser, opened)
        finally:
            if proc.poll() is None:  # interrupted: do not leave QEMU behind
                proc.kill()
        rc = proc.wait()
        if held:
            rc = held[0]
    t1 = time.time()
    with open(stream_path, "rb") as s:
        stream = s.read()
    with open(os.path.join(tmp, "qemu.err"), "rb") as e:
        errtext = e.read().decode(errors="replace")
    shutil.rmtree(tmp, ignore_errors=True)
    return rc, stream, errtext, t1 - t0, cmd


def read_pipe(fifo, parser, opened):
    """Feed the parser from the named pipe until QEMU closes it."""
    with open(fifo, "rb", buffering=0) as f:
        opened.set()
        try:
            if fcntl is not None:
                fcntl.fcntl(f.fileno(), 1031, 1 << 20)  # F_SETPIPE_SZ: fewer, larger reads
        except OSError:
            pass
        buf = []
        size = 0
        while True:
            data = os.read(f.fileno(), 1 << 20)
            if not data:
                break
            buf.append(data)
            size += len(data)
            if size >= (4 << 20):
                parser.feed(b"".join(buf))
                buf, size = [], 0
            elif len(data) < (256 << 10):
                # QEMU writes (and flushes) one line at a time: let the pipe
                # fill instead of waking up for every line
                time.sleep(0.005)
        if buf:
            parser.feed(b"".join(buf))
    parser.finish()


def parse_log_file(path, parser):
    with open(path, "rb") as f:
        while True:
            data = f.read(4 << 20)
            if not data:
                break
            parser.feed(data)
    parser.finish()


# ---------------------------------------------------------------------------
# turning counts into a report


CLASS_ORDER = ["alu", "mul", "mul_long", "div", "load", "store", "load_multi", "store_multi",
               "branch", "fpu_alu", "fpu_mac", "fpu_divsqrt", "fpu_load", "fpu_store", "system", "other"]
CLASS_DOC = {
    "alu": "data processing, moves, compares, shifts, IT",
    "mul": "32-bit multiply (MUL, MLA, MLS; RISC-V mul)",
    "mul_long": "64-bit product (SMULL/UMULL/SMLAL/UMLAL; mulh*)",
    "div": "divide (SDIV/UDIV; div/rem)",
    "load": "single load",
    "store": "single store",
    "load_multi": "LDM/POP/LDRD",
    "store_multi": "STM/PUSH/STRD",
    "branch": "branches, calls, returns (BX, CBZ, TBB; j/jal/jalr)",
    "fpu_alu": "FPU add/sub/mul/abs/neg/cmp/cvt/mov",
    "fpu_mac": "FPU multiply-accumulate",
    "fpu_divsqrt": "VDIV, VSQRT",
    "fpu_load": "VLDR/VLDM/VPOP",
    "fpu_store": "VSTR/VSTM/VPUSH",
    "system": "barriers, system registers, CSR, ecall/ebreak",
    "other": "not classified (1 cycle)",
}


class Model:
    def __init__(self, core):
        self.core = core
        self.isa = CORE_ISA[core]
        self.params = {ps: {k: v[i] for k, v in PARAMS[core].items()} for i, ps in enumerate(PSETS)}

    def prepare(self, blk):
        if blk.counts is not None:
            return
        for ins in blk.insns:
            (decode_arm if self.isa == "arm" else decode_riscv)(ins)
        blk.counts = collections.Counter(ins.cls for ins in blk.insns)
        blk.regs = collections.Counter()
        for ins in blk.insns:
            if ins.nregs:
                blk.regs[ins.cls] += ins.nregs
        for ps in PSETS:
            blk.cum[ps], blk.by[ps] = self.costs(blk.insns, self.params[ps])

    def costs(self, insns, p):
        if self.isa == "arm":
            return arm_block_costs(insns, self.core, p)
        return e31_block_costs(insns, p)

    def branch_extra(self, blk, dst, ps):
        """Extra cycles of the block's last instruction when the next block starts at dst."""
        ins = blk.last
        if ins is None or ins.br is None or dst is None:
            return 0
        taken = dst != blk.fall if is_conditional(ins) else True
        if self.isa == "arm":
            return arm_branch_extra(ins, self.core, self.params[ps]) if taken else 0
        return e31_branch_extra(ins, dst, taken, self.params[ps], ps)


def is_conditional(ins):
    """A conditional branch, or a PC write inside an IT block (bxeq lr, popne {.., pc})."""
    return ins.br == "cond" or ins.cond


def tally(parser, model, bucket, syms):
    """Totals for one bucket: instructions, per class, cycles per parameter set."""
    res = {"instructions": 0, "classes": collections.Counter(), "class_cycles": collections.Counter(),
           "cycles": dict.fromkeys(PSETS, 0), "cond_taken": 0, "cond_not_taken": 0, "jumps": 0,
           "regs": collections.Counter(), "funcs": collections.Counter(), "func_insns": collections.Counter(),
           "unknown_blocks": 0, "other_mnemonics": collections.Counter(), "refill": 0}
    addrs = [a for a, _ in syms]
    blocks = parser.blocks

    def func_of(pc):
        i = bisect.bisect_right(addrs, pc) - 1
        return syms[i][1] if i >= 0 else "?"

    def add_block(blk, n, cnt, cum_k, by=None):
        res["instructions"] += n * cnt
        for ps in PSETS:
            res["cycles"][ps] += blk.cum[ps][cum_k] * cnt
        if blk.func is None:
            blk.func = func_of(blk.pc)
        res["funcs"][blk.func] += blk.cum["typ"][cum_k] * cnt
        res["func_insns"][blk.func] += n * cnt

    for (src, dst), cnt in parser.edges[bucket].items():
        if src is None:
            continue
        blk = blocks.get(src)
        if blk is None:
            res["unknown_blocks"] += cnt
            continue
        model.prepare(blk)
        n = len(blk.insns)
        add_block(blk, n, cnt, n)
        for c, k in blk.counts.items():
            res["classes"][c] += k * cnt
        for c, k in blk.by["typ"].items():
            res["class_cycles"][c] += k * cnt
        for c, k in blk.regs.items():
            res["regs"][c] += k * cnt
        for ins in blk.insns:
            if ins.cls == "other":
                res["other_mnemonics"][ins.mnem] += cnt
        last = blk.last
        if last is not None and last.br is not None:
            dpc = trace_pc(dst) if dst is not None else None
            if dst is None:
                pass
            elif is_conditional(last):
                if dpc != blk.fall:
                    res["cond_taken"] += cnt
                else:
                    res["cond_not_taken"] += cnt
            else:
                res["jumps"] += cnt
            if dst is not None:
                for ps in PSETS:
                    e = model.branch_extra(blk, dpc, ps)
                    res["cycles"][ps] += e * cnt
                    if ps == "typ":
                        res["refill"] += e * cnt
                        res["funcs"][blk.func] += e * cnt
    for (src, pc), cnt in parser.partial[bucket].items():
        blk = blocks.get(src)
        if blk is None:
            res["unknown_blocks"] += cnt
            continue
        model.prepare(blk)
        k = sum(1 for ins in blk.insns if ins.addr < pc) if blk.pc <= pc < blk.fall else len(blk.insns)
        add_block(blk, k, cnt, k)
        pre = blk.insns[:k]
        for ins in pre:
            res["classes"][ins.cls] += cnt
            if ins.nregs:
                res["regs"][ins.cls] += ins.nregs * cnt
        _cum, by = model.costs(pre, model.params["typ"])
        for c, v in by.items():
            res["class_cycles"][c] += v * cnt
    res["class_cycles"]["stall:branch-refill" if model.isa == "arm" else "stall:mispredict"] += res["refill"]
    return res


def firmware_records(stream):
    rec = {}
    for key in (b"pixels", b"render_instructions", b"instructions_per_pixel"):
        m = re.search(rb"(?<![a-z_])" + key + rb" (\d+)", stream)
        if m:
            rec[key.decode()] = int(m.group(1))
    return rec


def run_firmware(args, parser, records, tool, extra):
    """Feed the parser from the saved log (--log; the board's output from
    --stream) or from a QEMU run; the board's report records (records(stream))
    and QEMU's time go into extra. Returns QEMU's status, a failure already
    reported on stderr."""
    if args.log:
        parse_log_file(args.log, parser)
        if args.stream and os.path.exists(args.stream):
            with open(args.stream, "rb") as f:
                extra["firmware"] = records(f.read())
        return 0
    rc, stream, errtext, secs, cmd = run_qemu(args, parser)
    extra["qemu_seconds"] = secs
    extra["firmware"] = records(stream)
    if rc != 0:
        sys.stderr.write(errtext)
        sys.stderr.write("%s: QEMU %s: %s\n" % (
            tool, "killed after %g s (--timeout)" % args.timeout if rc == -9 else "exited with status %d" % rc,
            " ".join(cmd)))
    return rc


def write_json(path, data, t0):
    """The figures as JSON, with the tool's run time since t0."""
    data["tool_seconds"] = time.time() - t0
    with open(path, "w") as f:
        json.dump(data, f, indent=1, sort_keys=True)
        f.write("\n")


def fmt_int(n):
    return "{:,}".format(n)


def report(args, parser, model, syms, extra):
    out = []
    region = tally(parser, model, "region", syms)
    total_insns = region["instructions"]
    excluded = tally(parser, model, "excluded", syms) if parser.excludes else None
    outside = tally(parser, model, "outside", syms) if parser.entry is not None else None
    whole = total_insns + (excluded["instructions"] if excluded else 0) + (outside["instructions"] if outside else 0)
    fw = extra.get("firmware", {})
    pixels = args.pixels or fw.get("pixels")

    what = ("inside %s (%d call%s)" % (args.from_symbol, parser.entries, "" if parser.entries == 1 else "s")
            if args.from_symbol else "whole run")
    if excluded:
        what += ", %s counted apart (%d calls)" % (", ".join(args.exclude_symbol), parser.ex_entries)
    out.append("core %s (%s), %s" % (model.core, args.machine, what))
    out.append("instructions            %15s" % fmt_int(total_insns))
    cyc = region["cycles"]
    out.append("cycles (typ)            %15s   min %s, max %s" % (fmt_int(cyc["typ"]), fmt_int(cyc["min"]), fmt_int(cyc["max"])))
    if total_insns:
        out.append("cycles per instruction  %15.3f   min %.3f, max %.3f" % (
            cyc["typ"] / total_insns, cyc["min"] / total_insns, cyc["max"] / total_insns))
    if pixels:
        out.append("per pixel (%d pixels)   instructions %.0f, cycles %.0f (min %.0f, max %.0f)" % (
            pixels, total_insns / pixels, cyc["typ"] / pixels, cyc["min"] / pixels, cyc["max"] / pixels))
    if args.clock_hz:
        out.append("time at %g MHz           %.3f s (min %.3f, max %.3f)" % (
            args.clock_hz / 1e6, cyc["typ"] / args.clock_hz, cyc["min"] / args.clock_hz, cyc["max"] / args.clock_hz))
    out.append("")
    out.append("%-12s %15s %7s %15s %7s  %s" % ("class", "instructions", "share", "cycles (typ)", "share", ""))
    classes = region["classes"]
    cc = region["class_cycles"]
    keys = [c for c in CLASS_ORDER if classes.get(c) or cc.get(c)] + sorted(c for c in classes if c not in CLASS_ORDER)
    for c in keys:
        note = CLASS_DOC.get(c, "")
        if c in ("load_multi", "store_multi", "fpu_load", "fpu_store") and region["regs"].get(c):
            note += "; %.2f registers each" % (region["regs"][c] / max(1, classes[c]))
        out.append("%-12s %15s %6.2f%% %15s %6.2f%%  %s" % (
            c, fmt_int(classes[c]), 100.0 * classes[c] / max(1, total_insns), fmt_int(cc[c]),
            100.0 * cc[c] / max(1, cyc["typ"]), note))
    for c in sorted(k for k in cc if k.startswith("stall:")):
        if cc[c]:
            out.append("%-12s %15s %7s %15s %6.2f%%" % (c.replace("stall:", "+"), "", "", fmt_int(cc[c]),
                                                          100.0 * cc[c] / max(1, cyc["typ"])))
    nb = region["cond_taken"] + region["cond_not_taken"]
    out.append("")
    out.append("conditional branches %s: taken %s (%.1f%%), not taken %s; other control transfers %s" % (
        fmt_int(nb), fmt_int(region["cond_taken"]), 100.0 * region["cond_taken"] / max(1, nb),
        fmt_int(region["cond_not_taken"]), fmt_int(region["jumps"])))
    if region["other_mnemonics"]:
        out.append("not classified: " + ", ".join("%s %d" % kv for kv in region["other_mnemonics"].most_common(12)))
    if args.top:
        out.append("")
        out.append("%-32s %15s %15s %6s %7s" % ("function", "instructions", "cycles (typ)", "CPI", "share"))
        for f, c in region["funcs"].most_common(args.top):
            ni = region["func_insns"][f]
            out.append("%-32s %15s %15s %6.2f %6.2f%%" % (f[:32], fmt_int(ni), fmt_int(c), c / max(1, ni),
                                                         100.0 * c / max(1, cyc["typ"])))
    out.append("")
    if excluded:
        out.append("excluded (%s): %s instructions, %s cycles (typ)" % (
            ", ".join(args.exclude_symbol), fmt_int(excluded["instructions"]), fmt_int(excluded["cycles"]["typ"])))
    out.append("whole run: %s instructions" % fmt_int(whole))
    if "render_instructions" in fw:
        ri = fw["render_instructions"]
        diff = total_insns - ri
        out.append("firmware's render_instructions %s (the board's counter, display sink subtracted): "
                   "counted here %s, difference %+d (%+.4f%%)" % (fmt_int(ri), fmt_int(total_insns), diff,
                                                                   100.0 * diff / max(1, ri)))
    st = "log: %s lines, %d translations, %d rewinds (I/O), %d stopped blocks" % (
        fmt_int(parser.lines), parser.translations, parser.rewinds, parser.stops)
    out.append(st)
    if region["unknown_blocks"]:
        out.append("warning: %d executions of blocks without a translation listing" % region["unknown_blocks"])
    for w, n in parser.warnings.most_common():
        out.append("warning: %s (%d)" % (w, n))
    if "qemu_seconds" in extra:
        out.append("QEMU + parsing %.1f s wall, tool total %.1f s" % (extra["qemu_seconds"], time.time() - extra["t0"]))
    data = {
        "core": model.core, "machine": args.machine, "elf": args.elf, "from_symbol": args.from_symbol,
        "exclude_symbols": args.exclude_symbol, "entries": parser.entries,
        "instructions": total_insns, "cycles": cyc, "classes": dict(classes),
        "class_cycles_typ": dict(cc), "cond_taken": region["cond_taken"], "cond_not_taken": region["cond_not_taken"],
        "other_control_transfers": region["jumps"], "pixels": pixels,
        "excluded_instructions": excluded["instructions"] if excluded else None,
        "whole_run_instructions": whole, "firmware": fw,
        "functions_typ_cycles": dict(region["funcs"].most_common(args.top or 20)),
        "params": model.params,
        "log": {"lines": parser.lines, "translations": parser.translations, "rewinds": parser.rewinds,
                "stops": parser.stops, "warnings": dict(parser.warnings),
                "unknown_block_executions": region["unknown_blocks"]},
    }
    return "\n".join(out), data


# ---------------------------------------------------------------------------


def main():
    t0 = time.time()
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="Cycle models and their sources: see the docstring (pydoc or the file head).")
    ap.add_argument("elf", nargs="?", help="firmware ELF (with --log: optional positional form of --elf)")
    ap.add_argument("--elf", dest="elf_opt", help=argparse.SUPPRESS)
    ap.add_argument("--machine", default=None, help="QEMU machine (default mps2-an385, or the core's board)")
    ap.add_argument("--core", choices=sorted(CORE_ISA), help="cycle model (default: the machine's core)")
    ap.add_argument("--qemu", help="QEMU binary (default: qemu-system-arm or qemu-system-riscv32)")
    ap.add_argument("--qemu-arg", action="append", default=[], help="extra QEMU argument (repeatable)")
    ap.add_argument("--from-symbol", help="count only inside the dynamic extent of this function")
    ap.add_argument("--exclude-symbol", action="append", default=[],
                    help="inside --from-symbol, count this function's calls apart (repeatable)")
    ap.add_argument("--pixels", type=int, help="pixels rendered (default: the firmware's 'pixels' record)")
    ap.add_argument("--clock-hz", type=float, help="also print the time at this clock")
    ap.add_argument("--top", type=int, default=10, help="functions to list by cycles (0: none)")
    ap.add_argument("--log", help="parse this saved QEMU log (-d in_asm,exec,nochain) instead of running QEMU")
    ap.add_argument("--stream", help="keep the board's UART output in this file (with --log: read it)")
    ap.add_argument("--json", help="also write the figures as JSON to this file")
    ap.add_argument("--nm", help="nm for the ELF's symbols (default: the target's binutils)")
    ap.add_argument("--timeout", type=float, default=900, help="seconds before QEMU is killed (default 900)")
    args = ap.parse_args()
    args.elf = args.elf or args.elf_opt
    if not args.elf:
        ap.error("an ELF is needed (for its symbols, and to run it)")
    if args.exclude_symbol and not args.from_symbol:
        ap.error("--exclude-symbol needs --from-symbol")
    if args.machine is None:
        args.machine = {"m0": "microbit", "m4": "mps2-an386", "e31": "sifive_e"}.get(args.core, "mps2-an385")
    if args.core is None:
        if args.machine not in MACHINES:
            ap.error("unknown machine %s: give --core" % args.machine)
        args.core = MACHINES[args.machine][0]
    isa = CORE_ISA[args.core]
    if args.qemu is None:
        args.qemu = MACHINES.get(args.machine, (None, "qemu-system-arm" if isa == "arm" else "qemu-system-riscv32"))[1]

    syms = read_symbols(args.elf, isa, args.nm)
    entry = symbol_addr(syms, args.from_symbol) if args.from_symbol else None
    excludes = [symbol_addr(syms, s) for s in args.exclude_symbol]
    model = Model(args.core)
    parser = Parser(model, entry, excludes)
    extra = {"t0": t0}
    rc = run_firmware(args, parser, firmware_records, "cycles", extra)
    if rc != 0 and parser.lines == 0:
        sys.exit(1)
    if args.from_symbol and parser.entries == 0:
        sys.stderr.write("cycles: %s was never entered by a call\n" % args.from_symbol)
    text, data = report(args, parser, model, syms, extra)
    print(text)
    if args.json:
        write_json(args.json, data, t0)
    if not args.log and rc != 0:
        sys.exit(rc if rc > 0 else 1)


if __name__ == "__main__":
    main()
