#!/usr/bin/env bash
# State files of a 3-D run (docs/3d.md, "The run"): a run of 0 to T and a run saved at T/2 and
# restarted from its state file to T write byte-identical history.csv, energy.csv and
# summary.json (the drum column example under its three-component record, and a brick wall on 2
# threads; a state of --save-state-every too); a run interrupted by SIGINT resumes in place from
# the state it wrote as it stopped and ends as a run straight to the same time; a 3-D state
# given a 2-D scenario, a state of another scenario and a 2-D state given to a 3-D scenario are
# refused with exit 2, naming the file, and so is a state whose deepest-overlap pair names no
# body; a state without the deepest overlap (saved before it was kept) restarts; a restart under
# bodies of another mass or shape is refused naming the body; a copied run folder goes on in
# itself (or is refused naming its missing scenario.toml), never in the folder the state names;
# --save-state-every below dt is refused, and files of a DT that is no whole number of steps are
# named by the times they hold.
# Usage: test_restart_3d.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
# A restart refused with exit 2: refused WHAT RESTART_ARGUMENTS... -- EXPECTED_TEXT...
refused() {
  local what=$1 args=() out status; shift
  while [[ $1 != -- ]]; do args+=("$1"); shift; done; shift
  out=$("$bin" run --restart "${args[@]}" -q 2>&1); status=$?
  [[ $status -eq 2 ]] || fail "$what: exit status $status, expected 2: $out"
  for text in "$@"; do expect_in "$out" "$text"; done
}
export OMP_WAIT_POLICY=passive

same_results() {  # LABEL DIR1 DIR2
  for f in history.csv energy.csv summary.json; do
    cmp -s "$2/$f" "$3/$f" || fail "$1: $f differs between $2 and $3"
  done
}

# 1. The drum column, 0.2 s, whole and cut at 0.1 s (--save-state) and at 0.15 s (--save-state-every
# 0.075), each time into a new folder.
drums="$src/examples/3d/drum_column.toml"
"$bin" run "$drums" --out "$tmp/whole" --set simulation.duration=0.2 -q --threads 1 >"$tmp/log" 2>&1 \
  || fail "the whole drum run failed: $(cat "$tmp/log")"
"$bin" run "$drums" --out "$tmp/first" --set simulation.duration=0.2 --save-state 0.1 --save-state-every 0.075 -q \
  --threads 1 >"$tmp/log" 2>&1 || fail "the saving drum run failed: $(cat "$tmp/log")"
for t in 0.075000 0.100000 0.150000; do
  [[ -s "$tmp/first/state/t_${t}s.h5" ]] || fail "no state file at $t s: $(ls "$tmp/first" "$tmp/first/state" 2>&1)"
done
"$bin" run --restart "$tmp/first/state/t_0.150000s.h5" --out "$tmp/third" -q --threads 1 >"$tmp/log" 2>&1 \
  || fail "the drum run restarted at 0.15 s failed: $(cat "$tmp/log")"
same_results "drums restarted at 0.15 s (--save-state-every)" "$tmp/whole" "$tmp/third"
"$bin" run --restart "$tmp/first/state/t_0.100000s.h5" --out "$tmp/second" -q --threads 1 >"$tmp/log" 2>&1 \
  || fail "the restarted drum run failed: $(cat "$tmp/log")"
same_results "drums restarted at 0.1 s" "$tmp/whole" "$tmp/second"
/usr/bin/python3 - "$tmp/second" "$tmp/whole" <<'PY' || fail "the restarted run's folder is not complete"
import json, sys
second, whole = sys.argv[1], sys.argv[2]
info = json.load(open(f"{second}/run_info.json"))
assert info["status"] == "completed" and abs(info["started_at_time_s"] - 0.1) < 1e-9, info
assert info["restarted_from"].endswith("t_0.100000s.h5"), info
# The VTK frames before the state were taken along, the rest written again: the same list.
assert open(f"{second}/vtk/bodies.pvd").read() == open(f"{whole}/vtk/bodies.pvd").read()
PY

# 2. The brick wall on 2 threads (its contact loops run in parallel), cut at 0.02 s of 0.04 s.
wall="$src/examples/3d/brick_wall.toml"
"$bin" run "$wall" --out "$tmp/wall_whole" --set simulation.duration=0.04 -q --threads 2 >"$tmp/log" 2>&1 \
  || fail "the whole wall run failed: $(cat "$tmp/log")"
"$bin" run "$wall" --out "$tmp/wall_first" --set simulation.duration=0.04 --save-state 0.02 -q --threads 2 >"$tmp/log" 2>&1 \
  || fail "the saving wall run failed: $(cat "$tmp/log")"
"$bin" run --restart "$tmp/wall_first/state/t_0.020000s.h5" --out "$tmp/wall_second" -q --threads 2 >"$tmp/log" 2>&1 \
  || fail "the restarted wall run failed: $(cat "$tmp/log")"
same_results "wall restarted at 0.02 s" "$tmp/wall_whole" "$tmp/wall_second"

# 3. Ctrl-C in the middle of a long wall run, then --restart in the same folder from the state it
# wrote, to 0.01 s after the time it stopped at (a restart may change the duration), against a
# run straight to that time.
"$bin" run "$wall" --out "$tmp/int" --threads 2 >"$tmp/int.txt" 2>&1 &
pid=$!
for _ in $(seq 100); do [[ -s "$tmp/int/energy.csv" ]] && break; sleep 0.05; done
sleep 1
kill -s INT $pid
wait $pid; status=$?
[[ $status -eq 130 ]] || fail "SIGINT: exit status $status, expected 130: $(cat "$tmp/int.txt")"
state=$(ls "$tmp/int/state/"*.h5 2>/dev/null | head -1)
[[ -n "$state" ]] || fail "the interrupted run wrote no state file: $(cat "$tmp/int.txt")"
expect_in "$(cat "$tmp/int.txt")" "to go on: blockdem run --restart"
end=$(/usr/bin/python3 -c "import json, sys; print(round(json.load(open(sys.argv[1]))['time_s'] + 0.01, 6))" "$tmp/int/summary.json")
"$bin" run --restart "$state" --set simulation.duration=$end -q --threads 2 >"$tmp/log" 2>&1 \
  || fail "the resumed run failed: $(cat "$tmp/log")"
"$bin" run "$wall" --out "$tmp/int_whole" --set simulation.duration=$end -q --threads 2 >"$tmp/log" 2>&1 \
  || fail "the wall run to $end s failed: $(cat "$tmp/log")"
same_results "wall interrupted and resumed in place to $end s" "$tmp/int_whole" "$tmp/int"

# 4. Refusals, exit 2 with the file named.
state="$tmp/first/state/t_0.100000s.h5"
refused "3-D state, 2-D scenario" "$state" "$src/examples/paper/sliding.toml" --out "$tmp/bad1" -- "t_0.100000s.h5"
refused "state of another scenario" "$state" "$wall" --out "$tmp/bad2" -- "does not belong to scenario"
# The deepest overlap's pair (summary.json checks.overlap) naming no body: refused. A state saved
# before the deepest overlap was kept (no such attributes) restarts, with none seen before it.
# The live limit's ratio out of range (NaN, below 1): refused; a state saved before the ratio was
# kept restarts with the scenario's start ratio.
cp "$state" "$tmp/bad_pair.h5"
cp "$state" "$tmp/no_overlap.h5"
cp "$state" "$tmp/bad_ratio.h5"
cp "$state" "$tmp/no_ratio.h5"
/usr/bin/python3 - "$tmp/bad_pair.h5" "$tmp/no_overlap.h5" "$tmp/bad_ratio.h5" "$tmp/no_ratio.h5" <<'PY' || fail "could not edit the state files (h5py)"
import sys, h5py
with h5py.File(sys.argv[1], "r+") as f:
    f["stability3d"].attrs["max_overlap_body_a"] = 999
with h5py.File(sys.argv[2], "r+") as f:
    for name in ("max_overlap_ratio", "max_overlap_m", "max_overlap_time_s", "max_overlap_body_a", "max_overlap_body_b"):
        del f["stability3d"].attrs[name]
with h5py.File(sys.argv[3], "r+") as f:
    f["stability3d"].attrs["limit_ratio"] = 0.5
with h5py.File(sys.argv[4], "r+") as f:
    for name in ("start_bound_s", "limit_ratio", "ratio_bound_s", "estimates"):
        del f["stability3d"].attrs[name]
PY
refused "a live-limit ratio of 0.5" "$tmp/bad_ratio.h5" --out "$tmp/bad_ratio" -- "bad_ratio.h5" "/stability3d/limit_ratio (0.5)"
"$bin" run --restart "$tmp/no_ratio.h5" --out "$tmp/no_ratio" -q >"$tmp/log" 2>&1 \
  || fail "a state without the live limit's ratio did not restart: $(cat "$tmp/log")"
cmp -s "$tmp/no_ratio/summary.json" "$tmp/second/summary.json" \
  || fail "the restart without the ratio differs from the one with it (the scenario's start ratio is the state's here)"
refused "a deepest-overlap pair naming no body" "$tmp/bad_pair.h5" --out "$tmp/bad_pair" -- \
  "bad_pair.h5" "max_overlap_body_a or _b names no body"
"$bin" run --restart "$tmp/no_overlap.h5" --out "$tmp/no_overlap" -q >"$tmp/log" 2>&1 \
  || fail "a state without the deepest overlap did not restart: $(cat "$tmp/log")"
/usr/bin/python3 - "$tmp/no_overlap" <<'PY' || fail "the restart without the deepest overlap does not report one of its own"
import json, sys
overlap = json.load(open(f"{sys.argv[1]}/summary.json"))["checks"]["overlap"]
assert 0.0 < overlap["max_ratio"] < 0.01 and 0.1 <= overlap["time_s"] <= 0.2, overlap
PY

"$bin" run "$src/examples/paper/sliding.toml" --out "$tmp/flat" --set simulation.duration=0.2 --save-state 0.1 -q >"$tmp/log" 2>&1 \
  || fail "the 2-D run failed: $(cat "$tmp/log")"
refused "2-D state, 3-D scenario" "$tmp/flat/state/t_0.100000s.h5" "$drums" --out "$tmp/bad3" -- "a 2-D state: scenario"

# 5. A restart under bodies that changed (another density, another radius): refused naming the
# body and the quantity, not run into an energy failure that blames dt.
sed 's/density = 2700.0/density = 5400.0/' "$drums" > "$tmp/heavier.toml"
sed 's/radius = 0.3 /radius = 0.31 /' "$drums" > "$tmp/wider.toml"
state="$tmp/first/state/t_0.100000s.h5"
refused "denser drums" "$state" "$tmp/heavier.toml" --out "$tmp/heavier" -- \
  "does not belong to scenario" "body 'drum_1' has mass" "kg in the state but" "initial_state"
refused "wider drums" "$state" "$tmp/wider.toml" --out "$tmp/wider" -- "body 'drum_1' has another shape in the state"
[[ ! -e "$tmp/heavier" && ! -e "$tmp/wider" ]] || fail "a refused restart created its --out"
# ... and an unchanged scenario given again still restarts (the same masses, exactly).
"$bin" run --restart "$state" "$drums" --set simulation.duration=0.2 --out "$tmp/same_bodies" -q --threads 1 >"$tmp/log" 2>&1 \
  || fail "a restart under the same scenario was refused: $(cat "$tmp/log")"

# 6. The folder a restart goes on in: a copy of the run folder without its scenario.toml is
# refused naming it (never the original folder the state names); a state copied out of its run
# needs --out; /dev/null is not a state file.
cp -r "$tmp/first" "$tmp/copy"
rm "$tmp/copy/scenario.toml"
before=$(md5sum < "$tmp/first/history.csv")
refused "a copied folder without scenario.toml" "$tmp/copy/state/t_0.100000s.h5" -- "$tmp/copy/scenario.toml" "missing"
[[ "$(md5sum < "$tmp/first/history.csv")" == "$before" ]] || fail "a restart from the copy wrote into the original folder"
"$bin" run --restart "$tmp/copy/state/t_0.100000s.h5" "$drums" --set simulation.duration=0.2 -q --threads 1 >"$tmp/log" 2>&1 \
  || fail "a restart in the copy, with the scenario given, failed: $(cat "$tmp/log")"
[[ "$(md5sum < "$tmp/first/history.csv")" == "$before" ]] || fail "the restart in the copy wrote into the original folder"
same_results "restarted in a copy of its folder" "$tmp/whole" "$tmp/copy"
cp "$state" "$tmp/lone.h5"
refused "a state outside a state/ folder" "$tmp/lone.h5" -- "lone.h5" "give --out"
refused "/dev/null" /dev/null -- "/dev/null: not a regular file"

# 7. --save-state-every: below dt refused (exit 2, nothing written), 1.5 dt saved every 2 steps
# with each file named by the time it holds, no name written twice.
dt=$(/usr/bin/python3 -c "import h5py, sys; print(repr(h5py.File(sys.argv[1], 'r').attrs['dt_s']))" "$state")
out=$("$bin" run "$drums" --out "$tmp/every_tiny" --set simulation.duration=0.01 --save-state-every 1e-9 -q 2>&1); status=$?
[[ $status -eq 2 ]] || fail "--save-state-every 1e-9: exit status $status, expected 2: $out"
expect_in "$out" "--save-state-every: 1e-09 s is below the time step dt = "
[[ ! -e "$tmp/every_tiny" ]] || fail "a refused --save-state-every created its --out"
every=$(/usr/bin/python3 -c "print(repr(1.5 * $dt))")
out=$("$bin" run "$drums" --out "$tmp/every_odd" --set simulation.duration=0.01 --save-state-every "$every" -q 2>&1) \
  || fail "--save-state-every 1.5 dt: $out"
expect_in "$out" "is not a whole number of time steps"
/usr/bin/python3 - "$tmp/every_odd" <<'PY' || fail "--save-state-every 1.5 dt: files not named by their times"
import glob, json, os, sys, h5py
folder = sys.argv[1]
listed = json.load(open(f"{folder}/run_info.json"))["state_files"]
assert len(listed) == len(set(listed)) > 10, listed
files = sorted(glob.glob(f"{folder}/state/t_*.h5"))
assert len(files) == len(listed), (len(files), len(listed))
for path in files:
    f = h5py.File(path, "r")
    assert os.path.basename(path) == f"t_{f.attrs['time_s']:.6f}s.h5", (path, f.attrs["time_s"])
    assert f.attrs["step_index"] % 2 == 0, (path, f.attrs["step_index"])
PY

if [[ $failures -gt 0 ]]; then echo "$failures failure(s)"; exit 1; fi
echo "test_restart_3d: all passed"
