#!/usr/bin/env python3
"""Runs the test suites of tests/suites.list against one build variant,
as many at once as the machine has cores, and closes with the totals.

    python3 tests/run-all.py [BUILD] [--jobs N] [NAME ...]

BUILD is the variant the suites test ($B in the list; default build/asan).
NAME picks suites by name (a script's or binary's name without its
extension); with none, every suite runs. Each suite writes its own log,
build/test-logs/NAME.log; a line is printed as each one ends, and the log
of every suite that failed is printed whole at the end. A suite passes
when its last summary line ("NAME: N passed, M failed") counts no failure
and it exits 0; a suite that prints no summary counts one failure.

Suites run side by side share nothing they write but one cache: each
gets its own FW_ROOT (where make builds and runs firmware), so two suites
never build into, or run from, the same folder; all get FW_CACHE, where a
firmware's compile stores its objects for the next one with the same
preprocessed source and flags (tools/firmware/cc-cache.sh; emptied here
first, its entries written whole or not at all). What all of them read (the host
tools, the scene compilers) is built before the suites start (make test).
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

SUMMARY = re.compile(r'^[a-z0-9_-]+: ([0-9]+) passed, ([0-9]+) failed$')
LIST = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'suites.list')
LOGS = 'build/test-logs'
CACHE = 'build/test-fw/cache'


def read_list(variant):
    """The suites in list order, each as (name, argv)."""
    suites = []
    with open(LIST) as f:
        for number, line in enumerate(f, 1):
            line = line.split('#', 1)[0].strip()
            if not line:
                continue
            argv = shlex.split(line.replace('$B', variant))
            script = next((a for a in argv if a != 'python3'), argv[0])
            name = os.path.splitext(os.path.basename(script))[0]
            if any(name == n for n, _ in suites):
                sys.exit(f'{LIST}:{number}: suite name {name} is listed twice')
            suites.append((name, argv))
    return suites


def result(log_text, status):
    """(passed, failed, summary) of one suite's output and exit status."""
    summary = None
    for line in log_text.splitlines():
        m = SUMMARY.match(line)
        if m:
            summary = m
    if summary is None:
        return 0, 1, 'printed no summary (crashed?)'
    passed, failed = int(summary.group(1)), int(summary.group(2))
    if status != 0 and failed == 0:
        return passed, 1, f'{summary.group(0)}, but exited with status {status}'
    return passed, failed, summary.group(0)


def main(argv):
    jobs = int(os.environ.get('TEST_JOBS') or os.cpu_count() or 1)
    args = []
    i = 0
    while i < len(argv):
        if argv[i] == '--jobs' and i + 1 < len(argv):
            jobs = int(argv[i + 1])
            i += 2
            continue
        args.append(argv[i])
        i += 1
    variant = 'build/asan'
    if args and '/' in args[0]:
        variant = args.pop(0)
    suites = read_list(variant)
    if args:
        unknown = sorted(set(args) - {n for n, _ in suites})
        if unknown:
            sys.exit(f'run-all: no such suite: {" ".join(unknown)} (see {LIST})')
        suites = [s for s in suites if s[0] in args]
    os.makedirs(LOGS, exist_ok=True)
    shutil.rmtree(CACHE, ignore_errors=True)
    jobs = max(1, min(jobs, len(suites)))
    print(f'run-all: {len(suites)} suites against {variant}, {jobs} at a time; logs in {LOGS}/', flush=True)

    start = time.monotonic()
    waiting = list(suites)
    running = {}  # pid -> (name, argv, log file, start time)
    totals = [0, 0]
    failed_logs = []
    while waiting or running:
        while waiting and len(running) < jobs:
            name, cmd = waiting.pop(0)
            log_path = f'{LOGS}/{name}.log'
            log = open(log_path, 'w')
            env = dict(os.environ, FW_ROOT=f'build/test-fw/{name}', FW_CACHE=CACHE)
            try:
                proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, env=env)
            except OSError as e:
                log.write(f'run-all: cannot start {" ".join(cmd)}: {e}\n')
                log.close()
                totals[1] += 1
                failed_logs.append((name, log_path))
                print(f'  FAIL  {name}: cannot start ({e})', flush=True)
                continue
            running[proc.pid] = (name, log, log_path, time.monotonic(), proc)
        pid, status, usage = os.wait4(-1, 0)
        if pid not in running:
            continue
        name, log, log_path, t0, proc = running.pop(pid)
        proc.returncode = os.waitstatus_to_exitcode(status)
        log.close()
        with open(log_path, errors='replace') as f:
            text = f.read()
        passed, failed, summary = result(text, proc.returncode)
        totals[0] += passed
        totals[1] += failed
        took = time.monotonic() - t0
        cpu = usage.ru_utime + usage.ru_stime
        verdict = 'ok   ' if failed == 0 else 'FAIL '
        print(f'  {verdict} {summary}  ({took:.0f} s, cpu {cpu:.0f} s)', flush=True)
        if failed:
            failed_logs.append((name, log_path))

    for name, log_path in failed_logs:
        print(f'\n==== {name} failed: its log, {log_path} ====')
        with open(log_path, errors='replace') as f:
            sys.stdout.write(f.read())
    print(f'\n(all suites took {time.monotonic() - start:.0f} s)')
    print(f'{totals[0]} passed, {totals[1]} failed')
    return 0 if totals[1] == 0 else 1


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
