#!/usr/bin/env python3
"""Where the second core idles: a scheduler timeline of one rcache render at N threads (default 2),
per phase (cache fill, final pass), from one system-wide `perf record` of the scheduler's switches
and of the CPU clock (1 kHz per CPU, DWARF call stacks).

The switches give, for every moment, which of the render's threads are on a CPU (the control
thread C, the pool's workers W, PoCL's kernel threads P) and whether other processes hold a CPU.
Reported per phase:
  - the phase's wall time split by how many of the render's threads ran: 0 (all waiting), 1 (C
    alone, W alone, P alone), 2 or more; "(preempted)" where one of its threads was runnable but
    off a CPU (load from other processes, not the render's own waiting; a polling worker's yield
    to another process counts too);
  - where the time with one thread running and the others waiting goes: the clock samples taken
    while their thread was the only one on a CPU and none was preempted, by call site (the innermost
    rcache function that is not the pool's own machinery, ← its caller, · the leaf when it is a
    library or kernel function). A site on C is serial work; on W or P it is the last chunk of a
    loop or a kernel's last work-groups, while C waits.
A polling pool worker counts as on a CPU. Where the control thread sleeps is better read from its
own switches: perf record -e sched:sched_switch -c 1 --call-graph dwarf,16384 of the render alone.
Times are exact for the split (switch timestamps) and sampled (1 ms each) for the sites.

Phases are told apart by the control thread's stacks: the fill from its first to last sample under
rc::fillCache, the final pass under rc::FinalPass::. Needs perf with the sched tracepoints and root
(-a). Say the machine's load with the figures: other processes' time is shown, not removed.

Usage (repository root): python3 bench/thread_timeline.py [--rcache build/rcache] [--threads 2]
                         [--top 10] SCENE.xml [rcache args...]
"""
import argparse
import bisect
import collections
import os
import re
import subprocess
import tempfile

GENERIC = ("rc::parallelFor", "WorkerPool", "readBack", "rc::parallelSelect", "ParallelArray", "rc::ArrayView",
           "rc::parallelSort")
HEADER = re.compile(r"^(\S.*?)\s+(\d+)/(\d+)\s+\[(\d+)\]\s+([\d.]+):\s+(?:\d+\s+)?(\S+):\s*(.*)$")
SWITCH = re.compile(r"prev_pid=(\d+) .*prev_state=(\S+) ==> .*next_pid=(\d+)")


def record(args, extra, work):
    data = os.path.join(work, "perf.data")
    pid_file = os.path.join(work, "pid")
    # The render's pid through a shell that execs it: other renders may run on the machine.
    # --rt: the render at real-time priority (chrt -f 10) and perf not, so perf's own work (it writes
    # the stacks out) waits in its buffers instead of taking a core from the render.
    rt = ["chrt", "-f", "10"] if args.rt else []
    render = ["sh", "-c", 'echo $$ > "$0"; exec "$@"', pid_file] + rt + [args.rcache, args.scene, "-t", str(args.threads),
              "--quiet", "-o", os.path.join(work, "out.exr")] + extra
    # Every switch (-c 1: a tracepoint under -F would be sampled too), the clock at 1 kHz; big
    # buffers so that no stack is lost.
    cmd = ["perf", "record", "-q", "-a", "-e", "sched:sched_switch", "-c", "1", "-e", "cpu-clock/freq=1000/",
           "-m", "32768", "--call-graph", "dwarf,8192", "-o", data, "--"] + render
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(pid_file) as f:
        pid = int(f.read())
    return pid, subprocess.run(["perf", "script", "-i", data, "-F", "comm,pid,tid,cpu,time,event,trace,ip,sym"],
                               capture_output=True, text=True, check=True).stdout


def parse(text):
    """Events as (time, cpu, pid, tid, event, trace, stack of symbols leaf first)."""
    events, cur = [], None
    for line in text.splitlines():
        if not line.strip():
            cur = None
            continue
        m = HEADER.match(line)
        if m:
            cur = [float(m.group(5)), int(m.group(4)), int(m.group(2)), int(m.group(3)), m.group(6), m.group(7), []]
            events.append(cur)
        elif cur is not None:
            parts = line.split(None, 1)
            cur[6].append(parts[1] if len(parts) > 1 else "?")
    return events


def clean(sym):
    m = re.search(r"(rc::[\w:~()]*?)(?:\(|$)", sym.replace("(anonymous namespace)", "anon"))
    name = m.group(1) if m else sym.split("(")[0]
    return name + ("{λ}" if "{lambda" in sym else "")


def site(stack):
    names = []
    for sym in stack:
        if "rc::" not in sym or any(g in sym for g in GENERIC):
            continue
        name = clean(sym)
        if not names or names[-1] != name:
            names.append(name)
        if len(names) == 2:
            break
    leaf = stack[0].split("(")[0] if stack else "?"
    label = " ← ".join(names) if names else "(outside rcache: %s)" % leaf
    if names and "rc::" not in leaf:
        label += " · " + leaf[:40]
    return label


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rcache", default="build/rcache")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--top", type=int, default=10)
    ap.add_argument("--perf-script", help="analyse this saved `perf script` output instead of recording")
    ap.add_argument("--rt", action="store_true", help="run the render under chrt -f 10 (perf not)")
    ap.add_argument("--pid", type=int, help="with --perf-script: the render's pid")
    ap.add_argument("scene")
    args, extra = ap.parse_known_args()
    if args.perf_script:
        with open(args.perf_script) as f:
            events = parse(f.read())
        pid = args.pid
    else:
        with tempfile.TemporaryDirectory(prefix="rcache_timeline_") as work:
            pid, text = record(args, extra, work)
            events = parse(text)
    control = pid
    tids = {e[3] for e in events if e[2] == pid}
    pool = {e[3] for e in events if e[2] == pid and any("WorkerPool" in s for s in e[6])} - {control}

    def klass(tid):
        return "C" if tid == control else "W" if tid in pool else "P"

    samples = [e for e in events if e[4].startswith("cpu-clock") and e[2] == pid]
    phases = {"fill": [e[0] for e in samples if e[3] == control and any("rc::fillCache" in s for s in e[6])],
              "final pass": [e[0] for e in samples if e[3] == control and any("rc::FinalPass::" in s for s in e[6])]}
    # Running set over time (sweep of the CPU changes): times, per time the render's running tids,
    # whether one of its threads was preempted (runnable, off a CPU: load, not the render's own
    # waiting), and how many CPUs ran other processes.
    switches = sorted(((e[0], e[1], SWITCH.search(e[5])) for e in events if e[4] == "sched:sched_switch"),
                      key=lambda x: (x[0], x[1]))
    on_cpu, preempted, times, running, others, held = {}, set(), [], [], [], []
    for t, cpu, m in switches:
        prev, state, nxt = int(m.group(1)), m.group(2), int(m.group(3))
        if prev in tids and state.startswith("R"):
            preempted.add(prev)
        preempted.discard(nxt)
        if prev in tids and not state.startswith("R"):
            preempted.discard(prev)
        on_cpu[cpu] = nxt
        times.append(t)
        running.append(frozenset(x for x in on_cpu.values() if x in tids))
        others.append(sum(1 for x in on_cpu.values() if x not in tids and x != 0))
        held.append(bool(preempted))

    for name, ts in phases.items():
        if not ts:
            print("%s: no samples (path-traced by the pilot?)" % name)
            continue
        lo, hi = min(ts), max(ts)
        split = collections.Counter()
        other_s = 0.0
        i = max(0, bisect.bisect_right(times, lo) - 1)
        while i < len(times) and times[i] < hi:
            a, b = max(lo, times[i]), min(hi, times[i + 1] if i + 1 < len(times) else hi)
            run = running[i]
            key = "2+" if len(run) >= 2 else "0" if not run else klass(next(iter(run))) + " alone"
            if held[i]:
                key += " (preempted)"
            split[key] += b - a
            other_s += others[i] * (b - a)
            i += 1
        wall = hi - lo
        print("## %s: %.3f s (from %d control-thread samples), %d threads" % (name, wall, len(ts), args.threads))
        print("time by threads of the render on a CPU: " + ", ".join(
            "%s %.3f s (%.1f %%)" % (k, v, 100 * v / wall) for k, v in sorted(split.items())))
        print("CPU time of other processes in the window: %.3f s" % other_s)
        alone = {k: collections.Counter() for k in "CWP"}
        for e in samples:
            if not lo <= e[0] <= hi:
                continue
            i = bisect.bisect_right(times, e[0]) - 1
            if i >= 0 and running[i] == frozenset([e[3]]) and not held[i]:
                alone[klass(e[3])][site(e[6])] += 1
        for k, label in (("C", "control thread alone (serial)"), ("W", "worker alone (C waits)"),
                         ("P", "PoCL alone (C waits)")):
            total = sum(alone[k].values())
            print("### %s, the others waiting: %d samples (≈ %.3f s)" % (label, total, total / 1000))
            for s, c in alone[k].most_common(args.top):
                print("  %5d  %s" % (c, s))


if __name__ == "__main__":
    main()
