#!/usr/bin/env bash
# `blockdem report` on a run folder whose files were damaged after the run (a summary.json that
# is not JSON, a history.csv cut in the middle of a row, overwritten with binary bytes or without
# its t column, a bodies.json of another shape, a 3-D run's summary.json that is not JSON) says
# which file and why, with exit status 2; it printed a Python traceback and exited 1.
# Usage: test_report_damaged.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/refusal_setup.sh" "$@"

sed 's/^duration = .*/duration = 0.05/' "$source_dir/examples/paper/rocking.toml" > "$work/rock.toml"
"$blockdem" run "$work/rock.toml" --out "$work/run" -q > /dev/null

damaged() {  # <name> <words>: a copy of the run with the damage made by the caller in $work/<name>
  local name=$1 words=$2
  set +e
  "$blockdem" report "$work/$name" > "$work/out.txt" 2> "$work/err.txt"
  local status=$?
  set -e
  [ $status -eq 2 ] || { cat "$work/err.txt"; fail "$name: exit status $status (expected 2)"; }
  grep -qF -- "$words" "$work/err.txt" || { cat "$work/err.txt"; fail "$name: message (expected: $words)"; }
  ! grep -q "Traceback" "$work/err.txt" || { cat "$work/err.txt"; fail "$name: a Python traceback"; }
}

cp -r "$work/run" "$work/summary_garbage" && echo garbage > "$work/summary_garbage/summary.json"
damaged summary_garbage "summary_garbage/summary.json: not a readable JSON file"
cp -r "$work/run" "$work/history_cut" && head -c 500 "$work/run/history.csv" > "$work/history_cut/history.csv"
damaged history_cut "history_cut/history.csv: not a CSV file of numbers under a header line"
cp -r "$work/run" "$work/history_binary" && head -c 2000 /dev/urandom > "$work/history_binary/history.csv"
damaged history_binary "history_binary/history.csv: not a CSV file of numbers under a header line"
cp -r "$work/run" "$work/history_no_t" && sed '1s/^t,/time,/' "$work/run/history.csv" > "$work/history_no_t/history.csv"
damaged history_no_t "history_no_t/history.csv: no column t"
cp -r "$work/run" "$work/bodies_shape" && echo '[1, 2]' > "$work/bodies_shape/bodies.json"
damaged bodies_shape "bodies_shape/bodies.json: no list of bodies"
# A 3-D run's damaged summary is named (it was taken for a 2-D folder lacking bodies.json).
"$blockdem" run "$source_dir/examples/3d/drum_column.toml" --out "$work/run3" -q --set simulation.duration=0.02 > /dev/null 2>&1
cp -r "$work/run3" "$work/summary3_garbage" && echo garbage > "$work/summary3_garbage/summary.json"
damaged summary3_garbage "summary3_garbage/summary.json: not a readable JSON file"
echo "damaged run folders: each refused with the file named"
