#!/usr/bin/env python3
"""Layering: no call cycle between the core's source files.

File A depends on file B when A's object refers to a symbol B's object
defines (calls, and function pointers such as the reader's keyword
table). The objects are one backend's compilation of src/*.c (default
build/asan/fixed); inline functions of headers count for the file that
uses them. Prints the dependencies and "layers: N passed, M failed"."""
import glob
import os
import subprocess
import sys

objdir = sys.argv[1] if len(sys.argv) > 1 else 'build/asan/fixed'
defs, refs = {}, {}
for o in sorted(glob.glob(os.path.join(objdir, '*.o'))):
    name = os.path.basename(o)[:-2]
    if not os.path.exists('src/%s.c' % name):  # stale object, or not the core
        continue
    rows = [l.split() for l in subprocess.run(['nm', o], capture_output=True, text=True, check=True).stdout.splitlines()]
    defs[name] = {r[-1] for r in rows if len(r) == 3 and r[1] in 'TDRB'}
    refs[name] = {r[-1] for r in rows if len(r) == 2 and r[0] == 'U'}
owner = {s: f for f, syms in defs.items() for s in syms}
deps = {f: sorted({owner[s] for s in refs[f] if owner.get(s, f) != f}) for f in defs}
for f in sorted(deps):
    print('    %-12s -> %s' % (f, ' '.join(deps[f]) or '-'))

# Strongly connected sets of more than one file are the cycles (Tarjan).
index, low, stack, on_stack, cycles = {}, {}, [], set(), []
def visit(v):
    index[v] = low[v] = len(index)
    stack.append(v)
    on_stack.add(v)
    for w in deps[v]:
        if w not in index:
            visit(w)
            low[v] = min(low[v], low[w])
        elif w in on_stack:
            low[v] = min(low[v], index[w])
    if low[v] == index[v]:
        scc = []
        while not scc or scc[-1] != v:
            scc.append(stack.pop())
            on_stack.discard(scc[-1])
        if len(scc) > 1:
            cycles.append(sorted(scc))
for v in sorted(deps):
    if v not in index:
        visit(v)

ok = len(deps) > 10 and not cycles  # also fails when the objects are missing
if ok:
    print('  ok    no call cycle between the %d source files of src/' % len(deps))
else:
    print('  FAIL  call cycles between src/ files: %s' % (cycles or 'no objects in ' + objdir))
print('layers: %d passed, %d failed' % (ok, not ok))
sys.exit(0 if ok else 1)
