#!/usr/bin/env bash
# `blockdem run` with [[sensors]] and interfaces end to end (docs/outputs.md, "sensors.csv",
# "interfaces.csv"): the paper's sliding block with an accelerometer and an LVDT writes
# sensors.csv and interfaces.csv with their headers, the summary's interfaces agree with the
# LVDT, the figures plot the sensors, --force clears them, and bad sensor keys are named errors
# with exit status 2.
# Usage: test_sensors_output.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

scene=$tmp/sliding.toml
sed 's/^duration = 5.0 .*/duration = 2.0/' "$src/examples/paper/sliding.toml" > "$scene"
cat >> "$scene" <<'TOML'

[[sensors]]
name = "top"
body = "block"
point = [0.0, 0.1]
lowpass_hz = 50.0

[[sensors]]
name = "slip"
kind = "relative"
body = "block"
point = [-0.25, -0.1]
body2 = "table"
point2 = [-0.25, 0.1]
TOML

out=$("$bin" run "$scene" --out "$tmp/run" -q 2>&1) || fail "run failed: $out"
/usr/bin/python3 - "$tmp/run" <<'PY' || fail "sensors.csv, interfaces.csv or summary.json"
import json, sys
from pathlib import Path
run = Path(sys.argv[1])
lines = (run / "sensors.csv").read_text().splitlines()
comments = [l for l in lines if l.startswith("#")]
assert len(comments) == 3, comments
assert "m/s^2" in comments[0] and "gravity not included" in comments[0], comments[0]
assert "Butterworth low-pass 50 Hz, order 4" in comments[1] and "group delay" in comments[1], comments[1]
header = lines[len(comments)].split(",")
assert header == ["t", "top.ax", "top.ay", "top.vx", "top.vy", "top.x", "top.y", "slip.dx", "slip.dy"], header
rows = [list(map(float, l.split(","))) for l in lines[len(comments) + 1:]]
assert len(rows) == 2001, len(rows)   # 2 s at 1 ms, both ends
lvdt_final = rows[-1][7]
ilines = (run / "interfaces.csv").read_text().splitlines()
assert ilines[0].startswith("#"), ilines[0]
assert ilines[1] == "t,body_a,body_b,normal_force_n,shear_force_n,points,opening_m,slip_m,bonded_points,broken_points", ilines[1]
last = ilines[-1].split(",")
assert last[1:3] == ["table", "block"], last
assert abs(float(last[3]) - 9.81) < 0.5, last          # the block's weight, give or take its rattle
s = json.loads((run / "summary.json").read_text())
assert s["outputs"]["sensors"] == "sensors.csv" and s["outputs"]["interfaces"] == "interfaces.csv"
(i,) = s["interfaces"]["list"]
assert (i["body_a"], i["body_b"]) == ("table", "block"), i
assert abs(i["residual_slip_m"] - lvdt_final) < 5e-5, (i["residual_slip_m"], lvdt_final)
assert i["peak_abs_slip_m"] > 0.005, i
block = next(b for b in s["bodies"] if b["name"] == "block")
assert block["slid"] and block["judged_on"] == "table", block
assert block["slip_threshold_m"] >= 2 * block["peak_elastic_shear_displacement_m"], block
assert "elastic_slip_factor" in s["outcome_thresholds"] and "slid_rule" in s["outcome_thresholds"]
PY

figs=$(/usr/bin/python3 "$src/tools/blockdem_figures.py" run "$tmp/run" --formats png --no-animation 2>&1) || fail "figures: $figs"
[ -s "$tmp/run/figures/sensors.png" ] || fail "no figures/sensors.png"

# Run again into the same folder without sensors and interfaces: --force clears the old files.
out=$("$bin" run "$src/examples/paper/sliding.toml" --out "$tmp/run" --force -q --set simulation.duration=0.1 \
      --set 'output.interfaces="none"' 2>&1) || fail "rerun failed: $out"
[ -e "$tmp/run/sensors.csv" ] && fail "sensors.csv of the earlier run was kept"
[ -e "$tmp/run/interfaces.csv" ] && fail "interfaces.csv of the earlier run was kept"

run_bad() {  # expected text, sed expression on the scenario
  sed "$2" "$scene" > "$tmp/bad.toml"
  local msg; msg=$("$bin" run "$tmp/bad.toml" --out "$tmp/bad" -q 2>&1); local rc=$?
  [ $rc -eq 2 ] || fail "$2: exit $rc, expected 2 ($msg)"
  expect_in "$msg" "$1"
}
run_bad "bad.toml:" 's/^body2 = "table"/body2 = "tabel"/'
run_bad "key 'sensors.slip.body2': no body is named 'tabel' (did you mean 'table'?)" 's/^body2 = "table"/body2 = "tabel"/'
run_bad "key 'sensors.top.point': [0, 0.3] m lies outside body 'block'" 's/^point = \[0.0, 0.1\]/point = [0.0, 0.3]/'
run_bad "key 'sensors.top.lowpass_hz': 6000 Hz is at or above the Nyquist frequency" 's/^lowpass_hz = 50.0/lowpass_hz = 6000.0/'
[ -e "$tmp/bad" ] && fail "a refused scenario wrote its folder"

[ $failures -eq 0 ] && echo "all sensor output checks passed"
exit $failures
