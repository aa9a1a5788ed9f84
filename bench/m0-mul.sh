#!/bin/sh
# m0-mul.sh: the fixed layer's wide products on a Cortex-M0 (QEMU microbit,
# nRF51), with the plain C product (__aeabi_lmul) against the 16x16
# partial products of fx_wide.h (FX_MUL64_PARTIAL=1 inline, =2 out of line).
#
#   sh bench/m0-mul.sh            (from the repository root; 1 to 3 minutes)
#
# Builds one small standalone firmware per path from src/numeric/fx.c and the
# headers (nothing of platform/), runs each under
# qemu-system-arm -M microbit -icount shift=0 and prints:
#   - a check on the board: fx_mul64, fx_umul64 and fx_mul64x against the
#     plain product (libgcc's __aeabi_lmul) on all pairs of edge values and
#     RANDOM_PAIRS random pairs (default 2000000), and one hash of fx_mul,
#     v3_dot, fx_div, fx_sqrt, v3_length, v3_unit, fx_pow_unit and the
#     polygon edge test over 200000 random inputs, which every path must
#     reproduce;
#   - instructions per call of each operation, from TIMER0 at 16 MHz (62.5
#     instructions per tick under -icount shift=0) over 65536 calls, minus
#     the same loop without the call: each count includes the call to an
#     out-of-line wrapper and its return (the "none" row: a wrapper that
#     only returns). These are instructions, not cycles;
#   - the .text of every C file of src/ for -mcpu=cortex-m0 -O2 -DRT_USE_SPD=0 on
#     each path (and for the Cortex-M3, where the default is the plain
#     product), as arm-none-eabi-size totals of the objects.
# Exits 1 when a check fails, 2 when a tool is missing or a build fails.
set -u
for t in arm-none-eabi-gcc arm-none-eabi-size qemu-system-arm; do
    command -v $t >/dev/null 2>&1 || { echo "m0-mul: $t not found" >&2; exit 2; }
done
ROOT=$(cd "$(dirname "$0")/.." && pwd)
W=$(mktemp -d "${TMPDIR:-/tmp}/m0-mul.XXXXXX") || exit 2
trap 'rm -rf "$W"' EXIT
RANDOM_PAIRS=${RANDOM_PAIRS:-2000000}

cat >"$W/board.h" <<'EOF'
#include <stdint.h>
void board_putc(char c);
void board_puts(const char *s);
void board_putu(uint32_t v);
void board_puthex(uint32_t v);
uint32_t board_ticks(void); /* TIMER0 at 16 MHz */
EOF

cat >"$W/board.c" <<'EOF'
/* nRF51 under QEMU: vectors, UART0, TIMER0, semihosting exit */
#include <stddef.h>
#include <stdint.h>
#include "board.h"

#define REG(a) (*(volatile uint32_t *)(a))
#define UART0 0x40002000u
#define TIMER0 0x40008000u

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _estack;
int main(void);

static void board_exit(int code)
{
    static volatile uint32_t block[2];
    block[0] = 0x20026; /* ADP_Stopped_ApplicationExit */
    block[1] = (uint32_t)code;
    register uint32_t r0 __asm__("r0") = 0x20; /* SYS_EXIT_EXTENDED */
    register volatile uint32_t *r1 __asm__("r1") = block;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    for (;;) {
    }
}

static void fault(void)
{
    board_puts("fault\n");
    board_exit(3);
}

static void reset(void)
{
    uint32_t *s = &_sidata, *d = &_sdata;
    while (d < &_edata)
        *d++ = *s++;
    for (d = &_sbss; d < &_ebss; d++)
        *d = 0;
    REG(UART0 + 0x500) = 4;  /* ENABLE */
    REG(UART0 + 0x008) = 1;  /* TASKS_STARTTX */
    REG(TIMER0 + 0x504) = 0; /* MODE: timer */
    REG(TIMER0 + 0x508) = 3; /* BITMODE: 32 bits */
    REG(TIMER0 + 0x510) = 0; /* PRESCALER: 16 MHz */
    REG(TIMER0 + 0x00C) = 1; /* TASKS_CLEAR */
    REG(TIMER0 + 0x000) = 1; /* TASKS_START */
    board_exit(main());
}

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))&_estack, reset, fault, fault, fault, fault, fault, fault,
    fault, fault, fault, fault, fault, fault, fault, fault,
};

void board_putc(char c)
{
    REG(UART0 + 0x11C) = 0; /* EVENTS_TXDRDY */
    REG(UART0 + 0x51C) = (uint8_t)c;
    while (REG(UART0 + 0x11C) == 0) {
    }
}
void board_puts(const char *s)
{
    while (*s)
        board_putc(*s++);
}
void board_putu(uint32_t v)
{
    char b[12];
    int n = 0;
    do {
        b[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v);
    while (n)
        board_putc(b[--n]);
}
void board_puthex(uint32_t v)
{
    for (int i = 28; i >= 0; i -= 4)
        board_putc("0123456789abcdef"[(v >> i) & 15]);
}
uint32_t board_ticks(void)
{
    REG(TIMER0 + 0x040) = 1; /* TASKS_CAPTURE[0] */
    return REG(TIMER0 + 0x540); /* CC[0] */
}
/* what GCC may call for struct copies */
void *memcpy(void *d, const void *s, size_t n)
{
    uint8_t *dd = d;
    const uint8_t *ss = s;
    while (n--)
        *dd++ = *ss++;
    return d;
}
void *memset(void *d, int c, size_t n)
{
    uint8_t *dd = d;
    while (n--)
        *dd++ = (uint8_t)c;
    return d;
}
EOF

cat >"$W/link.ld" <<'EOF'
MEMORY {
    FLASH (rx) : ORIGIN = 0x00000000, LENGTH = 256K
    RAM (rwx)  : ORIGIN = 0x20000000, LENGTH = 16K
}
_estack = ORIGIN(RAM) + LENGTH(RAM);
SECTIONS {
    .text : { KEEP(*(.vectors)) *(.text*) *(.rodata*) } > FLASH
    _sidata = LOADADDR(.data);
    .data : { _sdata = .; *(.data*) _edata = .; } > RAM AT > FLASH
    .bss (NOLOAD) : { _sbss = .; *(.bss*) *(COMMON) _ebss = .; } > RAM
}
EOF

cat >"$W/ops.h" <<'EOF'
#include "numeric/vec3.h"
int64_t op_none(int32_t a, int32_t b);
int64_t op_mul64(int32_t a, int32_t b);
uint64_t op_umul64(uint32_t a, uint32_t b);
int64_t op_mul64x(int32_t a, int64_t b);
fx_t op_mul(fx_t a, fx_t b);
fx_wide_t op_wdot(const vec3_t *a, const vec3_t *b);
fx_t op_dot(const vec3_t *a, const vec3_t *b);
fx_t op_div(fx_t a, fx_t b);
fx_t op_sqrt(fx_t a);
fx_t op_length(const vec3_t *a);
void op_unit(const vec3_t *a, vec3_t *out);
fx_t op_pow(fx_t x, shine_t s);
int op_edge(const vec3_t *d, const vec3_t *a, const vec3_t *b);
/* ref.c: always the plain C product (__aeabi_lmul on the M0) */
int64_t ref_mul64(int32_t a, int32_t b);
uint64_t ref_umul64(uint32_t a, uint32_t b);
uint64_t ref_mul64x(int32_t a, int64_t b);
EOF

cat >"$W/ops.c" <<'EOF'
/* the measured operations, each out of line (one call per operation) */
#include "ops.h"
int64_t op_none(int32_t a, int32_t b) { return (int64_t)(a ^ b); }
int64_t op_mul64(int32_t a, int32_t b) { return fx_mul64(a, b); }
uint64_t op_umul64(uint32_t a, uint32_t b) { return fx_umul64(a, b); }
int64_t op_mul64x(int32_t a, int64_t b) { return fx_mul64x(a, b); }
fx_t op_mul(fx_t a, fx_t b) { return fx_mul(a, b); }
fx_wide_t op_wdot(const vec3_t *a, const vec3_t *b) { return v3_wdot(*a, *b); }
fx_t op_dot(const vec3_t *a, const vec3_t *b) { return v3_dot(*a, *b); }
fx_t op_div(fx_t a, fx_t b) { return fx_div(a, b); }
fx_t op_sqrt(fx_t a) { return fx_sqrt(a); }
fx_t op_length(const vec3_t *a) { return v3_length(*a); }
void op_unit(const vec3_t *a, vec3_t *out) { *out = v3_unit(*a); }
fx_t op_pow(fx_t x, shine_t s) { return fx_pow_unit(x, s); }
/* polygon.c's edge test: the sign of d . (a x b), the cross product wide */
int op_edge(const vec3_t *d, const vec3_t *a, const vec3_t *b)
{
    return r_wsign_dot(d->x, d->y, d->z, r_wmul(a->y, b->z) - r_wmul(a->z, b->y),
                       r_wmul(a->z, b->x) - r_wmul(a->x, b->z), r_wmul(a->x, b->y) - r_wmul(a->y, b->x));
}
EOF

cat >"$W/ref.c" <<'EOF'
#include "ops.h"
#if FX_MUL64_PARTIAL
#error "ref.c is the plain product"
#endif
int64_t ref_mul64(int32_t a, int32_t b) { return (int64_t)a * b; }
uint64_t ref_umul64(uint32_t a, uint32_t b) { return (uint64_t)a * b; }
uint64_t ref_mul64x(int32_t a, int64_t b) { return (uint64_t)(int64_t)a * (uint64_t)b; }
EOF

cat >"$W/main.c" <<'EOF'
#include "board.h"
#include "ops.h"

static uint32_t rng = 2463534242u;
static uint32_t rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}
static int32_t rnd_any(void) { return (int32_t)rnd() >> (rnd() & 31); } /* random magnitude */
static fx_t rnd_fx(void) { return (int32_t)rnd() >> (4 + (rnd() % 20)); } /* |x| < 2^(F+4) at F = 20 */
static vec3_t rnd_v3(void) { return v3(rnd_fx(), rnd_fx(), rnd_fx()); }

static uint32_t fails;
static void check(const char *what, uint64_t got, uint64_t want, uint32_t a, uint32_t b)
{
    if (got != want && fails++ < 10) {
        board_puts("MISMATCH ");
        board_puts(what);
        board_putc(' ');
        board_puthex(a);
        board_putc(' ');
        board_puthex(b);
        board_putc('\n');
    }
}

static const int32_t edges[] = {
    0, 1, -1, 2, -2, 0x7FFF, 0x8000, 0xFFFF, 0x10000, 0x10001, -0x7FFF, -0x8000, -0x8001, -0xFFFF,
    -0x10000, -0x10001, 0x7FFFFFFF, -0x7FFFFFFF, (int32_t)0x80000000u, 0x7FFF0000, (int32_t)0x80008000u,
    0x00FF00FF, (int32_t)0xFFFF0000u, (int32_t)0xFFFF8000u, (int32_t)0xFFFF7FFFu, 0x12345678,
    (int32_t)0xDEADBEEFu,
};
#define NEDGES (int)(sizeof edges / sizeof edges[0])

static void check_pair(int32_t a, int32_t b, int64_t w)
{
    check("mul64", (uint64_t)op_mul64(a, b), (uint64_t)ref_mul64(a, b), (uint32_t)a, (uint32_t)b);
    check("umul64", op_umul64((uint32_t)a, (uint32_t)b), ref_umul64((uint32_t)a, (uint32_t)b), (uint32_t)a,
          (uint32_t)b);
    check("mul64x", (uint64_t)op_mul64x(a, w), ref_mul64x(a, w), (uint32_t)a, (uint32_t)((uint64_t)w >> 32));
}

#define N 65536u
#define M 64u
static int32_t xa[M], xb[M];
static int64_t xw[M];
static vec3_t va[M], vb[M], vc[M];

static uint32_t hash = 2166136261u;
static void mix(uint32_t v) { hash = (hash ^ v) * 16777619u; }

static void report(const char *name, uint32_t ticks)
{
    board_puts("time ");
    board_puts(name);
    board_putc(' ');
    board_putu(ticks);
    board_putc('\n');
}
#define TIME(name, expr)                                                                     \
    do {                                                                                     \
        uint32_t t0_ = board_ticks();                                                        \
        for (uint32_t i = 0; i < N; i++) {                                                   \
            uint32_t k = i & (M - 1);                                                        \
            acc += (uint32_t)(expr);                                                         \
        }                                                                                    \
        report(name, board_ticks() - t0_);                                                   \
    } while (0)

int main(void)
{
    uint32_t pairs = 0;
    for (int i = 0; i < NEDGES; i++)
        for (int j = 0; j < NEDGES; j++, pairs++)
            check_pair(edges[i], edges[j],
                       (int64_t)((uint64_t)(uint32_t)edges[j] << 32 | (uint32_t)edges[(i + j) % NEDGES]));
    for (uint32_t n = 0; n < RANDOM_PAIRS; n++, pairs++) {
        int32_t a = n & 1 ? rnd_any() : (int32_t)rnd(), b = n & 2 ? rnd_any() : (int32_t)rnd();
        check_pair(a, b, (int64_t)((uint64_t)rnd() << 32 | rnd()) >> (rnd() & 63));
    }
    board_puts("pairs ");
    board_putu(pairs);
    board_puts(" mismatches ");
    board_putu(fails);
    board_putc('\n');

    for (uint32_t n = 0; n < 200000; n++) {
        fx_t a = rnd_fx(), b = rnd_fx();
        vec3_t p = rnd_v3(), q = rnd_v3(), r = rnd_v3(), u;
        mix((uint32_t)op_mul(a, b));
        mix((uint32_t)op_mul(rnd_any(), rnd_any()));
        mix((uint32_t)op_dot(&p, &q));
        mix((uint32_t)op_div(a, b));
        mix((uint32_t)op_div(rnd_any(), rnd_any()));
        mix((uint32_t)op_sqrt(rnd_any()));
        mix((uint32_t)op_length(&p));
        op_unit(&p, &u);
        mix((uint32_t)u.x);
        mix((uint32_t)u.y);
        mix((uint32_t)u.z);
        mix((uint32_t)op_pow(rnd_fx() & (FX_ONE - 1), rnd() & 0xFFFFFu));
        mix((uint32_t)op_edge(&r, &p, &q));
    }
    board_puts("hash ");
    board_puthex(hash);
    board_putc('\n');

    for (uint32_t k = 0; k < M; k++) {
        xa[k] = rnd_fx();
        xb[k] = rnd_fx();
        xw[k] = (int64_t)rnd_fx() << (rnd() % 20);
        va[k] = rnd_v3();
        vb[k] = rnd_v3();
        vc[k] = v3_unit(rnd_v3());
    }
    uint32_t acc = 0;
    vec3_t u;
    TIME("loop", xa[k] ^ xb[k]);
    TIME("none", op_none(xa[k], xb[k]));
    TIME("fx_mul64", op_mul64(xa[k], xb[k]));
    TIME("fx_umul64", op_umul64((uint32_t)xa[k], (uint32_t)xb[k]));
    TIME("fx_mul64x", op_mul64x(xa[k], xw[k]));
    TIME("fx_mul", op_mul(xa[k], xb[k]));
    TIME("v3_wdot", op_wdot(&va[k], &vb[k]));
    TIME("v3_dot", op_dot(&va[k], &vb[k]));
    TIME("fx_div", op_div(xa[k], xb[k]));
    TIME("fx_sqrt", op_sqrt(xa[k] < 0 ? -xa[k] : xa[k]));
    TIME("v3_length", op_length(&va[k]));
    TIME("v3_unit", (op_unit(&va[k], &u), u.x));
    TIME("fx_pow_unit", op_pow(vc[k].x < 0 ? -vc[k].x : vc[k].x, 50u << R_SHINE_FRAC_BITS));
    TIME("edge_side", op_edge(&vc[k], &va[k], &vb[k]));
    board_puts("acc ");
    board_puthex(acc);
    board_putc('\n');
    return fails ? 1 : 0;
}
EOF

CFLAGS="-std=c11 -Wall -Wextra -Werror -mcpu=cortex-m0 -mthumb -O2 -ffreestanding -fno-tree-loop-distribute-patterns"
# path name, FX_MUL64_PARTIAL
build_run() {
    o="$W/$1"
    mkdir -p "$o"
    D="-DFX_MUL64_PARTIAL=$2 -DRANDOM_PAIRS=$RANDOM_PAIRS -I$ROOT/include -I$ROOT/src -I$W"
    for f in main ops board; do
        arm-none-eabi-gcc $CFLAGS $D -c "$W/$f.c" -o "$o/$f.o" || return 2
    done
    arm-none-eabi-gcc $CFLAGS $D -c "$ROOT/src/numeric/fx.c" -o "$o/fx.o" || return 2
    arm-none-eabi-gcc $CFLAGS -DFX_MUL64_PARTIAL=0 -I"$ROOT/include" -I"$ROOT/src" -I"$W" -c "$W/ref.c" -o "$o/ref.o" || return 2
    arm-none-eabi-gcc -mcpu=cortex-m0 -mthumb -nostdlib -nostartfiles -T "$W/link.ld" -Wl,--gc-sections \
        -o "$o/fw.elf" "$o"/*.o -lgcc || return 2
    timeout 600 qemu-system-arm -M microbit -nographic -monitor none -semihosting-config enable=on,target=native \
        -icount shift=0 -kernel "$o/fw.elf" </dev/null >"$o/out.txt" 2>&1
}

status=0
for p in 0 1 2; do
    build_run p$p $p
    rc=$?
    [ $rc -eq 2 ] && { echo "m0-mul: build failed (FX_MUL64_PARTIAL=$p)" >&2; exit 2; }
    grep -q '^acc ' "$W/p$p/out.txt" || { echo "m0-mul: the firmware (FX_MUL64_PARTIAL=$p) did not finish:"; cat "$W/p$p/out.txt"; status=1; }
    grep MISMATCH "$W/p$p/out.txt"
done

echo "Cortex-M0 (QEMU microbit, -icount shift=0), FX_FRAC_BITS default, $(arm-none-eabi-gcc -dumpversion) -O2"
echo
for p in 0 1 2; do
    m=$(awk '$1 == "pairs" { print $4 }' "$W/p$p/out.txt")
    n=$(awk '$1 == "pairs" { print $2 }' "$W/p$p/out.txt")
    h=$(awk '$1 == "hash" { print $2 }' "$W/p$p/out.txt")
    echo "FX_MUL64_PARTIAL=$p: $n pairs against __aeabi_lmul, ${m:-?} mismatches; results hash $h"
    [ "${m:-x}" = 0 ] || status=1
done
h0=$(awk '$1 == "hash" { print $2 }' "$W/p0/out.txt")
for p in 1 2; do
    [ "$(awk '$1 == "hash" { print $2 }' "$W/p$p/out.txt")" = "$h0" ] || {
        echo "FAIL: FX_MUL64_PARTIAL=$p gives other results than the plain product"
        status=1
    }
done
[ $status -eq 0 ] && echo "ok: every path bit-identical to the plain product"
echo
echo "instructions per call (65536 calls, minus the loop; each includes a wrapper's call and return)"
echo
echo "| operation | plain (__aeabi_lmul) | partial, inline (=1) | partial, call (=2) | =1 vs plain |"
echo "|---|---:|---:|---:|---:|"
awk '
    $1 == "time" { t[FILENAME, $2] = $3; if (!seen[$2]++) order[n++] = $2 }
    END {
        for (i = 0; i < n; i++) {
            k = order[i]
            if (k == "loop") continue
            for (p = 0; p < 3; p++) {
                f = W "/p" p "/out.txt"
                v[p] = (t[f, k] - t[f, "loop"]) * 62.5 / 65536
            }
            printf "| %s | %.1f | %.1f | %.1f | %s |\n", k, v[0], v[1], v[2],
                k == "none" ? "" : sprintf("%.2fx", v[0] / v[1])
        }
    }' W="$W" "$W/p0/out.txt" "$W/p1/out.txt" "$W/p2/out.txt"

echo
echo "code: .text of all C files of src/ (-O2 -DRT_USE_SPD=0, objects, arm-none-eabi-size)"
echo
echo "| target | FX_MUL64_PARTIAL | .text (bytes) | calls to __aeabi_lmul |"
echo "|---|---|---:|---:|"
for cfg in "cortex-m0 0" "cortex-m0 1" "cortex-m0 2" "cortex-m3 0"; do
    set -- $cfg
    o="$W/size-$1-$2"
    mkdir -p "$o"
    for c in "$ROOT"/src/*.c "$ROOT"/src/*/*.c; do
        arm-none-eabi-gcc -std=c11 -Wall -Wextra -Werror -mcpu=$1 -mthumb -O2 -ffreestanding -DRT_USE_SPD=0 \
            -DFX_MUL64_PARTIAL=$2 -I"$ROOT/include" -I"$ROOT/src" -c "$c" -o "$o/$(basename "$c" .c).o" || exit 2
    done
    text=$(arm-none-eabi-size -t "$o"/*.o | awk 'END { print $1 }')
    calls=$(for f in "$o"/*.o; do arm-none-eabi-objdump -dr "$f"; done | grep -c 'R_ARM_THM_CALL[[:space:]]*__aeabi_lmul')
    echo "| $1 | $2 | $text | $calls |"
done
exit $status
