#!/usr/bin/env bash
# State files keep the measurements (docs/outputs.md, "State files"): a run of 0 to T and a run
# of 0 to T/2 restarted from its state file to T write byte-identical sensors.csv (a filtered
# accelerometer, whose Butterworth filter runs on across the restart, and an LVDT, which reads
# from the start of the run), interfaces.csv (one row per touching pair: the cut is by rows, not
# times) and summary.json (its "interfaces": accumulated slip, peaks, first touch), into a new
# folder and in the run's own folder, from a state at an output time and from one between two.
# Usage: test_restart_measurements.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
export OMP_WAIT_POLICY=passive
py=/usr/bin/python3

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

# Three marble drums on a table shaken hard enough to rock and slide (examples/columns, shorter).
cat > "$tmp/drums.toml" <<TOML
[simulation]
duration = 0.6
output_interval = 0.005
[output]
interfaces = "all"
[contact]
kn = 1.0e9
ks = 1.0e9
mu = 0.5
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
[[sensors]]
name = "top"
body = "drum2"
point = [0.0, 0.45]
lowpass_hz = 40.0
order = 4
[[sensors]]
name = "lvdt"
kind = "relative"
body = "drum0"
point = [-0.3, -0.45]
body2 = "table"
point2 = [-0.3, 0.1]
[table_motion.horizontal]
type = "record"
file = "$tmp/burst.AT2"
scale = 4.0
TOML

same_results() {  # LABEL DIR1 DIR2
  for f in sensors.csv interfaces.csv history.csv; do
    cmp -s "$2/$f" "$3/$f" || fail "$1: $f differs between $2 and $3 ($(cmp "$2/$f" "$3/$f" 2>&1 | head -1))"
  done
  # summary.json whole, and (so that a failure says whose state is missing) what differs in it.
  cmp -s "$2/summary.json" "$3/summary.json" || fail "$1: summary.json differs between $2 and $3: $($py - "$2" "$3" <<'PY'
import json, sys
a, b = (json.load(open(f"{d}/summary.json")) for d in sys.argv[1:3])
keys = [k for k in a if a.get(k) != b.get(k)]
bodies = sorted({f for x, y in zip(a.get("bodies", []), b.get("bodies", [])) for f in x if x[f] != y.get(f)})
print("keys", keys, "body fields", bodies)
PY
)"
}

# 0.3 s is an output time; 0.3024 s lies between two.
"$bin" run "$tmp/drums.toml" --out "$tmp/full" -q --save-state 0.3 --save-state 0.3024 > /dev/null 2> "$tmp/full.log" \
  || { fail "full run: $(tail -2 "$tmp/full.log")"; exit $failures; }
# The run measures something worth continuing: a filtered channel that moves, slip that grows,
# and, at some output time, another number of touching pairs than at the first.
$py - "$tmp/full" <<'PY' || fail "the full run's measurements are too quiet to test a restart"
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(l for l in open(f"{d}/sensors.csv") if not l.startswith("#")))
assert max(abs(float(r["top.ax"])) for r in rows) > 0.5, "top.ax"
assert max(abs(float(r["lvdt.dx"])) for r in rows) > 1e-5, "lvdt.dx"
irows = list(csv.DictReader(l for l in open(f"{d}/interfaces.csv") if not l.startswith("#")))
per_time = {}
for r in irows: per_time[r["t"]] = per_time.get(r["t"], 0) + 1
assert len(irows) > len(rows), "one row per pair"
summary = json.load(open(f"{d}/summary.json"))["interfaces"]["list"]
assert max(abs(i["peak_abs_slip_m"]) for i in summary) > 1e-5, summary
PY
# (A state file is named by the time it holds: the step nearest 0.3024 s is a little off it.)
between=$(cd "$tmp/full/state" && ls t_0.302*s.h5 2>/dev/null | head -1)
[ -n "$between" ] && [ "$between" != t_0.302400s.h5 ] || fail "the state nearest 0.3024 s is named '$between'"
for state in t_0.300000s.h5 $between; do
  [ -f "$tmp/full/state/$state" ] || { fail "no state $state in $tmp/full/state"; continue; }
  label=${state%.h5}
  # (a) into a new folder;
  "$bin" run --restart "$tmp/full/state/$state" --out "$tmp/new-$label" -q > /dev/null 2> "$tmp/new-$label.log" \
    || fail "$label: restart into a new folder: $(tail -2 "$tmp/new-$label.log")"
  same_results "$label, restarted into a new folder" "$tmp/full" "$tmp/new-$label"
done
$py - "$tmp/full/state/t_0.300000s.h5" "$tmp/full/interfaces.csv" <<'PY' || fail "state file groups /sensors and /interfaces (h5py)"
import sys, h5py
f = h5py.File(sys.argv[1], "r")
before = sum(1 for l in open(sys.argv[2]) if l[0].isdigit() and float(l.split(",")[0]) < 0.3 - 1e-7)
s, i = f["sensors"], f["interfaces"]
names = [n.decode() if isinstance(n, bytes) else n for n in s["sensor"][:]]
assert names == ["top (low-pass 40 Hz, order 4)", "lvdt (unfiltered)"], names
assert s["filter_state"].shape == (6 * 2 * 2,) and s["filter_started"].shape == (6,), s["filter_state"].shape
assert s["relative_start_m"].shape == (2, 2) and s.attrs["started"] == 1
assert len(i["body_a"]) == 3 and i.attrs["csv_rows"] == before, (len(i["body_a"]), i.attrs["csv_rows"], before)
assert "slip_m" in i and "peak_opening_m" in i and "first_touch_time_s" in i
PY
# (b) a run that ends at T/2, continued in its own folder to T (a longer duration).
"$bin" run "$tmp/drums.toml" --set simulation.duration=0.3 --out "$tmp/half" -q --save-state 0.3 > /dev/null 2>&1 \
  || fail "first half"
"$bin" run --restart "$tmp/half/state/t_0.300000s.h5" --set simulation.duration=0.6 -q > /dev/null 2> "$tmp/half.log" \
  || fail "restart in place: $(tail -2 "$tmp/half.log")"
same_results "first half then continued in place" "$tmp/full" "$tmp/half"

# A state whose sensors are not the scenario's is refused (exit 2), naming both lists.
sed 's/name = "top"/name = "head"/' "$tmp/drums.toml" > "$tmp/renamed.toml"
out=$("$bin" run --restart "$tmp/full/state/t_0.300000s.h5" "$tmp/renamed.toml" --out "$tmp/x1" -q 2>&1); rc=$?
[ $rc -eq 2 ] || fail "renamed sensor: exit $rc, expected 2 ($out)"
echo "$out" | grep -q "state's sensors (top (low-pass 40 Hz, order 4), lvdt (unfiltered)) are not the scenario's.*head (low-pass 40 Hz, order 4), lvdt" \
  || fail "renamed sensor: $out"
# ... and so is another filter on the same sensor (order 3 has as many sections as order 4).
sed 's/order = 4/order = 3/' "$tmp/drums.toml" > "$tmp/refiltered.toml"
out=$("$bin" run --restart "$tmp/full/state/t_0.300000s.h5" "$tmp/refiltered.toml" --out "$tmp/x2" -q 2>&1); rc=$?
[ $rc -eq 2 ] && echo "$out" | grep -q "order 3" || fail "another filter order: exit $rc ($out)"

[ $failures -eq 0 ] && echo "state files: sensors.csv, interfaces.csv and summary.json survive a restart byte for byte"
exit $failures
