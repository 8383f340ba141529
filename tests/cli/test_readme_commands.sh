#!/usr/bin/env bash
# Every command of the README's shell code blocks, run as written (in a scratch copy of the
# layout the README assumes: build/blockdem, examples/, studies/, ../shared/), and the README's
# scenario file checked with `blockdem check`. A command that fails fails the test.
#
# Made short, not skipped: `blockdem run` and `blockdem converge` get
# `--set simulation.duration=$README_TEST_DURATION` (default 1 s; docs/scenario.md: any key can be
# overridden), so that the report of the run and the converge study take seconds, not minutes.
# Skipped, and said so: `make demo` and `make test` (they install packages and build and test
# the whole project: the lead runs them from a clean clone), and the commands that read
# ../shared/data when that folder is absent.
#   bash tests/cli/test_readme_commands.sh BLOCKDEM SOURCE_DIR
set -uo pipefail
blockdem=$(realpath "$1") source_dir=$(realpath "$2")
duration=${README_TEST_DURATION:-1}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
failures=0 ran=0

# The README's layout: the repository with build/blockdem, and ../shared beside it.
mkdir -p "$work/repo/build"
ln -s "$blockdem" "$work/repo/build/blockdem"
for entry in examples studies tools; do ln -s "$source_dir/$entry" "$work/repo/$entry"; done
[ -d "$source_dir/../shared" ] && ln -s "$(realpath "$source_dir/../shared")" "$work/shared"

# The shell code blocks (``` with no language, sh or bash), continuation lines joined and end-of-
# line comments dropped: one command a line.
commands=$(awk '
  /^```/ { if (block) block = 0; else block = ($0 ~ /^```(sh|bash)?[ \t]*$/) ? 1 : 2; next }
  block == 1 {
    line = $0
    if (pending != "") { sub(/^[ \t]+/, "", line); line = pending " " line; pending = "" }
    if (line ~ /\\[ \t]*$/) { sub(/\\[ \t]*$/, "", line); pending = line; next }
    sub(/[ \t]+#.*$/, "", line)
    if (line ~ /[^ \t]/) print line
  }' "$source_dir/README.md")
[ -n "$commands" ] || { echo "FAIL: no shell commands found in README.md"; exit 1; }

while IFS= read -r command; do
  case "$command" in
    "make demo"* | "make test"*)
      echo "SKIP ($command): installs packages, builds and tests the whole project (run from a clean clone)"
      continue ;;
  esac
  if [[ "$command" == *"../shared/"* || "$command" == *elcentro* ]] && [ ! -d "$work/shared" ]; then
    echo "SKIP ($command): ../shared/data is not present"
    continue
  fi
  short=$command
  if [[ "$command" =~ build/blockdem\ (run|converge)\  ]]; then
    short="$command --set simulation.duration=$duration"
  fi
  echo "RUN  $short"
  # (stdin closed: mpirun would otherwise read the rest of the command list)
  if ! (cd "$work/repo" && bash -c "$short") < /dev/null > "$work/log" 2>&1; then
    echo "FAIL: $short"; tail -20 "$work/log"; failures=$((failures + 1))
  fi
  ran=$((ran + 1))
done <<< "$commands"

# What the README says the commands give.
cd "$work/repo"
if [ -f out/sweep/results.csv ]; then
  # The sweep's cells differ: at least three outcomes among the 8 cases.
  outcomes=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "block.outcome") c = i; next } { print $c }' \
             out/sweep/results.csv | sort -u | tr '\n' ' ')
  [ "$(wc -w <<< "$outcomes")" -ge 3 ] || { echo "FAIL: the sweep's cases should differ, outcomes: $outcomes"; failures=$((failures + 1)); }
  echo "sweep outcomes: $outcomes"
  if [ -f out/sweep-mpi/results.csv ]; then
    cut -d, -f1-17 out/sweep/results.csv > "$work/serial.csv"; cut -d, -f1-17 out/sweep-mpi/results.csv > "$work/mpi.csv"
    cmp -s "$work/serial.csv" "$work/mpi.csv" || { echo "FAIL: mpirun's table differs from the serial one"; failures=$((failures + 1)); }
  fi
fi
[ -f out/sliding/report.html ] || { echo "FAIL: no report.html for out/sliding"; failures=$((failures + 1)); }

# The README's scenario file, as shown, is a valid scenario.
awk '/^```toml/ { inside = 1; next } /^```/ { inside = 0 } inside' "$source_dir/README.md" > "$work/readme.toml"
if ! "$blockdem" check "$work/readme.toml" > "$work/log" 2>&1; then
  echo "FAIL: the README's scenario file"; cat "$work/log"; failures=$((failures + 1))
fi

echo "$ran README commands run, $failures failures"
[ $failures -eq 0 ]
