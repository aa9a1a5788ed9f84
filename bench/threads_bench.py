#!/usr/bin/env python3
"""`rt --threads`: the host's speed-up on two cores.

Every SPD scene (scenes/spd/*.nff) at 512x512 in SPD mode (--spd, fixed
backend), rendered by build/host/rt with
  - --threads 1: the whole frame in one call of the core, one thread;
  - --threads 2: two threads, each starting on half the lines and taking
    half of what the other has left when it runs out (app/rt/
    bands.c); each run start recomputes its top row of SPD corner rays,
    which the eye-ray column shows.
Time: render_seconds of --stats (wall time of the render, without loading
the scene), median of RUNS runs after a warm-up, the two taken in turn;
beside it threads_busy (the share of 2 x the wall time the two threads
spent rendering) and the threads' time together against one thread's
(2 x busy x time / one thread's time: the extra corner rows, and the
threads slowing each other down on shared caches or a shared host), so
speed-up = 2 x busy / that. The host may be shared: a run during which other processes used
more than a tenth of a core is repeated (up to TRIES times, then kept and
counted in the table's last column). It writes bench/threads.md and
bench/threads.csv.

  bench/threads_bench.py [--runs N] [--scenes a,b]
"""
import argparse
import csv
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "build", "bench-threads")
SIZE = "512x512"
RUNS = 7
TRIES = 10
OTHER_MAX = 0.1  # of a core, on average over the run
THREADS = [1, 2]
TICK = os.sysconf("SC_CLK_TCK")


def busy_seconds():
    """CPU time every process of the machine has used so far (/proc/stat)."""
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:9]]
    return (sum(v) - v[3] - v[4]) / TICK  # all but idle and iowait


def render(scene, threads):
    """(render_seconds, eye_rays, threads_busy, quiet): the run repeated while others were busy."""
    cmd = ["build/host/rt", scene, "-o", os.path.join(OUT, "out.png"), "--size", SIZE, "--spd", "--fixed",
           "--threads", str(threads), "--quiet", "--stats"]
    for attempt in range(TRIES):
        r0, b0, t0 = resource.getrusage(resource.RUSAGE_CHILDREN), busy_seconds(), time.monotonic()
        p = subprocess.run(cmd, cwd=ROOT, check=True, capture_output=True, text=True)
        r1, b1, t1 = resource.getrusage(resource.RUSAGE_CHILDREN), busy_seconds(), time.monotonic()
        mine = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
        other = (b1 - b0) - mine
        secs = float(re.search(r"^render_seconds\s+(\S+)$", p.stderr, re.M).group(1))
        eye = int(re.search(r"^eye_rays\s+(\d+)$", p.stderr, re.M).group(1))
        busy = float(re.search(r"^threads_busy\s+(\S+)$", p.stderr, re.M).group(1))
        quiet = other <= OTHER_MAX * (t1 - t0) + 2.0 / TICK  # a tick or two of noise
        if quiet:
            break
        time.sleep(1 + attempt)
    return secs, eye, busy, quiet


def render_pair(scene):
    """Mean render_seconds of two one-thread renders run at once, as separate
    processes: what the machine's two cores give two jobs that share
    nothing, the control for the threads' speed-up."""
    cmd = lambda k: ["build/host/rt", scene, "-o", os.path.join(OUT, "pair%d.png" % k), "--size", SIZE, "--spd",
                     "--fixed", "--threads", "1", "--quiet", "--stats"]
    ps = [subprocess.Popen(cmd(k), cwd=ROOT, stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
          for k in (0, 1)]
    outs = [p.communicate()[1] for p in ps]
    return statistics.mean(float(re.search(r"^render_seconds\s+(\S+)$", o, re.M).group(1)) for o in outs)


def cpu_name():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def gmean(xs):
    return math.exp(sum(math.log(x) for x in xs) / len(xs))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=RUNS)
    ap.add_argument("--scenes", help="comma-separated names (default: every scenes/spd/*.nff)")
    args = ap.parse_args()
    os.makedirs(OUT, exist_ok=True)
    names = (args.scenes.split(",") if args.scenes else
             sorted(f[:-4] for f in os.listdir(os.path.join(ROOT, "scenes", "spd")) if f.endswith(".nff")))
    rows = []
    for name in names:
        scene = os.path.join("scenes", "spd", name + ".nff")
        for n in THREADS:
            render(scene, n)  # warm-up
        times = {n: [] for n in THREADS}
        busy, pair = [], []
        eyes, noisy = {}, 0
        for _ in range(args.runs):
            for n in THREADS:
                secs, eye, b, quiet = render(scene, n)
                times[n].append(secs)
                eyes[n] = eye
                noisy += not quiet
                if n == 2:
                    busy.append(b)
            pair.append(render_pair(scene))
        row = {"scene": name, "threads1_s": statistics.median(times[1]), "threads2_s": statistics.median(times[2]),
               "busy_2": statistics.median(busy), "eye_rays_1": eyes[1], "eye_rays_2": eyes[2], "noisy_runs": noisy}
        row["speedup"] = row["threads1_s"] / row["threads2_s"]
        row["thread_time_ratio"] = 2 * row["busy_2"] * row["threads2_s"] / row["threads1_s"]
        row["pair_ratio"] = statistics.median(pair) / row["threads1_s"]  # two processes at once, over one alone
        row["ceiling"] = 2 / row["pair_ratio"]
        rows.append(row)
        print("%-16s --threads 1 %.3f s  --threads 2 %.3f s  speed-up %.2fx  busy %.3f  thread time %.2fx  "
              "two processes %.2fx (ceiling %.2fx)%s"
              % (name, row["threads1_s"], row["threads2_s"], row["speedup"], row["busy_2"], row["thread_time_ratio"],
                 row["pair_ratio"], row["ceiling"],
                 "  (%d noisy runs)" % noisy if noisy else ""), flush=True)

    keys = ["scene", "threads1_s", "threads2_s", "speedup", "busy_2", "thread_time_ratio", "pair_ratio", "ceiling",
            "eye_rays_1", "eye_rays_2", "noisy_runs"]
    with open(os.path.join(ROOT, "bench", "threads.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(keys)
        for r in rows:
            w.writerow([("%.4f" % r[k]) if isinstance(r[k], float) else r[k] for k in keys])
    g1, g2 = gmean([r["threads1_s"] for r in rows]), gmean([r["threads2_s"] for r in rows])
    md = ["# rt --threads: speed-up on the host", "",
          "Generated by `bench/threads_bench.py` (`make bench`) on %d online CPUs (%s). Every SPD scene at %s in "
          "SPD mode, fixed backend; render time (`render_seconds`: wall time, scene loading excluded), median of %d "
          "runs after a warm-up. `--threads 1`: the whole frame in one call of the core; `--threads 2`: two "
          "threads, each starting on half the lines and taking half of what the other has left when it runs out, "
          "each start recomputing its top row of SPD corners (the eye rays columns). Speed-up: `--threads 1` time over `--threads 2` time. Busy: `threads_busy` of `--threads 2`, "
          "the share of 2 x its time the threads spent rendering (the rest: starting the second thread, the end "
          "of the frame). Thread time: the two threads' rendering time together against one thread's (2 x busy x "
          "time / one thread's time): above 1 by the extra corner rows and by the threads slowing each other "
          "down (shared caches, or a host that shares the cores); speed-up = 2 x busy / thread time. Two "
          "processes: two one-thread renders run at once as separate processes (sharing nothing), their time over "
          "one alone, measured in the same runs: what this machine's two cores give two independent jobs; ceiling "
          "= 2 / that, the speed-up the threads could reach here. Runs during "
          "which other processes used more than %d%% of a core were repeated (up to %d times); \"noisy\" counts "
          "those kept anyway (a virtual machine's neighbours are not seen)."
          % (os.cpu_count() or 0, cpu_name(), SIZE, args.runs, int(OTHER_MAX * 100), TRIES), "",
          "| scene | --threads 1 (s) | --threads 2 (s) | speed-up | busy | thread time | two processes | ceiling | "
          "eye rays, 1 thread | eye rays, 2 threads | noisy |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append("| %s | %.3f | %.3f | %.2fx | %.3f | %.2fx | %.2fx | %.2fx | %d | %d | %d |" % (
            r["scene"], r["threads1_s"], r["threads2_s"], r["speedup"], r["busy_2"], r["thread_time_ratio"],
            r["pair_ratio"], r["ceiling"], r["eye_rays_1"], r["eye_rays_2"], r["noisy_runs"]))
    md.append("| geometric mean | %.3f | %.3f | %.2fx | %.3f | %.2fx | %.2fx | %.2fx | | | %d |" % (
        g1, g2, g1 / g2, gmean([r["busy_2"] for r in rows]), gmean([r["thread_time_ratio"] for r in rows]),
        gmean([r["pair_ratio"] for r in rows]), gmean([r["ceiling"] for r in rows]),
        sum(r["noisy_runs"] for r in rows)))
    with open(os.path.join(ROOT, "bench", "threads.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("wrote bench/threads.md, bench/threads.csv: geometric mean speed-up %.2fx" % (g1 / g2))


if __name__ == "__main__":
    try:
        main()
    except subprocess.CalledProcessError as e:
        sys.exit("bench: %s failed:\n%s%s" % (" ".join(e.cmd), e.stdout, e.stderr))
