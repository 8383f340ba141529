#!/usr/bin/env bash
# `blockdem report` on a run folder whose files were damaged after the run (a summary.json that
# is not JSON, a history.csv cut in the middle of a row or overwritten with binary bytes) says
# which file and why, with exit status 2; it printed a Python traceback and exited 1.
# Usage: test_report_damaged.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

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
echo "damaged run folders: each refused with the file named"
