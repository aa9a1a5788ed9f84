#!/usr/bin/env python3
"""Worst-case stack depth of the firmware from GCC's -fcallgraph-info=su.

Reads the .ci files of a build, follows the call graph from a root, and
prints the deepest path. Self-recursion (CSG's solid_spans; the tracer walks
its ray tree in a loop, trace.c) counts --depth frames;
indirect calls go to the --indirect targets; functions without a known
frame (libgcc helpers) count --unknown bytes and are listed.
"""
import argparse
import glob
import os
import re
import sys

NODE = re.compile(r'node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE = re.compile(r'edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')


def load(folder):
    frames, edges = {}, {}
    for path in glob.glob(os.path.join(folder, "*.ci")):
        with open(path) as f:
            text = f.read()
        for title, label in NODE.findall(text):
            m = re.search(r"(\d+) bytes", label)
            if m:
                frames[title] = int(m.group(1))
        for src, dst in EDGE.findall(text):
            edges.setdefault(bare(src), set()).add(bare(dst))
    # static functions are titled "file:name"; calls from other files use "name"
    return {bare(t): n for t, n in frames.items()}, edges


# A whole-program (LTO) build writes one call graph for its one partition,
# titled after a temporary object: its names are unique already.
LTRANS = re.compile(r"^[^:]*\.ltrans\d+\.o:")
# The linker folds identical copies of a local function (x.lto_priv.0,
# x.lto_priv.1) into one; a call may name a copy that has no frame left.
LTO_COPY = re.compile(r"^(.*\.lto_priv)\.\d+$")


def bare(title):
    return LTRANS.sub("", title)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("folder")
    ap.add_argument("--root", default="main")
    ap.add_argument("--below", default="", help="comma-separated functions under the root (start-up code that calls it "
                    "through a pointer): their frames are added")
    ap.add_argument("--depth", type=int, default=5, help="frames of a self-recursive function")
    ap.add_argument("--indirect", default="", help="comma-separated targets of indirect calls")
    ap.add_argument("--unknown", type=int, default=64, help="bytes assumed for functions without .su data")
    args = ap.parse_args()

    frames, edges = load(args.folder)
    indirect = [t for t in args.indirect.split(",") if t]
    unknown = set()
    memo = {}

    def resolve(name):
        if name in frames or name in edges:
            return name
        for title in frames:
            if title.endswith(":" + name):
                return title
        return name

    def worst(fn, stack):
        if fn in memo:
            return memo[fn]
        if fn in stack:
            sys.exit("stack_usage: call cycle through %s (only self-recursion is bounded)" % fn)
        copies = [frames[t] for t in frames if LTO_COPY.match(fn) and LTO_COPY.sub(r"\1", t) == LTO_COPY.sub(r"\1", fn)]
        if fn not in frames and copies:
            frames[fn] = max(copies)
        if fn not in frames:
            unknown.add(fn)
            return args.unknown, [fn + " (unknown, assumed)"]
        callees = set()
        for c in edges.get(fn, ()):
            if c == "__indirect_call":
                callees.update(resolve(t) for t in indirect)
            else:
                callees.add(resolve(c))
        recursive = fn in callees
        callees.discard(fn)
        best, path = 0, []
        for c in sorted(callees):
            d, p = worst(c, stack | {fn})
            if d > best:
                best, path = d, p
        n = args.depth if recursive else 1
        result = (n * frames[fn] + best, ["%s %d bytes%s" % (fn, frames[fn], " x %d" % n if n > 1 else "")] + path)
        memo[fn] = result
        return result

    total, path = worst(resolve(args.root), frozenset())
    # the start-up code under the root, which calls it through a pointer
    below = [(resolve(b), frames[resolve(b)]) for b in args.below.split(",") if b and resolve(b) in frames]
    total += sum(n for _, n in below)
    print("worst-case stack from %s: %d bytes" % (args.root, total))
    for name, n in below:
        print("    %s %d bytes (calls it)" % (name, n))
    for step in path:
        print("    " + step)
    if unknown:
        print("    (assumed %d bytes for: %s)" % (args.unknown, ", ".join(sorted(unknown))))


if __name__ == "__main__":
    main()
