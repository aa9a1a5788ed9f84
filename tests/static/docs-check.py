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
  - README.md's figures agree with the files they name: each figure (and
    both ends of a range "A to B dB") of a paragraph or table that names
    a bench file, rounded as written, is a number of one of those files;
    and a figure said to be of point-sampled textures, of cycles or of
    instructions names a file that has such figures (the word is in it);
  - a figure of the docs' own kind stated once: `make bench-quick`'s
    duration is given in one place of the Makefile, README.md, docs/
    and the bench scripts;
  - no bench table has a build variant's row ("board VAR=value") equal in
    every other cell to the board's own: such a row measures nothing;
  - docs/scenes.md's example scene (its ```nff block) is
    examples/make/scene.nff, byte for byte, and rt renders it;
  - every error message docs/scenes.md quotes (`x.nff:LINE: message`) is
    one the reader prints: the message of a tests/host/bad case, which
    rt, run on that case, prints as "FILE:LINE: message";
  - README.md is at most 250 lines.

  tests/static/docs-check.py [RT]
"""
import glob
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tests", "lib"))
from check import check, summary  # noqa: E402
RT = sys.argv[1] if len(sys.argv) > 1 else "build/host/rt"


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
for mk in ["Makefile", "app/firmware/firmware.mk"] + glob.glob("platform/*/board.mk"):
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
# a test named by its file name alone: any file under tests/
TEST_FILES = {os.path.basename(f) for f in glob.glob(os.path.join(ROOT, "tests", "**", "*"), recursive=True)}
SOURCE = re.compile(r"\b(bench/[\w.-]+\.(?:md|csv|svg)|tests/[\w./-]*[\w-]|[\w-]+\.(?:sh|py|c)\b)")


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
        if not any(os.path.exists(s) or s in TEST_FILES for s in SOURCE.findall(near)):
            unsourced.append("%s: %s" % (os.path.relpath(page, ROOT), " ".join(b.split())[:90]))
check(not unsourced, "every measured figure names its bench file or test%s" %
      ("".join("\n          " + u for u in unsourced) if unsourced else ""))
# the scripts `make bench` runs (read from the Makefile: make -n would run the sub-makes)
with open("Makefile") as f:
    bench_rule = "".join(re.findall(r"^bench(?:-[\w-]+)?:.*?\n((?:\t.*\n)+)", f.read(), re.M))
scripts = set(re.findall(r"bench/[\w.-]+\.(?:py|sh)", bench_rule))
sources = "".join(open(s).read() for s in scripts if os.path.exists(s)) + bench_rule
stale = sorted(r for r in named_results if not os.path.exists(r) or os.path.basename(r) not in sources)
check(scripts and not stale, "%d bench result files the docs name are written by make bench (%d scripts)%s" %
      (len(named_results), len(scripts), ": not " + " ".join(stale) if stale else ""))

# README.md's figures against the files they name
NUMBER = re.compile(r"\d[\d,]*(?:\.\d+)?")
RANGE = re.compile(r"(\d[\d,]*(?:\.\d+)?)x?\s(?:to|and)\s" + FIGURE.pattern[FIGURE.pattern.index("(?:"):])
QUALIFIERS = ("point-sampled", "cycles", "instructions")


def numbers_of(path):
    with open(path) as f:
        return {float(n.replace(",", "")) for n in NUMBER.findall(f.read())}


def agrees(figure, have):
    v = float(figure.replace(",", ""))
    d = len(figure.split(".")[1]) if "." in figure else 0
    return any(abs(round(n, d) - v) < 1e-9 for n in have)


def block_figures(block):
    """(figure, the text after it) for each figure of a block: prose and
    the figure columns of a table"""
    out = []
    rows = [r for r in block.splitlines() if r.lstrip().startswith("|")]
    prose = "\n".join(r for r in block.splitlines() if not r.lstrip().startswith("|"))
    seen = set()
    for m in list(RANGE.finditer(prose)) + list(FIGURE.finditer(prose)):
        if m.start(0) not in seen:  # a range's first figure, then each figure once
            seen.add(m.start(0))
            unit = m.end(0) - len(m.group(0).split()[-1])  # the clause from the figure's unit on
            start = max(prose.rfind(". ", 0, m.start(0)), prose.rfind(".\n", 0, m.start(0))) + 1
            end = min([i for i in (prose.find(". ", m.end(0)), prose.find(".\n", m.end(0))) if i >= 0] or [len(prose)])
            out.append((NUMBER.match(m.group(0)).group(0), re.split(r"[,;(]|\. ", prose[unit:])[0],
                        prose[start:end]))
    if len(rows) > 2:
        head = [c.strip() for c in rows[0].strip().strip("|").split("|")]
        cols = [i for i, h in enumerate(head) if FIGURE_COLUMN.search(h)]
        for r in rows[2:]:
            cells = [c.strip() for c in r.strip().strip("|").split("|")]
            for i in cols:
                if i < len(cells):
                    cell = re.sub(r"`[^`]*`|\[[^]]*\]\([^)]*\)", "", cells[i])
                    out += [(n, head[i] + " " + cell, "") for n in NUMBER.findall(cell)]
    return out


with open("README.md") as f:
    text = re.sub(r"```.*?```", "", f.read(), flags=re.S)
blocks = [b for b in re.split(r"\n\s*\n|\n(?=\s*- )", text) if b.strip()]
disagree, checked = [], 0
for i, b in enumerate(blocks):
    if b.lstrip().startswith("#") or not figure_in(b):
        continue
    near = b
    if b.lstrip().startswith("|"):  # a table: the paragraph before it (and before its plot)
        j = i - 1
        while j > 0 and blocks[j].lstrip().startswith("!["):
            near += "\n" + blocks[j]
            j -= 1
        near += "\n" + blocks[j] if j >= 0 else ""
    files = sorted({f for f in re.findall(r"bench/[\w.-]+\.(?:md|csv)", near) if os.path.exists(f)})
    if not files:
        continue
    for fig, after, sentence in block_figures(b):
        # the files the figure's sentence names, else the block's (or the table's paragraph's)
        own = sorted({f for f in re.findall(r"bench/[\w.-]+\.(?:md|csv)", sentence) if os.path.exists(f)}) or files
        checked += 1
        if not agrees(fig, set().union(*(numbers_of(f) for f in own))):
            disagree.append("%s (not in %s)" % (fig, ", ".join(own)))
        contents = "".join(open(f).read() for f in own)
        for q in QUALIFIERS:
            if q in after and q not in contents:
                disagree.append("%s %s (%s has no %s)" % (fig, q, ", ".join(own), q))
check(checked and not disagree, "%d README figures agree with the bench files they name%s" % (
    checked, "".join("\n          " + d for d in disagree) if disagree else ""))

# Seconds a frame: one price per board, backend and sampling.
# bench/time.csv's one-sample rows are bench/scenes.csv's card rows (the
# same instructions, cycles an instruction and cycles a pixel); each row's
# seconds are its cycles a pixel x 76,800 pixels / its clock (a panel
# board's scaled to 76,800), its cycles a pixel its instructions x CPI where
# estimated; and each seconds figure of a table of the pages that names
# bench/time.md ("board, N MHz" rows; a one-sample and an --aa 3 column)
# is its row's, to the rounding shown.
import csv  # noqa: E402
PIXELS = 320 * 240


def sig3(x):
    return float("%.3g" % x)


with open("bench/time.csv") as f:
    time_rows = list(csv.DictReader(f))
with open("bench/scenes.csv") as f:
    card = {(r["board"], r["backend"]): r for r in csv.DictReader(f) if r["scene"] == "card"}
priced, off = 0, []
for r in time_rows:
    if not r["cpp"]:
        continue
    priced += 1
    k = (r["board"], r["backend"])
    if r["sampling"] == "1 sample" and k in card:
        for col in ("ipp", "cpi", "cpp"):
            if r[col] != card[k][col]:
                off.append("%s %s one sample: %s %s in bench/time.csv, %s in bench/scenes.csv" % (
                    k + (col, r[col], card[k][col])))
    # the CPI shown to 3 decimals: its rounding alone moves the product by ipp / 2,000
    if r["cycles"] == "estimated" and abs(float(r["ipp"]) * float(r["cpi"]) - float(r["cpp"])) > float(r["ipp"]) / 2000 + 1:
        off.append("%s %s %s: cycles/px %s is not instr/px %s x CPI %s" % (
            r["board"], r["backend"], r["sampling"], r["cpp"], r["ipp"], r["cpi"]))
    # the card frame's 76,800 pixels; another row (make run's default) its own size's
    w, h = (int(v) for v in r["size"].split("x"))
    want = sig3(float(r["cpp"]) * (PIXELS if r["sampling"] in ("1 sample", "aa 3") else w * h)
                / (float(r["clock_mhz"]) * 1e6))
    if abs(float(r["seconds"]) - want) > 1e-9 * want:
        off.append("%s %s %s: %s s, but cycles/px x 76,800 / clock is %s s" % (
            r["board"], r["backend"], r["sampling"], r["seconds"], want))
by_key = {(r["board"], r["backend"], r["sampling"]): r for r in time_rows}
shown = 0
for page in pages:
    with open(page) as f:
        text = re.sub(r"```.*?```", "", f.read(), flags=re.S)
    blocks = re.split(r"\n\s*\n", text)
    for i, b in enumerate(blocks):
        rows = [[c.strip() for c in line.strip().strip("|").split("|")]
                for line in b.splitlines() if line.lstrip().startswith("|")]
        if len(rows) < 3 or not re.match(r"^board, clock$", rows[0][0]) or "backend" not in rows[0]:
            continue
        cols = [(j, "aa 3" if "--aa 3" in h else "1 sample") for j, h in enumerate(rows[0]) if re.search(r"\bs\b", h)]
        for row in rows[2:]:
            board, mhz = re.match(r"^(\S+), ([\d.]+) MHz$", row[0]).groups()
            for j, sampling in cols:
                m = re.match(r"^([\d.]+) s\b", row[j])
                if not m:
                    continue
                shown += 1
                r = by_key.get((board, row[rows[0].index("backend")], sampling))
                if not r or not r["cpp"]:
                    off.append("%s: %s %s %s: no priced row in bench/time.csv" % (
                        os.path.relpath(page, ROOT), board, row[1], sampling))
                    continue
                d = len(m.group(1).split(".")[1]) if "." in m.group(1) else 0
                want = float(r["cpp"]) * PIXELS / (float(mhz) * 1e6)
                if abs(round(want, d) - float(m.group(1))) > 1e-9 or r["clock_mhz"] != mhz:
                    off.append("%s: %s at %s MHz, %s %s: %s s, but bench/time.csv's %s cycles/px give %.4g s" % (
                        os.path.relpath(page, ROOT), board, mhz, row[1], sampling, m.group(1), r["cpp"], want))
check(priced and shown and not off, "seconds a frame: %d bench/time.csv rows and %d figures of the pages are "
      "cycles/px x 76,800 / clock, one price a board, backend and sampling%s" % (
          priced, shown, "".join("\n          " + o for o in off)))

# Seconds in prose: a figure "N s" in a paragraph or list item that names
# a clock ("125 MHz") and a bench file is cycles a pixel x 76,800 / clock,
# or a count of cycles / clock, of a number of that file, to the rounding
# shown (a time the pages measure otherwise names no clock: on the host;
# on the wire, "N s at 115200").
def cycles_of(path):
    """the counts of cycles a file gives: its tables' and CSV's cycles
    columns, and numbers followed by "cycles" in its text"""
    with open(path) as f:
        text = f.read()
    out = {float(n.replace(",", "")) for n in re.findall(r"(\d[\d,]*)\s+(?:\w+\s+)?cycles\b", text)}
    if path.endswith(".csv"):
        rows = list(csv.reader(text.splitlines()))
        cols = [i for i, h in enumerate(rows[0]) if h in ("cpp",) or "cycles" in h]
        tables = [rows]
    else:
        tables = [[[c.strip() for c in line.strip().strip("|").split("|")] for line in t.splitlines()]
                  for t in re.findall(r"(?:^\|.*\n)+", text, re.M)]
        # a kept text (bench/keep.sh) whose first line names cycles: its counts
        for block in re.findall(r"```\n(.*?)```", text, re.S):
            if "cycles" in block.split("\n", 1)[0]:
                out.update(float(n) for n in re.findall(r"(?<![\d.])\d{4,}(?![\d.])", block))
    for t in tables:
        cols = [i for i, h in enumerate(t[0]) if h == "cpp" or "cycles" in h]
        for r in t[1:]:
            for i in cols:
                if i < len(r):
                    out.update(float(n.replace(",", "")) for n in re.findall(r"\d[\d,]*", r[i]))
    return out


SECONDS = re.compile(r"(?<![\w.,])(\d+(?:\.\d+)?) s\b(?! of CPU)")
prose_off, prose_n = [], 0
for page in pages:
    with open(page) as f:
        text = re.sub(r"```.*?```", "", f.read(), flags=re.S)
    blocks = re.split(r"\n\s*\n|\n(?=\s*- )", text)
    # a table's rows one by one (but the "board, clock" tables, checked above),
    # each with the paragraph before the table for its files
    items = [(row, prev) for prev, b in zip([""] + blocks, blocks) if b.lstrip().startswith("|")
             and not b.lstrip().startswith("| board, clock") for row in b.splitlines()[2:]]
    items += [(b, "") for b in blocks if not b.lstrip().startswith("|")]
    for b, prev in items:
        clocks = {float(c) * 1e6 for c in re.findall(r"(\d+(?:\.\d+)?) MHz", b)}
        files = sorted({f for f in re.findall(r"bench/[\w.-]+\.(?:md|csv)", b) if os.path.exists(f)}
                       or {f for f in re.findall(r"bench/[\w.-]+\.(?:md|csv)", prev) if os.path.exists(f)})
        if not clocks or not files:
            continue
        have = set().union(*(cycles_of(f) for f in files))
        for m in SECONDS.finditer(b):
            if re.match(r" at [\d,]+\b(?! ?MHz)", b[m.end():]):
                continue  # at a baud rate: a time on the wire, not the render's
            prose_n += 1
            v, d = float(m.group(1)), len(m.group(1).split(".")[1]) if "." in m.group(1) else 0
            if not any(abs(round(n * k / hz, d) - v) < 1e-9 for n in have for hz in clocks for k in (PIXELS, 1)):
                prose_off.append("%s: %s s is no cycles/px x 76,800 / clock (%s MHz) of %s" % (
                    os.path.relpath(page, ROOT), m.group(1), ", ".join("%g" % (c / 1e6) for c in sorted(clocks)),
                    ", ".join(files)))
check(prose_n and not prose_off, "%d seconds figures in prose with a clock and a bench file are its "
      "cycles x pixels / clock%s" % (prose_n, "".join("\n          " + o for o in prose_off)))

# make bench-quick's duration: one place states it
DURATION = re.compile(r"(?:<|under|about|in|takes)\s*~?\d+(?:\.\d+)?\s*(?:s\b|seconds|min\b|minutes)")
places = []
for path in ["Makefile"] + pages + sorted(glob.glob("bench/*.py") + glob.glob("bench/*.sh")):
    with open(path) as f:
        lines_ = f.read().splitlines()
    for n, line in enumerate(lines_):
        if "bench-quick" in line and DURATION.search(line + " " + (lines_[n + 1] if n + 1 < len(lines_) else "")):
            places.append("%s:%d" % (os.path.relpath(path, ROOT), n + 1))
check(len(places) <= 1, "make bench-quick's duration is stated in at most one place%s" % (
    ": " + ", ".join(places) if places else ""))

# bench tables: a variant's row that equals the board's own measures nothing
same = []
for path in sorted(glob.glob("bench/*.md")):
    rows = [[c.strip() for c in line.strip().strip("|").split("|")]
            for line in open(path) if line.startswith("|")]
    own = {(r[0],) + tuple(r[1:]) for r in rows}
    for r in rows:
        if re.match(r"^\S+ [A-Z_]+=\S+$", r[0]) and (r[0].split()[0],) + tuple(r[1:]) in own:
            same.append("%s: %s" % (path, " | ".join(r[:4])))
check(not same, "no bench table has a build variant's row equal to the board's own%s" % (
    "".join("\n          " + s_ for s_ in same) if same else ""))

# docs/scenes.md: the example scene is the shipped one, and renders
with open("docs/scenes.md") as f:
    scenes_md = f.read()
blocks = re.findall(r"^```nff\n(.*?)^```$", scenes_md, re.M | re.S)
with open("examples/make/scene.nff") as f:
    shipped = f.read()
tmp = os.path.join(os.environ.get("TMPDIR", "/tmp"), "docs-check-%d.ppm" % os.getpid())
r = subprocess.run([RT, "examples/make/scene.nff", "-o", tmp, "--quiet"], capture_output=True, text=True)
rendered = r.returncode == 0 and os.path.exists(tmp) and os.path.getsize(tmp) > 0
if os.path.exists(tmp):
    os.remove(tmp)
same = len(blocks) == 1 and blocks[0] == shipped
check(same and rendered, "docs/scenes.md's example scene is examples/make/scene.nff (%d lines)%s; rt renders it%s" % (
    shipped.count("\n"), "" if same else ": %d nff blocks, %s" % (len(blocks), "not the file" if blocks else "none"),
    "" if rendered else ": " + r.stderr.strip()))

# docs/scenes.md's quoted error messages: each is a bad case's, which rt prints
expects = {}
for e in sorted(glob.glob("tests/host/bad/*.expect")):
    with open(e) as f:
        expects.setdefault(f.read().strip(), e[:-len(".expect")] + ".nff")
prose = re.sub(r"```.*?```", "", scenes_md, flags=re.S)
quoted = [" ".join(c.split()) for c in re.findall(r"`([^`]+)`", prose)]
quoted = [re.sub(r"^[\w./-]+\.nff:\d+: ", "", c) for c in quoted if re.match(r"^[\w./-]+\.nff:\d+: ", c)]
not_printed = []
for msg in quoted:
    nff = expects.get(msg)
    if not nff:
        not_printed.append("%s (no tests/host/bad case)" % msg)
        continue
    r = subprocess.run([RT, nff, "-o", tmp, "--quiet"], capture_output=True, text=True)
    if r.returncode != 2 or not re.fullmatch(re.escape(nff) + r":\d+: " + re.escape(msg) + r"\n?", r.stderr):
        not_printed.append("%s (%s printed %r)" % (msg, nff, r.stderr.strip()))
check(len(quoted) >= 4 and not not_printed, "the %d error messages docs/scenes.md quotes are the reader's%s" % (
    len(quoted), "".join("\n          " + m for m in not_printed)))

with open("README.md") as f:
    lines = sum(1 for _ in f)
check(lines <= 250, "README.md: %d lines (at most 250)" % lines)
sys.exit(summary("docs-check"))
