#!/usr/bin/env bash
# blockdem sweep gives the same table, row for row, serially, on 2 threads and on 2 MPI ranks
# (wall_time_s, the last column, aside). Bad-parameter cases are recorded with their error.
# Usage: test_sweep_parallel.sh <blockdem> <source-dir>
set -euo pipefail
blockdem=$(realpath "$1")
src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

sweep() {  # sweep <out> <launcher words> [sweep options...]
  local out=$1 launcher=$2; shift 2
  $launcher sweep "$src/studies/scenarios/pulse_block.toml" --out "$out" -q "$@" \
    --vary contact.mu=2,-1 \
    --vary table_motion.horizontal.amplitude=3,5,7 \
    --vary table_motion.horizontal.period=0.5,1 \
    --vary simulation.duration=2.5
}
without_wall_time() { sed 's/,[^,]*$//' "$1"; }

sweep "$work/serial" "$blockdem" --threads 1 > "$work/serial.log"
sweep "$work/threads" "$blockdem" --threads 2 > "$work/threads.log"
grep -q "12 cases, 12 done (6 failed or bad input)" "$work/serial.log" || { cat "$work/serial.log"; exit 1; }
[ "$(wc -l < "$work/serial/results.csv")" -eq 13 ]
# Ids in order; the six mu = -1 cases carry status "error" and the reason.
[ "$(cut -d, -f1 "$work/serial/results.csv" | tail -n +2 | tr '\n' ' ')" = "0 1 2 3 4 5 6 7 8 9 10 11 " ]
[ "$(tail -n +2 "$work/serial/results.csv" | grep -c ',error,')" -eq 6 ]
grep -q "mu" <(grep ',error,' "$work/serial/results.csv" | head -1)
grep -q ',overturned,' "$work/serial/results.csv"
diff <(without_wall_time "$work/serial/results.csv") <(without_wall_time "$work/threads/results.csv")
echo "serial and 2 threads: identical tables"

if ! command -v mpirun > /dev/null; then
  echo "SKIP mpirun: Open MPI is not installed (make deps installs openmpi-bin)"
  exit 0
fi
root_flag=""
if [ "$(id -u)" -eq 0 ]; then root_flag="--allow-run-as-root"; fi
if ! sweep "$work/mpi" "mpirun $root_flag --oversubscribe -n 2 $blockdem" > "$work/mpi.log" 2>&1; then
  if grep -q "built without MPI" "$work/mpi.log"; then echo "SKIP mpirun: blockdem built without MPI"; exit 0; fi
  cat "$work/mpi.log"; exit 1
fi
grep -q "on 2 ranks" "$work/mpi.log" || { cat "$work/mpi.log"; exit 1; }
diff <(without_wall_time "$work/serial/results.csv") <(without_wall_time "$work/mpi/results.csv")
echo "serial and mpirun -n 2: identical tables"
