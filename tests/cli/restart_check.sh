# Sourced by the restart tests (not a test itself: no test_ prefix). Needs `bin` (the blockdem
# binary) and a `fail MESSAGE` function from the sourcing script.
#
# restart_matches LABEL SCENARIO DIR HALF_S: runs SCENARIO straight to its end into DIR/full on
# 1 thread, saving a state at HALF_S, then restarts from that state into DIR/restarted on 2
# threads; history.csv, energy.csv, summary.json and interfaces.csv must be byte-identical
# (docs/outputs.md, "State files"). The straight run stays in DIR/full for further checks.
restart_matches() {
  local label=$1 scenario=$2 dir=$3 half=$4
  "$bin" run "$scenario" --out "$dir/full" -q --threads 1 --save-state "$half" > /dev/null 2> "$dir/full.log" \
    || { fail "$label: full run: $(tail -2 "$dir/full.log")"; return; }
  local state; state=$(ls "$dir/full/state/"t_*.h5 2>/dev/null | head -1)
  [ -n "$state" ] || { fail "$label: no state file in $dir/full/state"; return; }
  "$bin" run --restart "$state" --out "$dir/restarted" -q --threads 2 > /dev/null 2> "$dir/restarted.log" \
    || { fail "$label: restart: $(tail -2 "$dir/restarted.log")"; return; }
  local f
  for f in history.csv energy.csv summary.json interfaces.csv; do
    cmp -s "$dir/full/$f" "$dir/restarted/$f" || fail "$label: $f differs between the straight run and the restarted one"
  done
}
