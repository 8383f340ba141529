#!/usr/bin/env bash
# End-to-end: `blockdem converge` on 3-D scenarios (docs/3d.md, "Convergence in 3-D"). The drum
# column example under its synthetic three-component sine motion (x 1 g here, so that the
# column rocks well above the 0.02 rad floor within 0.4 s) converges, with the 3-D summary's quantities in
# converge.json and converge.csv; with a tolerance far below the changes it does not, and the
# stiffness and ensemble runs scale the 3-D keys; bad input exits 2 naming the key before any run;
# a drop with no stable bound at the start runs; the record example (Northridge, three
# components) runs through the study when ../shared/data is present and is skipped otherwise.
# Usage: test_converge_3d.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
json() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }
column=$src/examples/3d/drum_column.toml

# 1. The column rocking (peak tilt about 0.13 rad at 0.35 s): converged, dt halved exactly.
study=$tmp/rocking
out=$("$bin" converge "$column" --out "$study" -q --set simulation.duration=0.4 --set table_motion.x.amplitude=1.0 2>&1); rc=$?
[ $rc -eq 0 ] || fail "converge exited $rc: $out"
expect_in "$out" "verdict: converged (3 bodies converged, 0 not converged, 0 chaotic"
expect_in "$out" "peak tilt [rad]"
expect_in "$out" "final |slip| [m]"
for run in dt dt_2 dt_4; do
  for f in summary.json history.csv energy.csv scenario.toml; do [ -f "$study/$run/$f" ] || fail "no $run/$f"; done
done
[ -d "$study/dt/vtk" ] || fail "the base run should keep the scenario's VTK frames"
[ ! -e "$study/dt_2/vtk" ] || fail "a follow-up run should write no VTK frames"
/usr/bin/python3 - "$study" <<'PY' || fail "converge.json/csv of the rocking column"
import csv, json, math, sys
study = sys.argv[1]
d = json.load(open(f"{study}/converge.json"))
assert d["verdict"] == "converged" and d["dimension"] == 3, (d["verdict"], d.get("dimension"))
assert "peak_tilt_rad" in d["quantities_3d"]["peak_rotation_rad"], d["quantities_3d"]
dts = [json.load(open(f"{study}/{r}/summary.json"))["dt_s"] for r in ("dt", "dt_2", "dt_4")]
assert dts[1] == dts[0] / 2 and dts[2] == dts[0] / 4, dts
assert [b["name"] for b in d["bodies"]] == ["drum_1", "drum_2", "drum_3"], d["bodies"]
for b in d["bodies"]:
    q = {x["quantity"]: x for x in b["dt"]}
    assert set(q) == {"peak_rotation_rad", "peak_slip_m", "final_slip_m", "overturning_time_s", "overturned", "outcome"}, set(q)
    # The tilt is judged, not hidden under its floor: it rocks.
    assert q["peak_rotation_rad"]["judged"] and min(q["peak_rotation_rad"]["values"]) > 0.05, q["peak_rotation_rad"]
    assert q["overturning_time_s"]["judged"] is False and q["overturned"]["values"] == ["no"] * 3
# Each value is the summary's own: the tilt, and the length of the slip vector.
for label, k in (("dt", 0), ("dt_4", 2)):
    s = json.load(open(f"{study}/{label}/summary.json"))
    top = s["bodies"][3]
    row = {x["quantity"]: x for x in d["bodies"][2]["dt"]}
    assert row["peak_rotation_rad"]["values"][k] == top["peak_tilt_rad"]
    assert row["peak_slip_m"]["values"][k] == top["peak_slip_m"]
    assert abs(row["final_slip_m"]["values"][k] - math.hypot(*top["slip_m"])) < 1e-15
    assert row["outcome"]["values"][k] == top["outcome"], (row["outcome"], top["outcome"])
rows = list(csv.DictReader(open(f"{study}/converge.csv")))
assert len(rows) == 18 and all(r["body_verdict"] == "converged" for r in rows), len(rows)
PY

# 2. A tolerance far below the changes (1e-7 with floors of 1e-9): not converged, by the same
#    rules; the stiffness runs scale the 3-D kn and ks, the ensemble perturbs 3-D gravity.
study=$tmp/strict
out=$("$bin" converge "$column" --out "$study" -q --set simulation.duration=0.2 --rtol 1e-7 --floor-rotation 1e-9 \
      --floor-slip 1e-9 --stiffness --ensemble 2 2>&1); rc=$?
[ $rc -eq 0 ] || fail "strict converge exited $rc (the verdict does not set the exit status): $out"
verdict=$(json "$study/converge.json" "d['verdict']")
[ "$verdict" = "not converged" ] || [ "$verdict" = chaotic ] || fail "strict verdict '$verdict': $out"
expect_in "$out" "NOT CONVERGED"
for run in kn_x0.5 kn_x2 ensemble_1 ensemble_2; do [ -f "$study/$run/summary.json" ] || fail "no $run/summary.json"; done
grep -q '^kn = 200000000' "$study/kn_x2/scenario.toml" || fail "kn_x2: $(grep '^kn' "$study/kn_x2/scenario.toml")"
grep -q '^ks = 50000000' "$study/kn_x0.5/scenario.toml" || fail "kn_x0.5: $(grep '^ks' "$study/kn_x0.5/scenario.toml")"
g1=$(grep '^gravity' "$study/ensemble_1/scenario.toml"); g2=$(grep '^gravity' "$study/ensemble_2/scenario.toml")
[ -n "$g1" ] && [ "$g1" != "$g2" ] || fail "ensemble gravity not perturbed: '$g1', '$g2'"

# 3. Bad input: exit 2 naming the key, nothing run.
msg=$("$bin" converge "$column" --out "$tmp/bad1" --set contact.muu=0.3 2>&1); rc=$?
[ $rc -eq 2 ] || fail "a misspelled key: exit $rc, expected 2: $msg"
expect_in "$msg" "did you mean 'mu'?"
[ ! -e "$tmp/bad1/dt" ] || fail "a refused study ran its base run"
msg=$("$bin" converge "$column" --out "$tmp/bad2" --set simulation.dt=0.01 2>&1); rc=$?
[ $rc -eq 2 ] || fail "dt above the stable bound: exit $rc, expected 2: $msg"
expect_in "$msg" "simulation.dt"
[ ! -e "$tmp/bad2/dt" ] || fail "a refused study ran its base run"
msg=$("$bin" converge "$column" --out "$tmp/bad3" --ensemble 2 --set simulation.gravity=0 2>&1); rc=$?
[ $rc -eq 2 ] || fail "gravity 0 with --ensemble: exit $rc, expected 2: $msg"
expect_in "$msg" "simulation.gravity"
msg=$("$bin" converge "$column" --out "$tmp/bad4" --report 2>&1); rc=$?
[ $rc -eq 2 ] || fail "--report on a 3-D study: exit $rc, expected 2: $msg"
expect_in "$msg" "--report"
[ ! -e "$tmp/bad4/dt" ] || fail "a refused study ran its base run"

# 4. A block dropped onto the table: no stable bound at the start (summary.json critical_dt_s
#    null), dt given; the study runs and says so.
cat > "$tmp/drop.toml" <<'TOML'
dimension = 3
[simulation]
duration = 0.15
dt = 1.0e-4
[contact]
kn = 1.0e7
ks = 1.0e7
mu = 0.5
e = 0.5
[[bodies]]
name = "block"
shape = "box"
size = [0.2, 0.2, 0.4]
position = [0.0, 0.0, 0.25]
density = 2000.0
TOML
out=$("$bin" converge "$tmp/drop.toml" --out "$tmp/drop" -q 2>&1); rc=$?
[ $rc -eq 0 ] || fail "drop converge exited $rc: $out"
expect_in "$out" "base dt = 0.0001 s (no stable limit at the start)"
expect_in "$out" "verdict: converged"
[ "$(json "$tmp/drop/converge.json" "d['critical_dt_s']")" = 0.0 ] || fail "critical_dt_s of a drop"

# 5. The record example, shortened: the three record components go through every run.
if [ -d "$src/../shared/data/ground-motions" ]; then
  study=$tmp/record
  out=$("$bin" converge "$src/examples/3d/drum_column_record.toml" --out "$study" -q --set simulation.duration=0.2 2>&1); rc=$?
  [ $rc -eq 0 ] || fail "record example converge exited $rc: $out"
  expect_in "$out" "verdict:"
  grep -q 'Rinaldi318.AT2' "$study/dt_4/scenario.toml" || fail "dt_4 did not run the record"
else
  echo "SKIP record example: ../shared/data is not present"
fi

[ $failures -eq 0 ] && echo "all 3-D converge checks passed"
exit $failures
