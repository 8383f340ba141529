#!/usr/bin/env bash
# State files (docs/outputs.md, "State files"): a run of 0 to T and a run of 0 to T/2 restarted
# from its state file to T write byte-identical history.csv, energy.csv and summary.json, for a
# rocking block, a drum column under a record and a wall of bricks under a record (large enough
# for the contact loops to run on threads), with 1 and 2 threads; an interrupted run resumes
# from the state it wrote as it stopped; a scenario's [simulation] initial_state starts new runs
# (and a sweep) from a settled state; a block dropped onto another, whose live limit's ratio is
# estimated again and saved; bad state files are refused with exit 2, and a state that
# cannot be written stops the run with exit 4 and leaves no torn file; a restart under a changed
# density, from a copied folder without scenario.toml, or from /dev/null is refused naming the
# cause, and --save-state-every below dt too.
# Usage: test_restart.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
export OMP_WAIT_POLICY=passive
py=/usr/bin/python3

# Same results: the three files, byte for byte.
same_results() {  # LABEL DIR1 DIR2
  for f in history.csv energy.csv summary.json; do
    cmp -s "$2/$f" "$3/$f" || fail "$1: $f differs between $2 and $3"
  done
}

# A record in the PEER AT2 format: 1.2 s of a 3 Hz burst, 0.35 g peak.
$py - "$tmp/burst.AT2" <<'PY'
import math, sys
dt, n = 0.005, 240
acc = [0.35 * math.sin(2 * math.pi * 3 * i * dt) * math.sin(math.pi * i / (n - 1)) for i in range(n)]
with open(sys.argv[1], "w") as f:
    f.write("PEER NGA STRONG MOTION DATABASE RECORD\nTest burst, 1/1/2000, blockdem, 000\n")
    f.write("ACCELERATION TIME SERIES IN UNITS OF G\n")
    f.write(f"NPTS=  {n}, DT=   .0050 SEC\n")
    for k in range(0, n, 5):
        f.write("".join(f"{a:15.7E}" for a in acc[k:k + 5]) + "\n")
PY

# Three marble drums on a table shaken by the record (examples/columns, shorter).
cat > "$tmp/drums.toml" <<TOML
[simulation]
duration = 0.6
output_interval = 0.005
[contact]
kn = 1.0e9
ks = 1.0e9
mu = 0.7
e = 0.5
e_meaning = "rebound"
h_s = 1.0
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 3.0
height = 0.2
center = [0.0, -0.1]
density = 7850.0
[[assemblies]]
type = "column"
name = "drum"
density = 2700.0
base_center = [0.0, 0.0]
count = 3
width = 0.6
height = 0.9
record = true
[table_motion.horizontal]
type = "record"
file = "$tmp/burst.AT2"
scale = 3.0
TOML

# A wall of about 1,250 bricks under the record: more than 2,048 contact pairs, so the step
# runs on threads (world/parallel.hpp).
cat > "$tmp/wall.toml" <<TOML
[simulation]
duration = 0.02
dt = 4.0e-5
output_interval = 0.002
[contact]
kn = 6.0e7
ks = 6.0e7
mu = 0.6
e = 0.5
h_s = 0.2
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 7.0
height = 0.2
center = [2.5, -0.1]
density = 1000.0
[[assemblies]]
type = "wall"
name = "brick"
density = 2000.0
length = 5.0
courses = 50
brick_length = 0.2
brick_height = 0.1
record = true
[settling]
kinetic_ratio = 1.0
window = 0.004
[table_motion.horizontal]
type = "record"
file = "$tmp/burst.AT2"
scale = 3.0
TOML

# 1. Save at T/2, restart to T, with the thread counts crossed.
check_restart() {  # LABEL HALF_TIME SCENARIO [--set ...]
  local label=$1 half=$2 before=$failures; shift 2
  "$bin" run "$@" --out "$tmp/$label-full" -q --threads 1 --save-state "$half" > /dev/null 2> "$tmp/$label-full.log" \
    || { fail "$label: full run: $(tail -2 "$tmp/$label-full.log")"; return; }
  "$bin" run "$@" --out "$tmp/$label-2" -q --threads 2 > /dev/null 2>&1 || fail "$label: run with 2 threads"
  same_results "$label, 1 and 2 threads" "$tmp/$label-full" "$tmp/$label-2"
  local state; state=$(ls "$tmp/$label-full/state/"t_*.h5 2>/dev/null | head -1)
  [ -n "$state" ] || { fail "$label: no state file in $tmp/$label-full/state"; return; }
  # (a) into a new folder, 2 threads;
  "$bin" run --restart "$state" --out "$tmp/$label-new" -q --threads 2 > /dev/null 2> "$tmp/$label-new.log" \
    || fail "$label: restart into a new folder: $(tail -2 "$tmp/$label-new.log")"
  same_results "$label, restarted into a new folder" "$tmp/$label-full" "$tmp/$label-new"
  # (b) a run that ends at T/2, continued in its own folder to T (a longer duration), 1 thread.
  local end; end=$($py -c 'import json, sys; print(json.load(open(sys.argv[1]))["end_time_s"])' "$tmp/$label-full/summary.json")
  "$bin" run "$@" --set simulation.duration="$half" --out "$tmp/$label-half" -q --threads 2 --save-state "$half" \
    > /dev/null 2>&1 || fail "$label: first half"
  "$bin" run --restart "$tmp/$label-half/state/$(basename "$state")" --set simulation.duration="$end" -q --threads 1 \
    > /dev/null 2> "$tmp/$label-half.log" || fail "$label: restart in place: $(tail -2 "$tmp/$label-half.log")"
  same_results "$label, first half then continued in place" "$tmp/$label-full" "$tmp/$label-half"
  [ $failures -eq $before ] && echo "$label: restarted from $(basename "$state"): identical files"
}
check_restart rocking 1.0 "$src/examples/paper/rocking.toml" --set simulation.duration=2 --set output.vtk=false
check_restart drums 0.3 "$tmp/drums.toml"
check_restart wall 0.01 "$tmp/wall.toml"
# A block dropped onto another (at the derived dt): the live watch estimates its ratio again once
# they are stacked (docs/physics.md, "The stable time step"); the state carries the ratio.
cat > "$tmp/stack.toml" <<TOML
[simulation]
duration = 0.3
output_interval = 0.01
[contact]
kn = 1.0e7
ks = 1.0e7
mu = 0.5
e = 0.3
h_s = 1.0
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 3.0
height = 0.2
center = [0.0, -0.1]
[[bodies]]
name = "lower"
shape = "rectangle"
width = 0.4
height = 0.4
center = [0.0, 0.2]
density = 2500.0
[[bodies]]
name = "upper"
shape = "rectangle"
width = 0.4
height = 0.4
center = [0.0, 0.61]
density = 2500.0
TOML
check_restart stack 0.15 "$tmp/stack.toml"
# 1,100 such stacks 0.1 m apart (more than 2,048 contact pairs: the step runs on threads): the
# estimate made once they are stacked is the same at 1 and 2 threads and across the restart.
$py - "$tmp/stacks.toml" <<'PY'
import sys
rows = ["[simulation]", "duration = 0.2", "output_interval = 0.01",
        "[contact]", "kn = 1.0e7", "ks = 1.0e7", "mu = 0.5", "e = 0.3", "h_s = 1.0",
        "[[bodies]]", 'name = "table"', 'kind = "fixed"', 'shape = "rectangle"', "width = 552.0", "height = 0.2",
        "center = [275.0, -0.1]"]
for i in range(1100):
    for level, y in (("lower", 0.2), ("upper", 0.61)):
        rows += ["[[bodies]]", f'name = "{level}{i}"', 'shape = "rectangle"', "width = 0.4", "height = 0.4",
                 f"center = [{0.5 * i:.1f}, {y}]", "density = 2500.0", "record = false"]
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
check_restart stacks 0.1 "$tmp/stacks.toml" --set output.vtk=false
$py - "$tmp/stacks-full/state" <<'PY' || fail "the stacks made no estimate, or too few pairs for threads"
import glob, sys, h5py
f = h5py.File(sorted(glob.glob(sys.argv[1] + "/*.h5"))[0], "r")
assert f["stability"].attrs["estimates"] >= 1, dict(f["stability"].attrs)
assert len(f["contacts/a"]) > 2048, len(f["contacts/a"])
PY
# The wall's contact loops did run on threads.
pairs=$($py -c 'import h5py, sys; print(len(h5py.File(sys.argv[1], "r")["contacts/a"]))' "$(ls "$tmp"/wall-full/state/*.h5 | head -1)")
[ "${pairs:-0}" -gt 2048 ] || fail "the wall has only ${pairs:-0} contact pairs (no threads)"

# --save-state-every: one state every 0.5 s, the end included, named by the times.
"$bin" run "$src/examples/paper/rocking.toml" --set simulation.duration=2 --set output.vtk=false --out "$tmp/every" -q \
  --save-state-every 0.5 > /dev/null 2>&1 || fail "--save-state-every"
[ "$(cd "$tmp/every/state" && echo t_*)" = "t_0.500000s.h5 t_1.000000s.h5 t_1.500000s.h5 t_2.000000s.h5" ] \
  || fail "--save-state-every 0.5 wrote: $(ls "$tmp/every/state")"

# 2. The layout, read with h5py (docs/outputs.md).
$py - "$(ls "$tmp"/drums-full/state/*.h5 | head -1)" <<'PY' || fail "state file layout (h5py)"
import sys, h5py
f = h5py.File(sys.argv[1], "r")
assert f.attrs["format"] == "blockdem state" and f.attrs["format_version"] == 1
clock = f["clock"].attrs
assert abs(clock["time_s"] - 0.3) <= clock["dt_s"], clock["time_s"]
assert clock["step_index"] > 0 and clock["velocities_staggered"] == 1
names = [n.decode() if isinstance(n, bytes) else n for n in f["bodies/name"][:]]
assert names == ["table", "drum0", "drum1", "drum2"], names
assert f["bodies/position_m"].shape == (4, 2) and f["bodies/velocity_m_s"].shape == (4, 2)
n = len(f["contacts/a"])
assert f["contacts/point_shear_spring_n"].shape == (n, 2) and f["contacts/point_normal_dashpot_n"].shape == (n, 2)
assert (f["contacts/count"][:] > 0).sum() >= 1 and abs(f["contacts/point_shear_spring_n"][:]).max() > 0, "no shear history"
assert "kinetic_j" in f["energy"].attrs and "peak_abs_rotation_rad" in f["monitor"]
assert f.attrs["output_rows"] == 60, f.attrs["output_rows"]   # rows at t = 0, 0.005, ..., 0.295
PY

# 3. Interrupted, then resumed in place: the files of the uninterrupted run.
long=("$src/examples/paper/rocking.toml" --set simulation.duration=60 --set output.vtk=false)
"$bin" run "${long[@]}" --out "$tmp/straight" -q > /dev/null 2>&1 || fail "uninterrupted long run"
"$bin" run "${long[@]}" --out "$tmp/stopped" -q > /dev/null 2> "$tmp/stopped.log" &
pid=$!
for _ in $(seq 1 600); do
  [ -f "$tmp/stopped/history.csv" ] && [ "$(wc -l < "$tmp/stopped/history.csv")" -ge 400 ] && break
  sleep 0.02
done
kill -s INT $pid; wait $pid; rc=$?
if [ $rc -ne 130 ]; then
  fail "interrupt: exit $rc, expected 130 (did the run end before the signal?)"
else
  state=$(ls "$tmp"/stopped/state/t_*.h5 2>/dev/null | head -1)
  [ -n "$state" ] || fail "the interrupted run wrote no state file"
  grep -q "to go on: blockdem run --restart .*state/t_.*s.h5" "$tmp/stopped.log" || fail "no restart hint: $(cat "$tmp/stopped.log")"
  [ "$($py -c 'import h5py, sys; print(h5py.File(sys.argv[1], "r").attrs["reason"])' "$state")" = interrupted ] \
    || fail "the state's reason is not 'interrupted'"
  "$bin" run --restart "$state" -q > /dev/null 2> "$tmp/resume.log" || fail "resume: $(tail -2 "$tmp/resume.log")"
  before=$failures
  same_results "interrupted and resumed" "$tmp/straight" "$tmp/stopped"
  [ $failures -eq $before ] && echo "interrupted at $(basename "$state"), resumed: identical files"
fi

# 4. initial_state: settle once (--save-state 0), shake many times. The same scenario without
# [settling], started from the settled state, gives the run that settled itself. (A wall of 30
# bricks, settled for real.)
$py - "$tmp/wall.toml" "$tmp/small_wall.toml" "$tmp/from_state.toml" <<'PY'
import sys
text = open(sys.argv[1]).read()
for old, new in (("length = 5.0", "length = 1.0"), ("courses = 50", "courses = 6"), ("width = 7.0", "width = 2.0"),
                 ("center = [2.5", "center = [0.5"), ("kinetic_ratio = 1.0", "kinetic_ratio = 1.0e-6"),
                 ("duration = 0.02", "duration = 0.1")):
    assert old in text, old
    text = text.replace(old, new)
open(sys.argv[2], "w").write(text)
start, end = text.index("[settling]"), text.index("[table_motion")
text = text[:start] + text[end:]
text = text.replace("output_interval = 0.002", 'output_interval = 0.002\ninitial_state = "settled/state/t_0.000000s.h5"')
open(sys.argv[3], "w").write(text)
PY
"$bin" run "$tmp/small_wall.toml" --out "$tmp/settled" -q --save-state 0 > /dev/null 2>&1 || fail "settled run"
"$bin" run "$tmp/from_state.toml" --out "$tmp/branch" -q > /dev/null 2> "$tmp/branch.log" \
  || fail "run from initial_state: $(tail -2 "$tmp/branch.log")"
for f in history.csv energy.csv; do
  cmp -s "$tmp/settled/$f" "$tmp/branch/$f" || fail "initial_state: $f differs from the run that settled itself"
done
"$bin" run "$tmp/from_state.toml" --out "$tmp/branch2" -q --set table_motion.horizontal.scale=1.5 > /dev/null 2>&1 \
  || fail "run from initial_state with another amplitude"
cmp -s "$tmp/branch/history.csv" "$tmp/branch2/history.csv" && fail "another amplitude gave the same history"
[ "$(sed -n 2p "$tmp/branch2/history.csv" | cut -d, -f1)" = 0 ] || fail "a run from initial_state does not start at t = 0"
# ... and in a sweep, whose first case is the run above.
"$bin" sweep "$tmp/from_state.toml" --out "$tmp/sweep" --vary table_motion.horizontal.scale=3,1.5 --threads 1 -q \
  > "$tmp/sweep.log" 2>&1 || fail "sweep from initial_state: $(tail -3 "$tmp/sweep.log")"
$py - "$tmp/sweep/results.csv" "$tmp/branch/summary.json" <<'PY' || fail "sweep from initial_state: results"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["status"] for r in rows] == ["completed", "completed"], rows
run = {b["name"]: b for b in json.load(open(sys.argv[2]))["bodies"]}
brick = "brick10"
assert abs(float(rows[0][brick + ".peak_rotation_rad"]) - run[brick]["peak_abs_rotation_rad"]) <= 1e-5 * max(1e-12, run[brick]["peak_abs_rotation_rad"]), (rows[0][brick + ".peak_rotation_rad"], run[brick]["peak_abs_rotation_rad"])
PY

# 5. Bad input: exit 2, with the file and the problem named; exit 4 when the state cannot be written.
expect() {  # CODE PATTERN COMMAND...
  local code=$1 pattern=$2; shift 2
  local out; out=$("$@" 2>&1); local rc=$?
  [ $rc -eq "$code" ] || fail "$* : exit $rc, expected $code ($out)"
  echo "$out" | grep -q -- "$pattern" || fail "$* : message lacks '$pattern': $out"
}
good=$(ls "$tmp"/drums-full/state/*.h5 | head -1)
expect 2 "no such state file" "$bin" run --restart "$tmp/none.h5" --out "$tmp/x1" -q
printf 'garbage\n' > "$tmp/garbage.h5"
expect 2 "garbage.h5.*not an HDF5 file" "$bin" run --restart "$tmp/garbage.h5" "$tmp/drums.toml" --out "$tmp/x2" -q
head -c 3000 "$good" > "$tmp/cut.h5"
expect 2 "cut.h5" "$bin" run --restart "$tmp/cut.h5" "$tmp/drums.toml" --out "$tmp/x3" -q
expect 2 "does not belong to scenario.*the state has 4 bodies, the scenario 2" \
  "$bin" run --restart "$good" "$src/examples/paper/rocking.toml" --out "$tmp/x4" -q
[ -e "$tmp/x4" ] && fail "a refused restart wrote $tmp/x4"
expect 2 "simulation.initial_state" "$bin" run "$tmp/from_state.toml" --set simulation.initial_state="$tmp/none.h5" --out "$tmp/x5" -q
expect 2 "initial_state.*remove \[settling\]" "$bin" run "$tmp/small_wall.toml" --set simulation.initial_state="$good" --out "$tmp/x6" -q
expect 2 "save-state.*outside the run" "$bin" run "$tmp/drums.toml" --save-state 5 --out "$tmp/x7" -q
# The live limit's ratio: out of range, refused naming the attribute; absent (a file saved before
# the watch kept it), the scenario's start ratio is taken and estimated again on the stacked
# blocks, as the saved run did: the same summary, and no report of dt above the live limit.
stack_state=$(ls "$tmp"/stack-full/state/*.h5 | head -1)
for name in bad_ratio huge_ratio bad_bound no_ratio old_bad_start; do cp "$stack_state" "$tmp/$name.h5"; done
$py - "$tmp" <<'PY' || fail "editing the stack's state with h5py"
import sys, h5py
edits = {
    "bad_ratio": {"limit_ratio": 0.5},
    "huge_ratio": {"limit_ratio": 1e300},
    "bad_bound": {"ratio_bound_s": float("inf")},
    "no_ratio": {"limit_ratio": None, "ratio_bound_s": None, "estimates": None},
    "old_bad_start": {"limit_ratio": None, "ratio_bound_s": None, "estimates": None, "start_bound_s": float("nan")},
}
for name, changes in edits.items():
    with h5py.File(f"{sys.argv[1]}/{name}.h5", "r+") as f:
        a = f["stability"].attrs
        assert a["estimates"] >= 1, dict(a)
        for key, value in changes.items():
            if value is None:
                del a[key]
            else:
                a[key] = value
PY
expect 2 "bad_ratio.h5.*/stability/limit_ratio (0.5) is neither 0 nor between 1 and 100" \
  "$bin" run --restart "$tmp/bad_ratio.h5" --out "$tmp/x8" -q
expect 2 "huge_ratio.h5.*/stability/limit_ratio (1e+300)" "$bin" run --restart "$tmp/huge_ratio.h5" --out "$tmp/x9" -q
expect 2 "bad_bound.h5.*/stability/ratio_bound_s (inf)" "$bin" run --restart "$tmp/bad_bound.h5" --out "$tmp/x10" -q
expect 2 "old_bad_start.h5.*/stability/start_bound_s (nan) is not positive" \
  "$bin" run --restart "$tmp/old_bad_start.h5" --out "$tmp/x11" -q
"$bin" run --restart "$tmp/no_ratio.h5" --out "$tmp/no_ratio" -q > /dev/null 2> "$tmp/no_ratio.log" \
  || fail "a state without the live limit's ratio did not restart: $(tail -2 "$tmp/no_ratio.log")"
cmp -s "$tmp/no_ratio/summary.json" "$tmp/stack-full/summary.json" \
  || fail "the restart without the ratio differs from the run that saved it"
grep -q '"dt_above_live_limit": false' "$tmp/stack-full/summary.json" \
  || fail "the stacked blocks at the derived dt report dt above the live limit"
# A full disk: a 20 kB file-size limit lets the short history through but not the state.
msg=$( (ulimit -f 20; "$bin" run "$tmp/drums.toml" --set simulation.output_interval=0.1 --save-state 0.3 --out "$tmp/full" -q) 2>&1); rc=$?
[ $rc -eq 4 ] || fail "state on a full disk: exit $rc, expected 4 ($msg)"
echo "$msg" | grep -q "state/t_0.300000s.h5" || fail "the full-disk message does not name the state file: $msg"
[ -n "$(ls -A "$tmp/full/state" 2>/dev/null)" ] && fail "a torn state file was left: $(ls "$tmp/full/state")"
grep -q '"status": "failed"' "$tmp/full/summary.json" 2>/dev/null || fail "summary.json after a failed state write"

# 6. What a careless user may hand a restart (probe 22), 2-D: another density (mass and moment
# of inertia of the tombstone changed): refused naming the body and the quantity; a copied run
# folder without its scenario.toml: refused naming it, the original folder untouched; /dev/null:
# not a regular file; --save-state-every below dt: refused, nothing written.
"$bin" run "$src/examples/paper/rocking.toml" --set simulation.duration=0.2 --set output.vtk=false --out "$tmp/rock" -q \
  --save-state 0.1 > /dev/null 2>&1 || fail "rocking run with a state"
rock_state="$tmp/rock/state/t_0.100000s.h5"
sed 's/density = 2600.0/density = 5200.0/' "$src/examples/paper/rocking.toml" > "$tmp/heavy_rock.toml"
expect 2 "does not belong to scenario.*body 'tombstone' has mass .* kg in the state but .* kg in the scenario" \
  "$bin" run --restart "$rock_state" "$tmp/heavy_rock.toml" --out "$tmp/x12" -q
[ -e "$tmp/x12" ] && fail "a refused restart (changed density) wrote $tmp/x12"
cp -r "$tmp/rock" "$tmp/rock_copy" && rm "$tmp/rock_copy/scenario.toml"
sum_before=$(md5sum < "$tmp/rock/history.csv")
expect 2 "rock_copy/scenario.toml: missing" "$bin" run --restart "$tmp/rock_copy/state/t_0.100000s.h5" -q
[ "$(md5sum < "$tmp/rock/history.csv")" = "$sum_before" ] || fail "a restart from a copied folder wrote into the original"
grep -q restarted_from "$tmp/rock/run_info.json" 2>/dev/null && grep -q rock_copy "$tmp/rock/run_info.json" \
  && fail "the original folder's run_info.json names the copy's restart"
expect 2 "/dev/null: not a regular file" "$bin" run --restart /dev/null -q
expect 2 "save-state-every: 1e-07 s is below the time step dt" \
  "$bin" run "$src/examples/paper/rocking.toml" --set simulation.duration=0.001 --save-state-every 1e-7 --out "$tmp/x13" -q
[ -e "$tmp/x13" ] && fail "a refused --save-state-every wrote $tmp/x13"
# A dt below 1e-6 s: the names take more decimals, so that no two steps share one.
"$bin" run "$src/examples/paper/rocking.toml" --set simulation.duration=2e-6 --set simulation.dt=2e-7 --set output.vtk=false \
  --save-state-every 2e-7 --out "$tmp/fine" -q > /dev/null 2>&1 || fail "--save-state-every dt at dt = 2e-7 s"
[ "$(ls "$tmp/fine/state" | wc -l)" -eq 10 ] && [ "$(ls "$tmp/fine/state" | head -1)" = t_0.0000002s.h5 ] \
  || fail "--save-state-every at dt = 2e-7 s wrote: $(ls "$tmp/fine/state")"

[ $failures -eq 0 ] && echo "state files: restarts, interruptions and initial states give identical, whole results"
exit $failures
