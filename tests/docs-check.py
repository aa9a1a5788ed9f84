#!/usr/bin/env python3
"""The docs check: README.md and docs/*.md against the tree.

  - every relative link resolves: the file exists, and an anchor (#x)
    names a heading of the page it points to (GitHub's anchor rule);
  - every `rt` option the pages name (--x inside an inline or block code
    line that calls rt) appears in the help text of rt or its
    subcommands (rt --help, rt compare --help, rt receive --help);
  - every `make TARGET` the pages name is a target make knows (make -n);
  - every make variable given as VAR=value on a `make ...` line is one the
    Makefile or a board.mk reads;
  - every measured figure names where it comes from: a paragraph, list
    item or table (with the paragraph before it) that gives a number in
    dB, instructions or cycles per pixel or per test, ms, seconds at a
    clock, a ratio such as 1.9x, or a table with such a column, names a
    result file of bench/ or the test of tests/ that prints it (a
    bound such as >= 45 dB is not a figure);
  - every result file of bench/ the pages name is one `make bench`
    writes: its name is in the source of a script the bench rule runs;
  - README.md is at most 250 lines.

  tests/docs-check.py [RT]
"""
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RT = sys.argv[1] if len(sys.argv) > 1 else "build/host/rt"
passed = failed = 0


def check(ok, what):
    global passed, failed
    if ok:
        passed += 1
        print("  ok    " + what)
    else:
        failed += 1
        print("  FAIL  " + what)


def anchor(title):
    a = re.sub(r"[^\w\- ]", "", title.strip().lower())
    return a.replace(" ", "-")


def anchors(path):
    with open(path) as f:
        text = f.read()
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    return {anchor(m.group(1)) for m in re.finditer(r"^#{1,6} (.*)$", text, re.M)}


pages = [os.path.join(ROOT, "README.md")] + sorted(glob.glob(os.path.join(ROOT, "docs", "*.md")))
os.chdir(ROOT)

# links
for page in pages:
    with open(page) as f:
        text = f.read()
    prose = re.sub(r"```.*?```", "", text, flags=re.S)
    bad = []
    n = 0
    for m in re.finditer(r"\]\(([^)\s]+)\)", prose):
        target = m.group(1)
        if re.match(r"^[a-z]+:", target):
            continue
        n += 1
        path, _, frag = target.partition("#")
        dest = os.path.normpath(os.path.join(os.path.dirname(page), path)) if path else page
        if not os.path.exists(dest):
            bad.append(target + " (no such file)")
        elif frag and dest.endswith(".md") and frag not in anchors(dest):
            bad.append(target + " (no such heading)")
    check(not bad, "%s: %d relative links resolve%s" % (os.path.relpath(page, ROOT), n,
                                                          "" if not bad else ": " + "; ".join(bad)))

# rt options
helps = ""
for sub in ([], ["compare"], ["receive"]):
    r = subprocess.run([RT] + sub + ["--help"], capture_output=True, text=True)
    helps += r.stdout + r.stderr
known = set(re.findall(r"--[a-z][a-z0-9-]*", helps))
named = set()
for page in pages:
    with open(page) as f:
        for line in f:
            for code in re.findall(r"`([^`]*)`", line) + ([line] if line.startswith("    ") else []):
                if re.search(r"(^|\s|/)rt( |$)", code):
                    named.update(re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", code))
missing = sorted(named - known)
check(not missing, "%d rt options the docs name are in rt's help%s" % (len(named), ": missing " + " ".join(missing) if missing else ""))

# make targets and variables
vars_read = set()
for mk in ["Makefile", "platform/firmware/firmware.mk"] + glob.glob("platform/*/board.mk"):
    with open(mk) as f:
        vars_read.update(re.findall(r"\$\(([A-Z_][A-Z0-9_]*)\)", f.read()))
        f.seek(0)
        vars_read.update(re.findall(r"^([A-Z_][A-Z0-9_]*)\s*[?:]?=", f.read(), re.M))
targets, bad_vars = set(), set()
for page in pages:
    with open(page) as f:
        for line in f:
            for code in re.findall(r"`([^`]*)`", line) + ([line] if line.startswith("    ") else []):
                for m in re.finditer(r"(?:^|&&|\s)make ((?:[A-Za-z_][\w.-]*(?:=\S*)?\s*)+)", code):
                    for word in m.group(1).split():
                        if '"' in word or "'" in word:
                            break  # a quoted value: the rest is its words
                        if "=" in word:
                            v = word.split("=", 1)[0]
                            if v not in vars_read:
                                bad_vars.add(v)
                        elif re.match(r"^[a-z][\w-]*$", word):
                            targets.add(word)
# the targets make's database knows (make -p prints it; -q runs nothing)
db = subprocess.run(["make", "-pRrq", "-f", "Makefile", "docs-check-no-such-target"], capture_output=True,
                    text=True).stdout
have = set(re.findall(r"^([a-z][\w-]*):", db, re.M))
unknown = sorted(targets - have)
check(not unknown, "%d make targets the docs name exist%s" % (len(targets), ": unknown " + " ".join(unknown) if unknown else ""))
check(not bad_vars, "make variables the docs set are read by the Makefile or a board.mk%s" %
      (": unknown " + " ".join(sorted(bad_vars)) if bad_vars else ""))

# figures and their sources
FIGURE = re.compile(r"(?<![<>=\w.,])(?<![<>=] )(?:\d[\d,]*(?:\.\d+)?\s?(?:dB|ms\b|s at \d|s of\b"
                    r"|instructions? (?:per|a) (?:pixel|test)|instr/px|cycles (?:per|a) pixel|cycles/px)"
                    r"|\d+\.\d+(?:x\b|\s?times\b))")  # ratios with a decimal point: 1.9x, 3.7 times
FIGURE_COLUMN = re.compile(r"dB|PSNR|instr|cycles|\(bytes\)|\(B\)|speed-up|\(s\)|\bms\b")
SOURCE = re.compile(r"\b(bench/[\w.-]+\.(?:md|csv|svg)|tests/[\w.-]+|[\w-]+\.(?:sh|py|c)\b)")


def figure_in(block):
    if FIGURE.search(block):
        return True
    rows = [r for r in block.splitlines() if r.lstrip().startswith("|")]
    return len(rows) > 2 and bool(FIGURE_COLUMN.search(rows[0])) and any(
        re.search(r"\|\s*[\d.,]+\s*(\||\()", r) for r in rows[2:])


unsourced, named_results = [], set()
for page in pages:
    with open(page) as f:
        text = re.sub(r"```.*?```", "", f.read(), flags=re.S)
    named_results.update(m for m in re.findall(r"bench/[\w.-]+\.(?:md|csv|svg)", text))
    blocks = [b for b in re.split(r"\n\s*\n|\n(?=\s*- )", text) if b.strip()]
    for i, b in enumerate(blocks):
        if b.lstrip().startswith("#") or not figure_in(b):
            continue
        near = b + ("\n" + blocks[i - 1] if b.lstrip().startswith("|") and i else "")
        if not any(os.path.exists(s) or os.path.exists("tests/" + s) for s in SOURCE.findall(near)):
            unsourced.append("%s: %s" % (os.path.relpath(page, ROOT), " ".join(b.split())[:90]))
check(not unsourced, "every measured figure names its bench file or test%s" %
      ("".join("\n          " + u for u in unsourced) if unsourced else ""))
# the scripts `make bench` runs (read from the Makefile: make -n would run the sub-makes)
with open("Makefile") as f:
    bench_rule = re.search(r"^bench:.*?\n((?:\t.*\n)+)", f.read(), re.M).group(1)
scripts = set(re.findall(r"bench/[\w.-]+\.(?:py|sh)", bench_rule))
sources = "".join(open(s).read() for s in scripts if os.path.exists(s)) + bench_rule
stale = sorted(r for r in named_results if not os.path.exists(r) or os.path.basename(r) not in sources)
check(scripts and not stale, "%d bench result files the docs name are written by make bench (%d scripts)%s" %
      (len(named_results), len(scripts), ": not " + " ".join(stale) if stale else ""))

with open("README.md") as f:
    lines = sum(1 for _ in f)
check(lines <= 250, "README.md: %d lines (at most 250)" % lines)
print("docs-check: %d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
