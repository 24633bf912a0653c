#!/usr/bin/env python3
"""Turns the CSVs that scripts/benchmarks measured into docs/benchmarks.md.
Every number in the page comes from those files; none is typed here."""
import csv
import json
import os
import statistics
import sys


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def speedup_against_cpus(w, cpu_rows):
    """Two threads against the best the two fastest CPUs can do, 1 / (1 / t_a + 1 / t_b), seed by seed."""
    cpus = sorted({r["cpu"] for r in cpu_rows if r["cpu"] != "any"}, key=int)
    runs = {}  # (algorithm, iterations) -> seed -> cpu -> wall
    for r in cpu_rows:
        runs.setdefault((r["algorithm"], int(r["iterations"])), {}).setdefault(r["seed"], {})[r["cpu"]] = float(r["wall_s"])
    w("One thread pinned to each CPU (`taskset -c K`), then two threads, back to back for each seed "
      "(`acobench --first-seed K --seeds 1`): a virtual machine's CPUs need not be equally fast, an unpinned "
      "one-thread run lands on any, and the machine's speed drifts within minutes. Two threads can at best take "
      "1 / (1 / t_a + 1 / t_b) on the two fastest (serial part aside); the last columns are how close they come, "
      f"the median of the seeds' ratios and its range ({len(next(iter(runs.values()), {}))} seeds).\n")
    w("| algorithm | iterations | " + " | ".join(f"CPU {c} s" for c in cpus) +
      " | two threads s | best / two threads | min | max |")
    w("|---|---:|" + "---:|" * (len(cpus) + 4))
    for config, seeds in runs.items():
        ratios = []
        for times in seeds.values():
            if "any" in times and all(c in times for c in cpus):
                best = 1.0 / sum(1.0 / t for t in sorted(times[c] for c in cpus)[:2])
                ratios.append(best / times["any"])
        if not ratios:
            continue
        med = {c: statistics.median(t[c] for t in seeds.values() if c in t) for c in cpus + ["any"]}
        w(f"| {config[0]} | {config[1]} | " + " | ".join(f"{med[c]:.3f}" for c in cpus) +
          f" | {med['any']:.3f} | {statistics.median(ratios):.2f} | {min(ratios):.2f} | {max(ratios):.2f} |")
    w("")


def main():
    d = sys.argv[1]
    out = []
    w = out.append
    machine = dict(line.strip().split("=", 1) for line in open(os.path.join(d, "machine.txt")) if "=" in line)
    w("# Benchmarks\n")
    w("Measured by the harness and written by `scripts/benchmarks`; regenerate with that one command "
      "(most of an hour on 2 cores: the gap table alone runs its budgets for 5 seeds, 24 minutes). Raw data: "
      "`docs/bench/`.\n")
    w(f"Machine: {machine.get('cpu')}, {machine.get('cores')} cores, {machine.get('memory')}, {machine.get('os')}, "
      f"{machine.get('compiler')}; commit {machine.get('commit')}.\n")
    if machine.get("remeasured"):
        w(f"Rows measured again: {machine.get('remeasured')}.\n")
    if machine.get("sections") and machine.get("sections") != "thesis targets gap speedup scale programs micro":
        w(f"That run measured these sections: {machine.get('sections')}; the others keep the CSVs of an earlier "
          "run (`git log docs/bench`).\n")
    for key in sorted(k for k in machine if k.startswith("measured.")):
        w(f"Measured again since: the {key.split('.', 1)[1]} section, at {machine[key]}.\n")

    # Gap at fixed budgets, beside the best published parallel ACO (issue 12).
    path = os.path.join(d, "tsp-targets.csv")
    peers = {}
    if len(sys.argv) > 2 and os.path.exists(sys.argv[2]):
        for r in rows(sys.argv[2]):
            peers[(r["instance"], r["budget_s"])] = r
    if os.path.exists(path):
        w("## Gap to the optimum within a time budget\n")
        w("`acodrill tsp INSTANCE --time-limit BUDGET --threads 2 --seed K`, default settings (the focused colony "
          "with 2-opt, Or-opt and 3-opt with Lin-Kernighan steps, on alpha-nearness candidates), whole-process wall "
          "time, median over seeds; gap with TSPLIB's rounded distances (CEIL_2D rounded up for pla7397). "
          "Beside it, from `bench/peers.csv` (measured on a machine of this kind, `../shared/peers.md`): the median "
          "of Focused ACO (R. Skinderowicz, Applied Soft Computing 2022; the author's code, 2 threads, same budgets; "
          "at 60 s for d15112 and brd14051), LKH-3's gap at the wall time it took with that budget (1 thread, its "
          "only mode; the budgets of pla7397, d15112 and brd14051 are that wall time), and the bound an issue set "
          "(issue 12's; issue 24's, twice LKH-3's gap, where there is an LKH-3 figure). "
          "✓: at or below Focused ACO and the bound.\n")
        w("| instance | budget s | median gap | min | max | Focused ACO | LKH-3 | bound | median wall s | peak RSS MB | seeds |")
        w("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        by = {}
        for r in rows(path):
            by.setdefault((r["instance"], r["budget_s"]), []).append(r)
        # In bench/peers.csv's order, whatever order the rows were measured in.
        order = list(peers.keys())
        rank = lambda key: order.index(key) if key in order else len(order)
        for (inst, budget), rs in sorted(by.items(), key=lambda kv: rank(kv[0])):
            gaps = [float(r["gap_pct"]) for r in rs]
            walls = [float(r["wall_s"]) for r in rs]
            rss = max(int(r["peak_rss_mb"]) for r in rs)
            med = statistics.median(gaps)
            peer = peers.get((inst, budget))
            faco = float(peer["focused_aco_median_pct"]) if peer and peer["focused_aco_median_pct"] else None
            bound = float(peer["target_pct"]) if peer and peer["target_pct"] else None
            lkh = float(peer["lkh3_pct"]) if peer and peer.get("lkh3_pct") else None
            limits = [x for x in (faco, bound) if x is not None]
            verdict = "" if not limits else (" ✓" if med <= min(limits) + 1e-9 else " ✗")
            w(f"| {inst} | {budget} | {med:.2f} %{verdict} | {min(gaps):.2f} % | {max(gaps):.2f} % | "
              f"{'' if faco is None else f'{faco:.2f} %'} | {'' if lkh is None else f'{lkh:.2f} %'} | "
              f"{'' if bound is None else f'{bound:.2f} %'} | "
              f"{statistics.median(walls):.2f} | {rss} | {len(rs)} |")
        w("")

    # 33 000 to 100 000 holes (issue 24): acodrill, and Focused ACO where the section ran it (FACO_BIN).
    path = os.path.join(d, "scale.csv")
    if os.path.exists(path):
        w("## 33 000 to 100 000 holes\n")
        w("`acodrill tsp INSTANCE --time-limit BUDGET --threads 2 --seed K`, default settings, whole process. No "
          "optimum is known for these instances, so each length is given against a reference. Holes at uniform "
          "random places on a square plate, in random order (`bench/make_uniform.py`, seed 1; EUC_2D): the "
          "Beardwood-Halton-Hammersley estimate 0.7124·√(n·A) of the optimum, which a square's edges make a little "
          "short, so the optimum itself lies somewhat above it. `pla7397x5`, five copies of pla7397 side by side "
          "with 20 000 units between them (`bench/make_tiled.py`; CEIL_2D): five times pla7397's optimum, which "
          "leaves out the moves between copies. Focused ACO, where measured: the author's public code built "
          "outside the project (`FACO_BIN`, see `scripts/benchmarks`), its default settings, 2 threads, stopped by "
          "the same whole-process wall time, which it checks once an iteration (so it may run over by up to an "
          "iteration: up to 1.5 s at 100 000 holes). LKH-3 cannot be run on this machine.\n")
        by = {}
        for r in rows(path):
            by.setdefault((r["instance"], int(r["n"]), r["budget_s"]), {}).setdefault(r["solver"], []).append(
                (float(r["above_reference_pct"]), float(r["wall_s"]), int(r["peak_rss_mb"])))
        has_faco = any("faco" in v for v in by.values())
        head = "| instance | holes | budget s | median above the reference | min | max |"
        line = "|---|---:|---:|---:|---:|---:|"
        if has_faco:
            head += " Focused ACO (min-max) |"
            line += "---:|"
        w(head + " median wall s | peak RSS MB | seeds |")
        w(line + "---:|---:|---:|")
        for (inst, n, budget), solvers in sorted(by.items(), key=lambda kv: kv[0][1]):
            rs = solvers.get("acodrill", [])
            if not rs:
                continue
            above = [x[0] for x in rs]
            row = (f"| {inst} | {n} | {budget} | {statistics.median(above):.2f} % | {min(above):.2f} % | "
                   f"{max(above):.2f} % |")
            if has_faco:
                fs = [x[0] for x in solvers.get("faco", [])]
                row += (f" {statistics.median(fs):.2f} % ({min(fs):.2f}-{max(fs):.2f}) |" if fs else " |")
            w(row + f" {statistics.median(x[1] for x in rs):.2f} | {max(x[2] for x in rs)} | {len(rs)} |")
        if has_faco:
            faco_rss = max(x[2] for v in by.values() for x in v.get("faco", []))
            w(f"\nFocused ACO's peak RSS: up to {faco_rss} MB (its ants each keep whole routes).")
        w("")

    # Gap against time per algorithm, and baselines.
    path = os.path.join(d, "gap-summary.csv")
    if os.path.exists(path):
        w("## Algorithms against the time budget (TSPLIB)\n")
        w("`acobench --algorithm focused,acs,mmas,as --time-limit 0.25,1,4 --threads 2 --seeds 3`: median gap. "
          "`focused` is the default; `as` is the thesis's Ant System, here with local search.\n")
        summary = rows(path)
        budgets = sorted({float(r["time_limit_s"]) for r in summary})
        w("| instance | algorithm | " + " | ".join(f"{b:g} s" for b in budgets) + " |")
        w("|---|---|" + "---:|" * len(budgets))
        cells = {}
        for r in summary:
            cells[(r["instance"], r["algorithm"], float(r["time_limit_s"]))] = r["gap_median_pct"]
        for inst in sorted({r["instance"] for r in summary}):
            for alg in ["focused", "acs", "mmas", "as"]:
                if (inst, alg, budgets[0]) in cells:
                    w(f"| {inst} | {alg} | " + " | ".join(f"{float(cells.get((inst, alg, b), 'nan')):.2f} %" for b in budgets) + " |")
        w("")
        w("![gap against time](bench/plots-gap/gap_vs_time.svg)\n")
    path = os.path.join(d, "baseline-summary.csv")
    if os.path.exists(path):
        w("### Baselines\n")
        w("| instance | order | gap | wall s |")
        w("|---|---|---:|---:|")
        names = {"input": "input order", "raster": "boustrophedon raster (CAM default)", "nn": "nearest neighbour",
                 "greedy": "greedy edge", "nn2opt": "nearest neighbour + 2-opt (pcb2gcode)"}
        for r in rows(path):
            w(f"| {r['instance']} | {names.get(r['algorithm'], r['algorithm'])} | {float(r['gap_median_pct']):.2f} % | "
              f"{float(r['wall_median_s']):.4f} |")
        w("")

    # Speedup, idle and loaded.
    for name, title in [("speedup-summary.csv", "an idle machine"),
                        ("speedup-loaded-summary.csv", "a busy machine (two other processes keep both cores busy)")]:
        path = os.path.join(d, name)
        if not os.path.exists(path):
            continue
        if name == "speedup-summary.csv":
            w("## Threads\n")
            w("`acobench --instances pcb1173.tsp --algorithm focused --iterations 200,2000 --threads 1,2 --seeds 9` "
              "and the same for `acs` at 200 iterations: the same iterations on 1 and 2 threads, median wall time of "
              "the solver (its whole run, candidate lists included); the tours are identical (same seed). Each seed "
              "runs on 1 and then on 2 threads, so both see the machine in the same state. A focused iteration on "
              "pcb1173 lasted about 1.5 ms on one thread with 10 ants: in 200 of them (0.3 s) the solver's start weighs. By timing "
              "instrumentation at 25c8cc1 and 21f63d6 (not committed), the candidate lists and the first route took about 30 ms on one "
              "thread, 23.6 of them the ascent's 100 spanning trees; on two threads about 20-22 ms, the ascent 14.7 ms "
              "(the two strips' trees 12.4-12.7 ms each, the joins and steps between them 1.8 ms on one thread), and "
              "the local search of the first route (2.2 ms) is one thread's. The second thread comes up 0.15-3.3 ms "
              "after it is launched, as its CPU wakes; the first thread goes on meanwhile. Within the iterations the "
              "ants of a round vary (3 us to 1.2 ms, nearly all of it local search), and over 200 rounds the worker "
              "done first waited about 5 ms in all for the other's last ant; ordering the ants by their true cost "
              "would have saved at most 3.7 ms of it. The tables below were measured on a day this VM ran the same "
              "solve 1.8 times slower; timed then the same way (287da5a, the same solver), the start took 53 ms on one "
              "thread and 37-43 ms on two (the ascent 40 against 25-31 ms, the first route 4.4-6 ms on one thread "
              "either way), the second thread came up 0.16-3.6 ms after its launch, and over 200 rounds the worker "
              "done first waited 19-28 ms in all for the other's last ant. Timed ant by ant at 9f910e4 (not committed; "
              "2000 iterations on one pinned thread, seeds 1-3), building an ant's route is 3.0-3.3 % of the ants' work "
              "and its local search the rest; dealing those times out round by round to two workers as the team deals "
              "them (each free worker takes the next ant) leaves the one done first waiting 5.0-5.3 % of the ideal "
              "two-thread wall with the ants in the order they have (largest bound first), 3.6-3.9 % if they went by "
              "the new edges each ant made (known only once built: every route built before any search), and 1.4 % in "
              "the best order, known only afterwards. With rounds of 10 ants whose searches vary this much, about that share of "
              "two threads' time goes to waiting. 2000 iterations are nearer the work of 200 whole-route ACS "
              "iterations. Larger rounds win that wait back, and since 7ff92fe a focused round has 40 ants from 801 "
              "to 10 000 holes, pcb1173 among them, so the tables below are of rounds of 40, an iteration four times "
              "the work it was (measured at b5f8c4e, in the same hour, the same ratio as the second table below, "
              "9 seeds, `acobench ... --ants N`: with 40 ants two threads came to 0.96 (0.89-1.01) of what the "
              "CPUs allow over 2000 iterations and 0.95 (0.80-1.07) over 200, with 10 to 0.89 (0.75-0.97) and "
              "0.84 (0.77-0.93), with 20 to 0.88).\n")
        w(f"On {title}:\n")
        w("| algorithm | iterations | threads | median wall s | speedup | efficiency |")
        w("|---|---:|---:|---:|---:|---:|")
        for r in rows(path):
            w(f"| {r['algorithm']} | {r['iterations']} | {r['threads']} | {float(r['wall_median_s']):.3f} | "
              f"{r['speedup']} | {r['efficiency']} |")
        w("")
        cpus_path = os.path.join(d, "speedup-cpus.csv")
        if name == "speedup-summary.csv" and os.path.exists(cpus_path):
            speedup_against_cpus(w, rows(cpus_path))
    if os.path.exists(os.path.join(d, "plots-speedup", "speedup.svg")):
        w("![speedup](bench/plots-speedup/speedup.svg)\n")

    # The thesis.
    path = os.path.join(d, "thesis-tables.md")
    if os.path.exists(path):
        w("## The thesis's experiments 1-5 (tables 4.1-4.15)\n")
        w("`acobench --preset thesis`: the Ant System exactly as published (tau0 = m / C_nn, eta = 1/d, rho 0.5, "
          "every ant deposits 1/C_k, ants start at random holes, no local search), on the sample plates, 30 "
          "repetitions, median times. The thesis's own times (C#, Intel Core i7 930, 1-6 processors) beside ours.\n")
        w(open(path).read())
        w("![thesis speedup](bench/plots-thesis/speedup.svg)\n")

    # Other CAMs' drilling programs, reordered (issue 14).
    path = os.path.join(d, "programs.csv")
    if os.path.exists(path):
        runs = rows(path)
        w("## Other CAMs' drilling programs, reordered\n")
        w("pcb2gcode 2.5.0's own drill programs (its test boards, `tests/data/real-gcode/`; pcb2gcode orders each "
          "tool's holes by nearest neighbour and 2-opt under the Chebyshev distance), reordered by "
          "`acodrill plan PROGRAM -o OUT --threads 2 --seed K`; XY rapid travel of input and output as LinuxCNC's "
          "`rs274` runs them (`bench/rs274_travel.py`), median over seeds. Holes that overlap (closer than the "
          "drill) keep their input order, so boards whose holes are mostly drilled slots have little to gain.\n")
        w("| program | holes | overlapping | input mm | reordered mm (median) | saved % (median) | min..max % | wall s |")
        w("|---|---:|---:|---:|---:|---:|---|---:|")
        names = sorted({r["program"] for r in runs}, key=lambda n: (-int(next(r["holes"] for r in runs if r["program"] == n)), n))
        for n in names:
            rr = [r for r in runs if r["program"] == n]
            saved = [float(r["saved_pct"]) for r in rr]
            big = " **(>100 holes)**" if int(rr[0]["holes"]) > 100 else ""
            w(f"| {n}{big} | {rr[0]['holes']} | {rr[0]['overlapping']} | {float(rr[0]['input_mm']):.1f} | "
              f"{statistics.median(float(r['output_mm']) for r in rr):.1f} | {statistics.median(saved):.2f} | "
              f"{min(saved):.2f}..{max(saved):.2f} | {statistics.median(float(r['wall_s']) for r in rr):.2f} |")
        w("")

    # Microbenchmarks.
    for name, title in [("solver_bench.json", "Solver microbenchmarks"), ("io_bench.json", "Input and output microbenchmarks")]:
        path = os.path.join(d, name)
        if not os.path.exists(path):
            continue
        data = json.load(open(path))
        w(f"## {title}\n")
        w("Google Benchmark, each optimised routine beside its reference in the same binary; real time per call.\n")
        w("| benchmark | time | unit | throughput |")
        w("|---|---:|---|---:|")
        for b in data.get("benchmarks", []):
            if "real_time" not in b:  # complexity fits (BigO, RMS)
                if "big_o" in b:
                    w(f"| {b['name']} | fitted {b['big_o']} | | |")
                continue
            mbps = b.get("bytes_per_second")
            extra = f"{mbps / 1e6:.0f} MB/s" if mbps else ""
            if "MB" in b:
                extra += f" ({b['MB']:.1f} MB, {int(b.get('holes', 0))} holes)"
            w(f"| {b['name']} | {b['real_time']:.3g} | {b['time_unit']} | {extra} |")
        w("")
    print("\n".join(out))


if __name__ == "__main__":
    main()
