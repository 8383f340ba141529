#!/usr/bin/env bash
# `blockdem run` when something goes wrong around the physics, and the exit codes of
# docs/outputs.md: a write that fails (file-size limit), an --out folder that holds another run
# (--force) or a run still in progress (refused even with --force), a run that would not fit the machine (duration 1e300, memory, disk), a failed
# settle, a stop while settling, a bad command line, an internal error.
# Usage: test_run_faults.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
complete_rows() { awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad || NR < 2 }' "$1"; }
sliding=$src/examples/paper/sliding.toml

# 1. A file-size limit (ulimit -f, 60 kB): history.csv cannot grow past it. The run stops with
#    exit 4 naming the file and the OS reason; history.csv keeps whole rows only, summary.json
#    says failed. blockdem ignores SIGXFSZ itself, so that write() returns EFBIG (the shell
#    here does not ignore it: without that, the kernel would kill the run with no message).
msg=$( (ulimit -f 60; "$bin" run "$sliding" --out "$tmp/full" -q --set simulation.duration=2) 2>&1); rc=$?
[ $rc -eq 4 ] || fail "file-size limit: exit $rc, expected 4 ($msg)"
expect_in "$msg" "could not write the output: $tmp/full/history.csv: cannot write: File too large"
complete_rows "$tmp/full/history.csv" || fail "history.csv after a failed write is not whole rows"
size=$(stat -c %s "$tmp/full/history.csv")
[ "$size" -gt 30000 ] && [ "$size" -le 61440 ] || fail "history.csv is $size bytes (limit 61440)"
grep -q '"status": "failed"' "$tmp/full/summary.json" || fail "summary.json status after a failed write"
grep -q 'File too large' "$tmp/full/summary.json" || fail "summary.json error after a failed write"

# 2. --out that holds another run: refused (exit 2) unless --force, which removes blockdem's
#    files (the stale VTK frames too) and keeps the user's own.
"$bin" run "$sliding" --out "$tmp/reuse" -q --set simulation.duration=0.4 > /dev/null || fail "first run"
frames_before=$(ls "$tmp/reuse/vtk" | grep -c '^bodies_.*vtp$')
echo "notes" > "$tmp/reuse/my_notes.txt"
echo "mine" > "$tmp/reuse/vtk/my_view.pvsm"
msg=$("$bin" run "$sliding" --out "$tmp/reuse" -q --set simulation.duration=0.2 2>&1); rc=$?
[ $rc -eq 2 ] || fail "reused --out: exit $rc, expected 2"
expect_in "$msg" "the folder holds an earlier run (scenario.toml, history.csv"
expect_in "$msg" "use --force to replace it"
grep -q "duration = 0.4" "$tmp/reuse/scenario.toml" || fail "a refused run must leave the earlier run alone"
"$bin" run "$sliding" --out "$tmp/reuse" -q --force --set simulation.duration=0.2 > /dev/null || fail "--force run"
frames_after=$(ls "$tmp/reuse/vtk" | grep -c '^bodies_.*vtp$')
[ "$frames_after" -lt "$frames_before" ] || fail "--force kept stale VTK frames ($frames_before before, $frames_after after)"
[ "$frames_after" -eq "$(grep -c '<DataSet' "$tmp/reuse/vtk/bodies.pvd")" ] || fail "frames and bodies.pvd disagree after --force"
[ -f "$tmp/reuse/my_notes.txt" ] && [ -f "$tmp/reuse/vtk/my_view.pvsm" ] || fail "--force removed a file blockdem did not write"
grep -q "duration = 0.2" "$tmp/reuse/scenario.toml" || fail "--force run did not replace scenario.toml"
#    A sweep is refused in a run folder, and a run in a sweep folder (exit 2).
msg=$("$bin" sweep "$sliding" -q --vary contact.mu=0.3,0.4 --vary simulation.duration=0.05 --out "$tmp/reuse" 2>&1); rc=$?
[ $rc -eq 2 ] || fail "sweep into a run folder: exit $rc, expected 2"
expect_in "$msg" "the folder holds a run of \`blockdem run\`"
"$bin" sweep "$sliding" -q --vary contact.mu=0.3,0.4 --vary simulation.duration=0.05 --out "$tmp/sweep" > /dev/null || fail "sweep"
msg=$("$bin" run "$sliding" --out "$tmp/sweep" -q --force 2>&1); rc=$?
[ $rc -eq 2 ] || fail "run into a sweep folder: exit $rc, expected 2"
expect_in "$msg" "the folder holds a sweep (sweep.json)"
#    A folder a run is still writing in: refused even with --force (exit 2), naming the folder
#    and the live run's pid, its files left alone; so is a restart in place from its state and a
#    second sweep into a live sweep's folder. Killed (SIGKILL: no chance to clean up), the run
#    holds nothing: the next --force run takes the folder, and removes run.lock at its end.
"$bin" run "$sliding" --out "$tmp/live" -q --set simulation.duration=300 --set output.vtk=false --save-state 0 \
  > /dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do [ -n "$(ls "$tmp/live/state" 2>/dev/null)" ] && break; sleep 0.05; done
msg=$("$bin" run "$sliding" --out "$tmp/live" -q --force --set simulation.duration=0.05 2>&1); rc=$?
[ $rc -eq 2 ] || fail "--force into a live run's folder: exit $rc, expected 2 ($msg)"
expect_in "$msg" "$tmp/live: the run of pid $pid is writing in this folder (run.lock is locked)"
grep -q "duration = 300" "$tmp/live/scenario.toml" || fail "a refused run touched the live run's scenario.toml"
msg=$("$bin" run --restart "$tmp/live/state/t_0.000000s.h5" -q 2>&1); rc=$?
[ $rc -eq 2 ] || fail "restart in place into a live run's folder: exit $rc, expected 2 ($msg)"
expect_in "$msg" "the run of pid $pid is writing in this folder"
kill -KILL $pid; wait $pid 2>/dev/null
[ -f "$tmp/live/run.lock" ] || fail "no run.lock in the folder of a live run"
"$bin" run "$sliding" --out "$tmp/live" -q --force --set simulation.duration=0.05 > /dev/null 2>&1 \
  || fail "the folder of a killed run stayed locked"
[ ! -e "$tmp/live/run.lock" ] || fail "run.lock left behind by a finished run"
live_sweep=("$sliding" -q --vary contact.mu=0.3,0.4 --vary simulation.duration=300 --threads 1 --out "$tmp/live_sweep")
"$bin" sweep "${live_sweep[@]}" > /dev/null 2>&1 &
pid=$!
for _ in $(seq 200); do [ -f "$tmp/live_sweep/sweep.json" ] && break; sleep 0.05; done
msg=$("$bin" sweep "${live_sweep[@]}" 2>&1); rc=$?
[ $rc -eq 2 ] || fail "a second sweep into a live sweep's folder: exit $rc, expected 2 ($msg)"
expect_in "$msg" "the run of pid $pid is writing in this folder"
kill -KILL $pid; wait $pid 2>/dev/null
#    A folder with no run: other files are fine, a file with one of blockdem's names is not
#    (not even with --force: it is not blockdem's to remove).
mkdir "$tmp/mine" && echo "data" > "$tmp/mine/readme.txt"
"$bin" run "$sliding" --out "$tmp/mine" -q --set simulation.duration=0.1 > /dev/null || fail "a folder of other files was refused"
mkdir "$tmp/own" && cp "$sliding" "$tmp/own/scenario.toml"
msg=$("$bin" run "$tmp/own/scenario.toml" --out "$tmp/own" -q --force --set simulation.duration=0.1 2>&1); rc=$?
[ $rc -eq 2 ] || fail "foreign scenario.toml: exit $rc, expected 2"
expect_in "$msg" "the folder holds scenario.toml, not written by blockdem run"
cmp -s "$sliding" "$tmp/own/scenario.toml" || fail "the user's scenario.toml was overwritten"

# 3. A run that would not fit the machine: refused before anything is written (exit 2), with
#    the figure and the key. (The timeout stops a blockdem that would start such a run.)
msg=$(timeout 10 "$bin" run "$sliding" --out "$tmp/huge" -q --set simulation.duration=1e300 2>&1); rc=$?
[ $rc -eq 2 ] || fail "duration 1e300: exit $rc, expected 2"
expect_in "$msg" "key 'simulation.duration': 1e+300 s is 1e+304 steps of dt = 0.0001 s, more than a run can count"
msg=$(timeout 10 "$bin" run "$sliding" --out "$tmp/huge" -q --set simulation.duration=1e9 2>&1); rc=$?
[ $rc -eq 2 ] || fail "duration 1e9: exit $rc, expected 2"
expect_in "$msg" "key 'simulation.duration': the run would write about"
expect_in "$msg" "(1e+12 rows)"
expect_in "$msg" "free where $tmp/huge is"
msg=$(timeout 10 "$bin" run "$sliding" --out "$tmp/huge" -q --set simulation.duration=1e5 --set output.vtk=true --set output.vtk_interval=1e-8 2>&1); rc=$?
[ $rc -eq 2 ] || fail "1e13 VTK frames: exit $rc, expected 2"
expect_in "$msg" "key 'output.vtk_interval': the run would need about"
expect_in "$msg" "of memory (1e+13 VTK frames)"
[ ! -e "$tmp/huge" ] || fail "a refused run must not create its output folder"

# 4. The other exit codes. 3: an assembly that does not settle (the run started: 3, not 2).
msg=$("$bin" run "$src/examples/assemblies/rock_slope.toml" --out "$tmp/unsettled" -q --set settling.window=0.0005 --set settling.max_time=0.001 2>&1); rc=$?
[ $rc -eq 3 ] || fail "unsettled assembly: exit $rc, expected 3"
expect_in "$msg" "the assembly did not settle within 0.001 s"
#    130 and 143: Ctrl-C (SIGINT) or SIGTERM while the model settles (a window far longer than the run
#    allows, so it would settle for hours): it stops at once, says nothing was written, and leaves
#    no output folder behind.
for sig in INT:130 TERM:143; do
    code=${sig#*:}; sig=${sig%:*}
    "$bin" run "$src/examples/assemblies/rock_slope.toml" --out "$tmp/stopped_$sig" -q \
        --set settling.window=1000 --set settling.max_time=10000 >"$tmp/log" 2>&1 &
    pid=$!
    sleep 2
    kill -$sig $pid
    for _ in $(seq 50); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
    kill -0 $pid 2>/dev/null && { fail "SIG$sig while settling: still running 5 s later"; kill -KILL $pid; }
    wait $pid; rc=$?
    [ $rc -eq "$code" ] || fail "SIG$sig while settling: exit $rc ($(cat "$tmp/log"))"
    expect_in "$(cat "$tmp/log")" "stopped while the model settled"
    expect_in "$(cat "$tmp/log")" "nothing was written"
    [ ! -e "$tmp/stopped_$sig" ] || fail "a run stopped while settling left its output folder"
done
#    2: a bad command line (CLI11's own codes are 100+).
msg=$("$bin" run "$sliding" --out "$tmp/x" --no-such-option 2>&1); rc=$?
[ $rc -eq 2 ] || fail "unknown option: exit $rc, expected 2"
expect_in "$msg" "--no-such-option"
msg=$("$bin" run "$sliding" --out "$tmp/x" --threads 0 2>&1); rc=$?
[ $rc -eq 2 ] || fail "--threads 0: exit $rc, expected 2"
#    1: an internal error (here a broken installation: the report's tools are missing).
msg=$(BLOCKDEM_TOOLS_DIR="$tmp/no-tools" "$bin" report "$tmp/mine" 2>&1); rc=$?
[ $rc -eq 1 ] || fail "missing tools: exit $rc, expected 1"
expect_in "$msg" "blockdem_report.py not found"
#    0: --help.
"$bin" run --help > /dev/null || fail "--help: exit $?"

[ $failures -eq 0 ] && echo "all run fault checks passed"
exit $failures
