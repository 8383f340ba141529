#!/usr/bin/env bash
# An interrupted sweep (Ctrl-C, SIGTERM, then kill -9) rerun with the same command does only the
# missing cases and ends with the same table as an uninterrupted one; after Ctrl-C / SIGTERM it
# exits 130 / 143, sweep.json says "interrupted", and only resumable state is left (no temporary
# file, no history of an unfinished case). A different plan in the same folder is refused.
# Usage: test_sweep_resume.sh <blockdem> <source-dir>
set -euo pipefail
blockdem=$(realpath "$1")
src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

args=(sweep "$src/studies/scenarios/pulse_block.toml" -q --threads 1
      --vary table_motion.horizontal.amplitude=3,4,5,6,7,8 --vary table_motion.horizontal.period=0.5,1
      --vary simulation.duration=3 --histories)
without_wall_time() { sed 's/,[^,]*$//' "$1"; }
rows() { echo $(( $(wc -l < "$1") - 1 )); }
# Starts the sweep, waits for at least 2 finished cases, sends the signal, waits for the end.
interrupt_after_two() {  # <out> <signal>
  "$blockdem" "${args[@]}" --out "$1" > "$1.log" 2>&1 &
  local pid=$!
  for _ in $(seq 1 600); do
    if [ -f "$1/finished_cases.csv" ] && [ "$(rows "$1/finished_cases.csv")" -ge 2 ]; then break; fi
    sleep 0.05
  done
  kill -s "$2" "$pid"
  status=0
  wait "$pid" || status=$?
}

"$blockdem" "${args[@]}" --out "$work/whole" > /dev/null
[ "$(rows "$work/whole/results.csv")" -eq 12 ]

for signal in INT TERM KILL; do
  out="$work/cut-$signal"
  interrupt_after_two "$out" "$signal"
  done_before=$(rows "$out/finished_cases.csv")
  echo "$signal: $done_before of 12 cases finished before the interruption"
  [ "$done_before" -ge 2 ] && [ "$done_before" -lt 12 ]
  if [ "$signal" != KILL ]; then
    [ "$status" -eq "$([ "$signal" = INT ] && echo 130 || echo 143)" ] || { echo "$signal: exit $status"; exit 1; }
    grep -q "interrupted with" "$out.log" || { cat "$out.log"; exit 1; }
    grep -q '"status": "interrupted"' "$out/sweep.json"
    ! ls "$out" | grep -q '\.tmp$' || { echo "$signal: a temporary file was left: $(ls "$out")"; exit 1; }
    # A history only for each finished case (the case ids of finished_cases.csv).
    diff <(ls "$out/cases" | sort -n) <(tail -n +2 "$out/finished_cases.csv" | cut -d, -f1 | sort -n) \
      || { echo "$signal: histories of unfinished cases were left"; exit 1; }
  fi
  # As if killed inside an atomic replace: the rerun removes the temporaries.
  [ "$signal" = KILL ] && echo "torn" > "$out/results.csv.tmp" && echo "torn" > "$out/sweep.json.tmp"
  "$blockdem" "${args[@]}" --out "$out" > "$out.rerun.log"
  ! ls "$out" | grep -q '\.tmp$' || { echo "$signal: the rerun left a temporary file: $(ls "$out")"; exit 1; }
  grep -q "12 done (0 failed or bad input), $((12 - done_before)) run now" "$out.rerun.log" || { cat "$out.rerun.log"; exit 1; }
  diff <(without_wall_time "$work/whole/results.csv") <(without_wall_time "$out/results.csv")
  grep -q '"status": "complete"' "$out/sweep.json"
done

# A finished sweep rerun does nothing; another plan in the same folder is refused.
"$blockdem" "${args[@]}" --out "$work/whole" | grep -q "0 run now"
if "$blockdem" "${args[@]}" --vary contact.mu=1 --out "$work/whole" > "$work/other.log" 2>&1; then
  echo "a different plan was accepted in a used folder"; exit 1
fi
grep -q "holds a different sweep" "$work/other.log"
echo "interrupted sweeps resume to the same table"
