#!/usr/bin/env bash
# Sweep throughput: cases per second for a 1-block sweep (40 equal cases: the pulse block, 1 s
# of a one-sine pulse too weak to rock it, 50 000 steps each), on 1 and 2 threads and on 1 and
# 2 MPI ranks, and the parallel efficiency rate(2) / (2 rate(1)). Never asserted: figures
# depend on the machine and its load (report them with both).
# Usage: studies/bench_sweep.sh [blockdem] [cases]
set -euo pipefail
blockdem=$(realpath "${1:-build/blockdem}")
cases=${2:-40}
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
amplitudes=$(seq -s, 1 $cases | sed 's/[0-9]\+/0.0&/g')  # 0.01 .. m/s^2: no rocking, equal cost

rate() {  # rate <name> <launcher words...>: prints cases/s from the sweep's own summary line
  local name=$1; shift
  "$@" sweep "$src/studies/scenarios/pulse_block.toml" --out "$work/$name" -q \
    --vary simulation.duration=1 --vary "table_motion.horizontal.amplitude=$amplitudes" "${extra[@]}" \
    | sed -n 's/.* in \([0-9.]*\) s (\([0-9.]*\) cases\/s).*/\2/p'
}
extra=(--threads 1); r1=$(rate t1 "$blockdem")
extra=(--threads 2); r2=$(rate t2 "$blockdem")
echo "threads: 1 -> $r1 cases/s, 2 -> $r2 cases/s, efficiency $(echo "$r2 / (2 * $r1)" | bc -l | cut -c1-5)"
if command -v mpirun > /dev/null; then
  root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
  extra=(); m1=$(rate m1 mpirun $root --oversubscribe -n 1 "$blockdem")
  m2=$(rate m2 mpirun $root --oversubscribe -n 2 "$blockdem")
  echo "MPI ranks: 1 -> $m1 cases/s, 2 -> $m2 cases/s, efficiency $(echo "$m2 / (2 * $m1)" | bc -l | cut -c1-5)"
fi
echo "($cases cases of 50 000 steps; $(nproc) cores; load average $(cut -d' ' -f1-3 /proc/loadavg))"
