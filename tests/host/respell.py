#!/usr/bin/env python3
"""Rewrite every number of an NFF file in another spelling of the same
value (tests/host/spelling-tests.sh): trailing zeros, leading zeros, exponents
(15e-1, 0.15E+1), a '+' sign, cycling through them number by number.
Comments go; words and layout stay.

usage: respell.py IN.nff OUT.nff"""
import re
import sys
from decimal import Decimal, InvalidOperation

NUMBER = re.compile(r'^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$')


def respell(tok, i):
    sign = '-' if tok.startswith('-') else ''
    body = tok.lstrip('+-')
    d = Decimal(body)
    digits = ''.join(map(str, d.as_tuple().digits))
    exp = d.as_tuple().exponent
    kind = i % 5
    if kind == 0:  # trailing zeros
        return sign + (body + '000' if '.' in body and 'e' not in body.lower() else
                       format(d, 'f') + ('' if '.' in format(d, 'f') else '.') + '000')
    if kind == 1:  # leading zeros
        return sign + '00' + format(d, 'f')
    if kind == 2:  # integer digits and an exponent
        return sign + digits + 'e' + str(exp)
    if kind == 3:  # a fraction and an explicit '+' exponent
        return sign + '0.' + digits + 'E+' + str(exp + len(digits)) if exp + len(digits) >= 0 else \
            sign + '0.' + digits + 'E' + str(exp + len(digits))
    return ('+' if not sign else sign) + format(d, 'f')  # an explicit sign


def main():
    src, dst = sys.argv[1], sys.argv[2]
    out, n = [], 0
    for line in open(src):
        words = line.split('#', 1)[0].split()
        new = []
        for w in words:
            if NUMBER.match(w):
                try:
                    Decimal(w.lstrip('+-'))
                except InvalidOperation:
                    new.append(w)
                    continue
                new.append(respell(w, n))
                n += 1
            else:
                new.append(w)
        out.append(' '.join(new) + '\n')
    open(dst, 'w').write(''.join(out))
    # every rewrite keeps the value
    for a, b in zip((w for l in open(src) for w in l.split('#', 1)[0].split() if NUMBER.match(w)),
                    (w for l in out for w in l.split() if NUMBER.match(w))):
        assert Decimal(a.lstrip('+')) == Decimal(b.lstrip('+')), (a, b)


main()
