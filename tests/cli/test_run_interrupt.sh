#!/usr/bin/env bash
# SIGINT / SIGTERM during `blockdem run`: the run finishes its step, flushes every file, writes
# summary.json with status "interrupted" and the time reached, closes the .pvd, and exits 130 /
# 143; `blockdem report` works on the folder. The run is the rocking example stretched to 500 s
# (also the large-output warning: 25,000 VTK files).
# Usage: test_run_interrupt.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
last_time() { tail -n 1 "$1" | cut -d, -f1; }

for signal in INT TERM; do
  out=$tmp/$signal
  want=$([ $signal = INT ] && echo 130 || echo 143)
  "$bin" run "$src/examples/paper/rocking.toml" --out "$out" -q --set simulation.duration=500 \
    --set table_motion.horizontal.amplitude=0.1 > "$out.log" 2>&1 &
  pid=$!
  # Wait for some history (rows are flushed in batches) before the signal.
  for _ in $(seq 1 1200); do
    [ -f "$out/history.csv" ] && [ "$(wc -l < "$out/history.csv")" -ge 400 ] && break
    sleep 0.05
  done
  kill -s $signal $pid
  wait $pid; rc=$?
  [ $rc -eq $want ] || { fail "$signal: exit $rc, expected $want"; cat "$out.log"; }
  grep -q "warning: this run will write about .* in 25008 files" "$out.log" || fail "$signal: no large-output warning"
  grep -q "interrupted at t = .* of 500 s" "$out.log" || fail "$signal: no interruption message"
  [ -f "$out/summary.json" ] || { fail "$signal: no summary.json"; continue; }
  /usr/bin/python3 - "$out" "$(last_time "$out/history.csv")" "$(last_time "$out/energy.csv")" <<'PY' || fail "$signal: summary.json"
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
t_history, t_energy = float(sys.argv[2]), float(sys.argv[3])
assert s["status"] == "interrupted", s["status"]
assert 0 < s["time_s"] < 500 and s["end_time_s"] == 500, (s["time_s"], s["end_time_s"])
# the time reached is the last row of history.csv and energy.csv
assert abs(t_history - s["time_s"]) < 1e-8 and abs(t_energy - s["time_s"]) < 1e-8, (t_history, t_energy, s["time_s"])
PY
  awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad || NR < 400 }' "$out/history.csv" || fail "$signal: history.csv rows"
  tail -n 1 "$out/vtk/bodies.pvd" | grep -q '</VTKFile>' || fail "$signal: bodies.pvd not closed"
  for f in $(grep -o 'file="[^"]*"' "$out/vtk/bodies.pvd" | cut -d'"' -f2); do
    [ -f "$out/vtk/$f" ] || { fail "$signal: bodies.pvd lists a missing $f"; break; }
  done
done

# The report works on an interrupted folder and says so.
if "$bin" report "$tmp/INT" --no-animation > "$tmp/report.log" 2>&1; then
  grep -q "The run was interrupted" "$tmp/INT/report.html" || fail "report does not say the run was interrupted"
else
  fail "report on an interrupted run: $(tail -3 "$tmp/report.log")"
fi

[ $failures -eq 0 ] && echo "interrupted runs keep whole, readable results"
exit $failures
