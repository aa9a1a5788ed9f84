#!/usr/bin/env python3
"""Prints the tables of src/numeric/real_float.c (the float backend's x^s).

log_table: z in [0.71875, 1.4375) in 32 rows by the top 5 mantissa bits
above LOG_M0; c = 2 / (lo + hi) of the row, rounded to 12 significant
bits (1 for the two rows next to z = 1), and log2(1/c) as the nearest
float plus the nearest float of the remainder. exp_table: 2^(j/32) split
the same way. Values to 60 digits with the decimal module."""
from decimal import Decimal, getcontext
from fractions import Fraction
import struct

getcontext().prec = 60
LN2 = Decimal(2).ln()
M0, BITS = 0x380000, 5


def f32(v):
    """A float near v (through double; the remainder's float absorbs any
    double rounding)."""
    return struct.unpack('f', struct.pack('f', float(v)))[0]


def lit(v):
    if v == 0:
        return '0x0p+0f'
    m, e = float(v).hex().split('p')
    return '%sp%sf' % (m.rstrip('0').rstrip('.'), e)


def pair(v):
    hi = f32(v)
    return hi, f32(v - Decimal(hi))


def round12(q):
    e = 0
    while q < 1:
        q, e = q * 2, e - 1
    while q >= 2:
        q, e = q / 2, e + 1
    return Fraction(round(q * 2048), 2048) * Fraction(2) ** e


print('log_table (c, log2(1/c) hi, lo):')
for i in range(1 << BITS):
    m = M0 + (i << (23 - BITS))
    if m < 1 << 23:  # z < 1: z = (1 + M / 2^23) / 2
        lo, hi = Fraction((1 << 23) + m, 1 << 24), Fraction((1 << 23) + m + (1 << (23 - BITS)), 1 << 24)
    else:
        m -= 1 << 23
        lo, hi = Fraction((1 << 23) + m, 1 << 23), Fraction((1 << 23) + m + (1 << (23 - BITS)), 1 << 23)
    c = Fraction(1) if 1 in (lo, hi) else round12(2 / (lo + hi))
    t = (Decimal(c.denominator).ln() - Decimal(c.numerator).ln()) / LN2
    th, tl = pair(t)
    print('    { %s, %s, %s },' % (lit(f32(c)), lit(th), lit(tl)))
print('exp_table (2^(j/32) hi, lo):')
for j in range(1 << BITS):
    print('    { %s, %s },' % tuple(lit(v) for v in pair((Decimal(j) / 32 * LN2).exp())))
print('INV_LN2 %s %s' % tuple(lit(v) for v in pair(1 / LN2)))
print('2^g - 1 coefficients (ln 2)^k / k!: %s' %
      ', '.join(lit(f32(LN2 ** k / [1, 1, 2, 6, 24][k])) for k in range(1, 5)))
print('ln(1 + r) coefficients 1/k: %s' % ', '.join(lit(f32(Decimal(1) / k)) for k in range(3, 8)))
