#!/usr/bin/python3
"""How evenly the dynamic schedule shares each parallel loop of a step between two threads.

usage: run_balance.py TRACE OUT PROGRAM [GHZ]
  TRACE   the events gomp_run_trace.so wrote (GOMP_TRACE), from a run on ONE thread
  OUT     the program's output: 'start TSC' and 'end TSC' around the timed steps (step_wall_3d.cpp)
  PROGRAM the program (built with -no-pie), to name each loop by its outlined function
  GHZ     the time stamp counter's rate (default 2.6)

For each loop (a parallel region, by its outlined function): the runs it was cut into (the
partition most of the timed steps had), each run's least time over those steps (another job on
the host only adds time), their sum, and the makespan of handing those runs in order to two
threads as they free up (schedule(dynamic)), against half the sum: the share of two threads'
time a loop would lose to its last runs alone, with the memory and the host left out.
"""
import collections
import heapq
import subprocess
import sys

# Outlined functions named for the loop they hold (world/step_3d.cpp, broad_phase/skin_pair_list.cpp).
LOOPS = [('step_begin(blockdem::World3d&)::{lambda(long)#1}', 'pose'),
         ('step_begin(blockdem::World3d&)::{lambda(long, long)#1}', 'pose'),
         ('step_begin(blockdem::World3d&)::{lambda(long)#3}', 'kick'),
         ('step_begin(blockdem::World3d&)::{lambda(long, long)#3}', 'kick'),
         ('step_end', 'drift'),
         ('find_contacts(blockdem::World3d&)::{lambda(long)#2}', 'narrow phase'),
         ('find_contacts(blockdem::World3d&)::{lambda(long)#3}', 'table fill'),
         ('lay_out_table(blockdem::WorldScratch3d&)::{lambda(unsigned long)#2}', 'layout: count'),
         ('lay_out_table(blockdem::WorldScratch3d&)::{lambda(unsigned long)#3}', 'layout: write'),
         ('apply_contact_law(blockdem::World3d&, blockdem::Vec3)::{lambda(long)#1}', 'law'),
         ('apply_contact_law(blockdem::World3d&, blockdem::Vec3)::{lambda(long)#2}', 'gather'),
         ('must_rebuild', 'skin: check'),
         ('filter_compacted', 'skin: filter')]


def loop_names(program):
    names = {}
    nm = subprocess.run(['nm', '-C', program], capture_output=True, text=True, check=True).stdout
    for line in nm.splitlines():
        parts = line.split(' ', 2)
        if len(parts) == 3 and '_omp_fn' in parts[2]:
            label = next((short for key, short in LOOPS if key in parts[2]), parts[2][-40:])
            names[hex(int(parts[0], 16))] = label + ('' if not label.startswith('skin: filter') else
                                                     ' ' + parts[2][parts[2].find('_omp_fn'):][:9])
    return names


def main():
    trace, out, program = sys.argv[1:4]
    ghz = float(sys.argv[4]) if len(sys.argv) > 4 else 2.6
    words = open(out).read().split()
    t0, t1 = int(words[words.index('start') + 1]), int(words[words.index('end') + 1])
    events = []
    for line in open(trace):
        t, fn, kind, thread, begin, _ = line.split()
        if t0 <= int(t) <= t1:
            events.append((int(t), fn, int(kind), int(thread), int(begin)))
    events.sort()
    # Each region's runs: from a thread's handout (kind 1) to its next event.
    regions = collections.defaultdict(list)
    current, last = None, {}
    for t, fn, kind, thread, begin in events:
        if kind == 0:
            current, last = {'fn': fn, 'runs': {}}, {}
        elif kind == 9:
            regions[current['fn']].append(current['runs'])
            current = None
        elif current is not None:
            if thread in last:
                handed, first = last.pop(thread)
                current['runs'][first] = t - handed
            if kind == 1:
                last[thread] = (t, begin)
    names = loop_names(program)
    us = lambda ticks: ticks / ghz / 1e3
    print(f'{"loop":>16} {"steps":>5} {"runs":>4} {"sum of runs us":>14} {"longest/mean":>12} {"2 threads us":>12} {"half us":>8} {"loss %":>6}')
    total_work = total_span = 0
    for fn, occurrences in sorted(regions.items(), key=lambda kv: -sum(sum(r.values()) for r in kv[1])):
        by_partition = collections.defaultdict(list)
        for runs in occurrences:
            by_partition[tuple(sorted(runs))].append(runs)
        starts, same = max(by_partition.items(), key=lambda kv: len(kv[1]))
        cost = [min(runs[s] for runs in same) for s in starts]
        work = sum(cost)
        threads = [0, 0]
        for c in cost:
            heapq.heappush(threads, heapq.heappop(threads) + c)
        span = max(threads)
        total_work += work
        total_span += span
        print(f'{names.get(fn, fn):>16} {len(same):>5} {len(cost):>4} {us(work):14.1f} {max(cost) / (work / len(cost)):12.2f} '
              f'{us(span):12.1f} {us(work / 2):8.1f} {100 * (span / (work / 2) - 1):6.1f}')
    print(f'a step: runs {us(total_work):.1f} us on one thread, {us(total_span):.1f} us on two as scheduled, '
          f'{us(total_work / 2):.1f} us evenly shared: {100 * (total_span / (total_work / 2) - 1):.1f} % lost to the last runs')


if __name__ == '__main__':
    main()
