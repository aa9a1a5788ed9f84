#!/usr/bin/env python3
"""Layering: the core's folders depend downwards only, its files without cycles.

src/ holds the layers in order: numeric (number formats, vectors,
tolerances), geometry (rays, primitives, the BVH, the camera), then the
reader and the tracer, which stand side by side and never use each other.
src/ itself holds what every layer shares (rt_prefix.h, rt_error.c).

File A depends on file B when A's object refers to a symbol B's object
defines (calls, and function pointers such as the reader's keyword
table); inline functions of headers count for the file that uses them.
Headers are checked by their #include lines. The objects are one
backend's compilation of the core (default build/asan/fixed).

Around the core, by #include lines: app/rt/ (the rt command) and tools/
use src/ and include/; app/firmware/ (the firmware every board runs)
uses src/, include/ and the port contract platform/port.h, no board's
own files; platform/ (the ports) uses include/, platform/ and, of
app/firmware/, only sink.h (what a display driver implements); src/
uses none of them. platform/ holds ports only: C, assembler, linker
scripts and make fragments, no scripts or emulators (tools/).
tests/ runs from one list: every entry of tests/suites.list names a file
that exists, and every suite file under tests/ is listed or used by a
listed one.
Prints the dependencies and "layers: N passed, M failed"."""
import glob
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'lib'))
from check import check, summary  # noqa: E402

# rank of each folder of src/: a file may use its own folder and lower ranks
RANK = {'': 0, 'numeric': 1, 'geometry': 2, 'reader': 3, 'tracer': 3}

objdir = sys.argv[1] if len(sys.argv) > 1 else 'build/asan/fixed'

def folder(name):
    return os.path.dirname(name)

def allowed(user, used):
    return folder(used) == folder(user) or RANK[folder(used)] < RANK[folder(user)]

folders = sorted({os.path.relpath(os.path.dirname(p), 'src') for p in glob.glob('src/**/*.[ch]', recursive=True)})
folders = ['' if f == '.' else f for f in folders]
check(all(f in RANK for f in folders),
      'every folder of src/ has a rank (%s)' % ', '.join(f or 'src/' for f in folders))

defs, refs = {}, {}
for o in sorted(glob.glob(os.path.join(objdir, '**', '*.o'), recursive=True)):
    name = os.path.relpath(o, objdir)[:-2]
    if not os.path.exists('src/%s.c' % name):  # stale object, or not the core
        continue
    rows = [l.split() for l in subprocess.run(['nm', o], capture_output=True, text=True, check=True).stdout.splitlines()]
    defs[name] = {r[-1] for r in rows if len(r) == 3 and r[1] in 'TDRB'}
    refs[name] = {r[-1] for r in rows if len(r) == 2 and r[0] == 'U'}
owner = {s: f for f, syms in defs.items() for s in syms}
deps = {f: sorted({owner[s] for s in refs[f] if owner.get(s, f) != f}) for f in defs}
for f in sorted(deps):
    print('    %-22s -> %s' % (f, ' '.join(deps[f]) or '-'))
n_core = len(glob.glob('src/**/*.c', recursive=True))
check(len(deps) == n_core, 'objects of all %d source files of src/ in %s (found %d)' % (n_core, objdir, len(deps)))

upward = ['%s -> %s' % (f, d) for f in sorted(deps) for d in deps[f]
          if folder(f) in RANK and folder(d) in RANK and not allowed(f, d)]
check(not upward, 'calls go to the same folder or a lower layer%s' % (': ' + ', '.join(upward) if upward else ''))

# #include "x.h" of src/ files: the same folder, src/ itself, or "layer/x.h" of a lower layer
bad_includes = []
for path in sorted(glob.glob('src/**/*.[ch]', recursive=True)):
    user = os.path.relpath(path, 'src')
    for n, line in enumerate(open(path), 1):
        m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
        if not m:
            continue
        inc = m.group(1)
        for used in (os.path.normpath(os.path.join(folder(user), inc)), inc):
            if os.path.exists(os.path.join('src', used)):
                break
        else:
            continue  # a public header of include/
        if folder(used) not in RANK or not allowed(user, used):
            bad_includes.append('%s:%d: %s' % (path, n, inc))
check(not bad_includes, 'includes go to the same folder or a lower layer%s' %
      (': ' + ', '.join(bad_includes) if bad_includes else ''))

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
check(not cycles, 'no call cycle between files%s' % (': %s' % cycles if cycles else ''))

# ---- the tree around the core: app/, platform/, tools/ -------------------
# An include is looked up beside the file, then in every folder a build
# names with -I (so a forbidden one is found whichever build would see it).
ROOTS = ['include', 'src', 'platform', 'app/firmware', 'app/rt']

def area(path):
    """The part of the tree a file belongs to: src, include, app/rt,
    app/firmware, platform or tools."""
    parts = path.split('/')
    return '/'.join(parts[:2]) if parts[0] == 'app' else parts[0]

def resolve(user, inc):
    for d in [os.path.dirname(user)] + ROOTS:
        p = os.path.normpath(os.path.join(d, inc))
        if os.path.isfile(p):
            return p
    return None  # a system header, or one a build writes (scene_data.h)

# who may include what: the areas a file's includes may resolve to, and
# single files allowed from an area otherwise closed to it
MAY_USE = {
    'src': ({'src', 'include'}, set()),
    'app/rt': ({'app/rt', 'src', 'include'}, set()),
    'tools': ({'tools', 'app/rt', 'src', 'include'}, set()),
    'app/firmware': ({'app/firmware', 'src', 'include'}, {'platform/port.h'}),
    'platform': ({'platform', 'include'}, {'app/firmware/sink.h'}),
}
uses, bad_tree = set(), []
for top in MAY_USE:
    for path in sorted(glob.glob('%s/**/*.[chS]' % top, recursive=True)):
        if 'node_modules' in path:
            continue
        for n, line in enumerate(open(path, errors='replace'), 1):
            m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
            used = m and resolve(path, m.group(1))
            if not used:
                continue
            uses.add((area(path), used))
            areas, files = MAY_USE[area(path)]
            if area(used) not in areas and used not in files:
                bad_tree.append('%s:%d: %s (%s)' % (path, n, m.group(1), used))
# the look-up finds what the builds use (else the rule above checks nothing)
seen = [(a, u) for a, u in [('app/firmware', 'platform/port.h'), ('platform', 'platform/port.h'),
                            ('platform', 'app/firmware/sink.h'), ('app/rt', 'include/rt_fb.h'),
                            ('app/firmware', 'src/tracer/trace.h')] if (a, u) in uses]
check(len(seen) == 5, 'includes around the core are found (%s)' % ', '.join('%s -> %s' % s for s in seen))
check(not bad_tree, 'src/ uses no app/ or platform/; app/rt/ and tools/ no platform/ or app/firmware/; '
      'app/firmware/ of platform/ only port.h; platform/ of app/ only app/firmware/sink.h%s' %
      (': ' + ', '.join(bad_tree) if bad_tree else ''))

# platform/ holds the ports only: sources, linker scripts, make fragments
PORT_FILES = ('.c', '.h', '.S', '.ld', '.mk')
not_port = sorted(p for p in glob.glob('platform/**/*', recursive=True)
                  if os.path.isfile(p) and not p.endswith(PORT_FILES) and 'node_modules' not in p)
check(not not_port, 'platform/ holds only %s files%s' %
      (' '.join(PORT_FILES), ': not ' + ', '.join(not_port) if not_port else ''))
boards = sorted(os.path.dirname(p) for p in glob.glob('platform/*/board.mk'))
others = sorted(d for d in glob.glob('platform/*/') if d.rstrip('/') not in boards and d != 'platform/arch/')
check(boards and not others, 'every folder of platform/ is a board (board.mk) or arch/: %d boards%s' %
      (len(boards), ', not ' + ' '.join(others) if others else ''))

# tests/ by kind, run from one list: every entry of tests/suites.list names
# a file that exists (a unit test, $B/test_NAME, its tests/unit/test_NAME.c
# or the Makefile's test_NAME_SRC), and every suite file under tests/
# (*-tests.sh, *-test.sh, test_*.c) is listed or used by a listed one (its
# name in that one's text): none is left out of make test unseen
makefile = open('Makefile').read()
listed, entries, bad_entries = [], 0, []
with open('tests/suites.list') as f:
    for n, line in enumerate(f, 1):
        words = line.split('#', 1)[0].split()
        if not words:
            continue
        entries += 1
        word = next((w for w in words if w != 'python3'), words[0])
        if word.startswith('$B/'):
            name = word[3:]
            source = 'tests/unit/%s.c' % name
            if os.path.isfile(source):
                listed.append(source)
            elif not re.search(r'^%s_SRC\s*=' % re.escape(name), makefile, re.M):
                bad_entries.append('%d: %s (no %s, no %s_SRC in the Makefile)' % (n, word, source, name))
        elif os.path.isfile(word):
            listed.append(word)
        else:
            bad_entries.append('%d: %s (no such file)' % (n, word))
check(listed and not bad_entries, 'tests/suites.list: %d entries, each names a file that exists%s' %
      (entries,
       ': not ' + ', '.join(bad_entries) if bad_entries else ''))
texts = {p: open(p, errors='replace').read() for p in listed}
suite_files = sorted(p for p in glob.glob('tests/**/*', recursive=True)
                     if re.search(r'(-tests?\.sh|/test_[^/]*\.c)$', p))
unlisted = [p for p in suite_files if p not in texts and
            not any(os.path.splitext(os.path.basename(p))[0] in t for t in texts.values())]
check(suite_files and not unlisted, '%d suite files under tests/ (*-tests.sh, *-test.sh, test_*.c), each listed in '
      'tests/suites.list or used by a listed one%s' %
      (len(suite_files), ': not ' + ', '.join(unlisted) if unlisted else ''))

sys.exit(summary('layers'))
