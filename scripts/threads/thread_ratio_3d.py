#!/usr/bin/python3
"""The S3D wall's 1e4 bricks on one thread and on two, by the wall clock, alternated, with the ticks the
host stole from this VM during each run, and the machine's own two-core figure for the same work:
two copies of the wall, each stepped by its own thread (BM_BrickWall3dCopies), nothing shared.

usage: MIN_TIME=1 [PROBE=core_probe] thread_ratio_3d.py ROUNDS BENCH [BENCH ...]
  each round runs every BENCH (a blockdem_bench) at 1 then 2 threads:
  OMP_NUM_THREADS=t BENCH --benchmark_filter=BrickWall3d/10000/t/ --benchmark_min_time=MIN_TIME
  (MIN_TIME is ignored by a benchmark that fixes its steps, as BrickWall3d does since the thirteenth
  session: one thread and two then time the same steps)
Two threads over the copies is the step's own parallel loss; the copies over one thread is what the
host gives two cores on this work at that moment (the most two threads of one wall could get).
Steal is the 8th number of /proc/stat's cpu lines, read before and after each run; the summary
gives the best-over-best ratio and the ratios of the rounds in which neither run saw any.
With PROBE (scripts/threads/core_probe.c, built), each round first prints what two threads of pure
arithmetic and of a memory stream get over one at that moment: the host's share of the two vCPUs,
which steal ticks do not show.
"""
import json, os, subprocess, sys

def steal():
    out = {}
    with open('/proc/stat') as f:
        for line in f:
            if line.startswith('cpu'):
                parts = line.split()
                out[parts[0]] = int(parts[8])
    return out

def run(bench, threads, min_time):
    env = dict(os.environ, OMP_NUM_THREADS='1' if threads == 'copies' else str(threads))
    before = steal()
    load = os.getloadavg()[0]
    name = 'BrickWall3dCopies/10000/' if threads == 'copies' else f'BrickWall3d/10000/{threads}/'
    out = subprocess.run([bench, f'--benchmark_filter={name}', f'--benchmark_min_time={min_time}',
                          '--benchmark_format=json'], env=env, capture_output=True, text=True, check=True).stdout
    after = steal()
    b = json.loads(out)['benchmarks'][0]
    ticks = {k: after[k] - before[k] for k in after}
    return b['box-steps/s'], b['real_time'], ticks, load

rounds = int(sys.argv[1])
min_time = float(os.environ.get('MIN_TIME', '1'))
benches = sys.argv[2:]
rows = {bch: [] for bch in benches}
probe = os.environ.get('PROBE')
for r in range(rounds):
    if probe:
        print(f'round {r} probe: ' + subprocess.run([probe], capture_output=True, text=True, check=True).stdout.strip(),
              flush=True)
    for bch in benches:
        one = run(bch, 1, min_time)
        two = run(bch, 2, min_time)
        copies = run(bch, 'copies', min_time)
        ratio = two[0] / one[0]
        rows[bch].append((one, two, ratio, copies[0]))
        print(f'round {r} {bch}: 1t {one[0]:.3e} (steal {one[2]["cpu"]}, load {one[3]:.2f})  '
              f'2t {two[0]:.3e} (steal {two[2]["cpu"]}: cpu0 {two[2]["cpu0"]} cpu1 {two[2]["cpu1"]}, load {two[3]:.2f})  ratio {ratio:.3f}  '
              f'copies {copies[0]:.3e} ({copies[0] / one[0]:.3f} x 1t; 2t {two[0] / copies[0]:.3f} of it)',
              flush=True)
for bch, rs in rows.items():
    clean = [x for x in rs if x[0][2]['cpu'] == 0 and x[1][2]['cpu'] == 0]
    best1 = max(x[0][0] for x in rs)
    best2 = max(x[1][0] for x in rs)
    print(f'{bch}: best 1t {best1:.3e}, best 2t {best2:.3e}, best over best {best2 / best1:.3f}; '
          f'ratios {", ".join(f"{x[2]:.3f}" for x in rs)}; runs without steal: {len(clean)} of {len(rs)}'
          + (f', their ratios {", ".join(f"{x[2]:.3f}" for x in clean)}' if clean else ''))
    mid = lambda v: sorted(v)[len(v) // 2]
    print(f'{bch}: medians: 2t over 1t {mid([x[2] for x in rs]):.3f}, copies over 1t {mid([x[3] / x[0][0] for x in rs]):.3f}, '
          f'2t over copies {mid([x[1][0] / x[3] for x in rs]):.3f}')
