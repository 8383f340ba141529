#!/usr/bin/env bash
# End-to-end: the outcome word of 3-D bodies (world/response_monitor_3d.hpp; the 2-D words and
# rule of world/outcome.hpp), each scene chosen so that the closed form says what must happen:
#   rocked:   a 0.4 x 1.0 x 1.6 m box under a one-sine pulse of 0.3 g, T = 1 s, along x: above
#             the uplift at g b / h = 0.25 g and below Housner's overturning threshold, 0.309 g
#             (README, 3-D rows: it rocks back from 0.10 rad); mu 0.8 > 0.3, so it does not slide;
#   slid:     a squat 1.0 x 1.0 x 0.2 m block, mu 0.2, under a 0.5 g sine: it slides (a > mu g)
#             (6 cm in 1 s) and cannot rock (that needs a > g b / h = 5 g);
#   fell:     a 0.2 x 0.2 x 0.1 m block on a 0.3 m wide pier, mu 0.1, under a 0.6 g, 1 s sine: it
#             slides off the pier's edge (0.05 m away; Newmark's slip is tens of cm a cycle) and
#             drops 0.5 m onto the table, which never held it up;
#   left_model: the fell scene without the table (below);
#   overturned: the slender block of test_run_3d.sh (0.2 x 0.2 x 1 m, 0.6 g one-sine pulse);
#   the collapse by assembly: a slender and a squat drum column on one table (below);
# [outcomes] thresholds are read in 3-D (a large rocking_ratio makes the rocking box "stable").
# A column in free fall beside the table is warned of; a model with nothing to move is refused.
# Usage: test_outcomes_3d.sh BLOCKDEM
set -u
bin=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

table='[[bodies]]
name = "table"
kind = "driven"
shape = "box"
size = [6.0, 6.0, 0.2]
position = [0.0, 0.0, -0.1]'

cat > "$tmp/rocked.toml" <<TOML
dimension = 3
[simulation]
duration = 2.0
[contact]
kn = 1e8
ks = 1e8
mu = 0.8
e = 0.5
$table
[[bodies]]
name = "box"
shape = "box"
size = [0.4, 1.0, 1.6]
position = [0.0, 0.0, 0.8]
density = 2000.0
[table_motion.x]
type = "one_sine"
amplitude = 0.3
unit = "g"
period = 1.0
TOML

cat > "$tmp/slid.toml" <<TOML
dimension = 3
[simulation]
duration = 1.0
[contact]
kn = 1e8
ks = 1e8
mu = 0.2
e = 0.5
$table
[[bodies]]
name = "slab"
shape = "box"
size = [1.0, 1.0, 0.2]
position = [0.0, 0.0, 0.1]
density = 2000.0
[table_motion.x]
type = "sine"
amplitude = 0.5
unit = "g"
period = 0.5
TOML

cat > "$tmp/fell.toml" <<TOML
dimension = 3
[simulation]
duration = 2.0
[contact]
kn = 1e7
ks = 1e7
mu = 0.1
e = 0.3
$table
[[bodies]]
name = "pier"
kind = "driven"
shape = "box"
size = [0.3, 0.3, 0.5]
position = [0.0, 0.0, 0.25]
[[bodies]]
name = "block"
shape = "box"
size = [0.2, 0.2, 0.1]
position = [0.0, 0.0, 0.55]
density = 2000.0
[table_motion.x]
type = "sine"
amplitude = 0.6
unit = "g"
period = 1.0
TOML

cat > "$tmp/overturned.toml" <<TOML
dimension = 3
[simulation]
duration = 3.0
[contact]
kn = 1e7
ks = 1e7
mu = 0.8
e = 0.5
$table
[[bodies]]
name = "slender"
shape = "box"
size = [0.2, 0.2, 1.0]
position = [0.0, 0.0, 0.5]
density = 2000.0
[table_motion.y]
type = "one_sine"
amplitude = 0.6
unit = "g"
period = 0.8
TOML

for scene in rocked slid fell overturned; do
    "$bin" run "$tmp/$scene.toml" --out "$tmp/$scene" -q >"$tmp/$scene.txt" 2>&1 || fail "$scene failed: $(cat "$tmp/$scene.txt")"
    /usr/bin/python3 - "$tmp/$scene/summary.json" "$scene" <<'PY' || fail "the $scene scene's summary"
import json, sys
s = json.load(open(sys.argv[1]))
scene = sys.argv[2]
body = [b for b in s["bodies"] if b["kind"] == "dynamic"][0]
assert body["outcome"] == scene, (scene, body["outcome"], body)
assert body["failed"] == (scene in ("fell", "overturned")), body
t = body["outcome_time_s"]
assert t is not None and 0.0 < t <= s["time_s"], body
collapse = s["collapse"][0]
assert collapse["group"] == "all" and collapse["blocks"] == 1, collapse
assert collapse["fell"] == (1 if scene == "fell" else 0) and collapse["overturned"] == (1 if scene == "overturned" else 0), collapse
if scene == "rocked":
    assert body["peak_tilt_rad"] > 0.01 * body["overturning_angle_rad"] and not body["overturned"], body
    assert body["supporters"] == ["table"], body["supporters"]
if scene == "slid":
    assert body["peak_base_slip_m"] > 0.02 and body["peak_tilt_rad"] < 0.01 * body["overturning_angle_rad"], body
if scene == "fell":
    assert body["supporters"] == ["pier"] and body["touches_a_supporter"] is False, body
    assert body["final_drop_m"] > 0.4, body["final_drop_m"]
    assert len(body["fell"]["position_m"]) == 3, body["fell"]
if scene == "overturned":
    assert t == body["overturning_time_s"], body
PY
done
grep -qF "box: rocked (from t = " "$tmp/rocked.txt" || "$bin" run "$tmp/rocked.toml" --out "$tmp/rocked2" 2>&1 | grep -qF "box: rocked (from t = " \
    || fail "the run's line does not name the outcome"

# left_model: the fell scene without the table under the pier. Nothing can catch the block, so
# once its box is wholly below the derived extent (the pier's bottom less one body diagonal,
# 0.3 m) it is taken out: frozen, its energy moved to removed_with_bodies_leaving, the ledger
# closed. Restarted from a state saved before it left and from one saved after, the run writes
# the same bytes as the run straight through. A given domain that misses a body is refused.
sed '/^name = "table"/,/^position = \[0.0, 0.0, -0.1\]/d; s/^\[\[bodies\]\]$/[[bodies]]/' "$tmp/fell.toml" \
    | awk 'BEGIN { skip = 0 } /^\[\[bodies\]\]$/ { if (prev == "[[bodies]]") next } { print; prev = $0 }' >"$tmp/left.toml"
grep -q '"table"' "$tmp/left.toml" && fail "the left scene still has the table"
"$bin" run "$tmp/left.toml" --out "$tmp/left" --save-state 1.0,1.5 >"$tmp/left.txt" 2>&1 || fail "left failed: $(cat "$tmp/left.txt")"
grep -qF "block: LEFT THE MODEL at t = " "$tmp/left.txt" || fail "the run's line does not say LEFT THE MODEL: $(cat "$tmp/left.txt")"
/usr/bin/python3 - "$tmp/left/summary.json" "$tmp/left/history.csv" <<'PY' || fail "the left scene's summary"
import csv, json, sys
s = json.load(open(sys.argv[1]))
body = [b for b in s["bodies"] if b["kind"] == "dynamic"][0]
assert body["outcome"] == "left_model" and body["failed"], body
d = s["domain"]
assert d["from"] == "derived" and d["hi_m"][2] is None, d
assert abs(d["margin_m"] - (0.2**2 + 0.2**2 + 0.1**2) ** 0.5) < 1e-12, d
assert abs(d["lo_m"][2] - (0.0 - d["margin_m"])) < 1e-12, d        # the pier's bottom, less the margin
(left,) = d["left"]
assert left["body"] == "block" and body["left_model"]["time_s"] == left["time_s"] == body["outcome_time_s"], (left, body)
assert left["position_m"][2] < d["lo_m"][2], left                   # below the extent (its box wholly so)
assert left["velocity_m_s"][2] < 0.0, left
e = s["energy_j"]
g, m = 9.81, body["mass_kg"]
v2 = sum(x * x for x in left["velocity_m_s"])
removed = 0.5 * m * v2 + m * g * left["position_m"][2]               # + its turning energy, small
assert abs(e["removed_with_bodies_leaving"] - removed) < 0.05 * abs(removed) + 1.0, (e, removed)
assert e["kinetic"] == 0.0, e                                        # the only body is frozen
assert s["collapse"][0]["left_model"] == 1, s["collapse"]
assert e["balance_error_relative"] < 1e-3, e
# frozen: the rows after it left keep its position
rows = list(csv.DictReader(open(sys.argv[2])))
after = [r for r in rows if float(r["t_s"]) > left["time_s"] + 1e-3]
assert len(after) > 10 and len({r["block.z_m"] for r in after}) == 1, after[:2]
assert abs(float(after[0]["block.z_m"]) - left["position_m"][2]) < 1e-12
PY
for state in 1.000000 1.500000; do
    "$bin" run --restart "$tmp/left/state/t_${state}s.h5" --out "$tmp/left_$state" -q >"$tmp/log" 2>&1 \
        || fail "restart at $state s failed: $(cat "$tmp/log")"
    for f in history.csv energy.csv; do
        cmp -s "$tmp/left/$f" "$tmp/left_$state/$f" || fail "restarted at $state s (the body left at 1.24 s): $f differs"
    done
done
"$bin" run "$tmp/left.toml" --out "$tmp/bad_domain" -q --set 'simulation.domain=[[-1.0, -1.0, -1.0], [1.0, 1.0, 0.5]]' \
    >"$tmp/bad.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "simulation.domain" "$tmp/bad.txt" && grep -q "does not contain body 'block'" "$tmp/bad.txt" \
    || fail "a domain that misses a body: $(cat "$tmp/bad.txt")"
"$bin" run "$tmp/left.toml" --out "$tmp/bad_domain2" -q --set 'simulation.domain=[[1.0, -1.0, -1.0], [-1.0, 1.0, 2.0]]' \
    >"$tmp/bad.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "simulation.domain': the first corner must be below the second" "$tmp/bad.txt" \
    || fail "an inverted domain: $(cat "$tmp/bad.txt")"
"$bin" run "$tmp/left.toml" --out "$tmp/bad_domain3" -q --set 'simulation.domain="big"' >"$tmp/bad.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "simulation.domain': must be a list of \[x, y, z\] points in m" "$tmp/bad.txt" \
    || fail "a domain that is not a list: $(cat "$tmp/bad.txt")"
"$bin" run "$tmp/left.toml" --out "$tmp/bad_domain4" -q --set 'simulation.domain=[[-1.0, -1.0], [1.0, 1.0]]' \
    >"$tmp/bad.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "simulation.domain': point 0 must be three numbers" "$tmp/bad.txt" \
    || fail "a 2-D domain in 3-D: $(cat "$tmp/bad.txt")"
#    A given domain: the block leaves as soon as its box is wholly below z = -0.2 m.
"$bin" run "$tmp/left.toml" --out "$tmp/given" -q --set 'simulation.domain=[[-1.0, -1.0, -0.2], [1.0, 1.0, 1.0]]' \
    >"$tmp/log" 2>&1 || fail "a given domain: $(cat "$tmp/log")"
/usr/bin/python3 -c "
import json
s = json.load(open('$tmp/given/summary.json'))
d = s['domain']
assert d['from'] == 'scenario' and d['hi_m'] == [1.0, 1.0, 1.0] and d['margin_m'] == 0.0, d
assert d['left'][0]['position_m'][2] < -0.2 and d['left'][0]['time_s'] < json.load(open('$tmp/left/summary.json'))['domain']['left'][0]['time_s']
" || fail "a given domain is not the extent"

# [outcomes] in 3-D: a rocking ratio above the box's peak tilt over its limit reads "stable".
"$bin" run "$tmp/rocked.toml" --out "$tmp/ratio" -q --set outcomes.rocking_ratio=0.9 >/dev/null 2>&1 || fail "[outcomes] in 3-D refused"
/usr/bin/python3 -c "
import json, sys
b = json.load(open('$tmp/ratio/summary.json'))['bodies'][1]
assert b['outcome'] == 'stable', b['outcome']
s = json.load(open('$tmp/ratio/summary.json'))
assert s['outcome_thresholds']['rocking_ratio'] == 0.9
" || fail "outcomes.rocking_ratio not used in 3-D"
"$bin" run "$tmp/rocked.toml" --out "$tmp/bad" -q --set outcomes.rocking_rato=0.9 >"$tmp/bad.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "rocking_rato" "$tmp/bad.txt" || fail "an unknown [outcomes] key is not refused by name: $(cat "$tmp/bad.txt")"
"$bin" run "$tmp/rocked.toml" --out "$tmp/bad2" -q --set outcomes.slip_ratio=-1 >"$tmp/bad2.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "outcomes.slip_ratio': must be >= 0" "$tmp/bad2.txt" || fail "a negative [outcomes] value: $(cat "$tmp/bad2.txt")"

# Collapse by assembly: two drum columns on one table, each its own group, then "all".
#   slender: two drums 0.08 m across, 0.8 m tall in all (tan alpha = 0.1): a 0.6 g one-sine
#            pulse is six times the uplift acceleration g tan(alpha), far above Housner's
#            overturning threshold for this size and period: it must lose its blocks;
#   squat:   two drums 0.6 m across, 0.2 m tall in all: uplift needs g b / h = 3 g and sliding
#            mu g = 0.8 g, both above 0.6 g: nothing of it may fail.
cat > "$tmp/columns.toml" <<TOML
dimension = 3
[simulation]
duration = 2.0
output_interval = 0.01
[contact]
kn = 1e7
ks = 1e7
mu = 0.8
e = 0.3
h_s = 0.3
[[bodies]]
name = "table"
kind = "driven"
shape = "box"
size = [3.0, 1.5, 0.2]
position = [0.0, 0.0, -0.1]
[[assemblies]]
name = "slender"
type = "drum_column"
drums = 2
sides = 8
radius = 0.04
height = 0.4
base = [-0.8, 0.0, 0.0]
density = 2700.0
[[assemblies]]
name = "squat"
type = "drum_column"
drums = 2
sides = 8
radius = 0.3
height = 0.1
base = [0.8, 0.0, 0.0]
density = 2700.0
[table_motion.x]
type = "sine"
amplitude = 0.6
unit = "g"
frequency = 2.0
cycles = 1
TOML
"$bin" run "$tmp/columns.toml" --out "$tmp/columns" --save-state 1.0 >"$tmp/columns.txt" 2>&1 \
    || fail "two columns: $(cat "$tmp/columns.txt")"
/usr/bin/python3 - "$tmp/columns/summary.json" <<'PY' || fail "the collapse groups of two columns"
import json, sys
c = {g["group"]: g for g in json.load(open(sys.argv[1]))["collapse"]}
assert list(c) == ["slender", "squat", "all"], list(c)
assert c["slender"]["blocks"] == 2 and c["squat"]["blocks"] == 2 and c["all"]["blocks"] == 4, c
failed = lambda g: g["fell"] + g["overturned"] + g["left_model"]
assert failed(c["slender"]) >= 1 and c["slender"]["first_to_go"].startswith("slender_"), c["slender"]
assert failed(c["squat"]) == 0 and c["squat"]["first_to_go"] is None and c["squat"]["displaced_mass_fraction"] == 0.0, c["squat"]
for k in ("fell", "overturned", "left_model"):
    assert c["all"][k] == c["slender"][k] + c["squat"][k], (k, c)
assert c["all"]["first_to_go"] == c["slender"]["first_to_go"], c
assert 0.0 < c["all"]["displaced_mass_fraction"] < c["slender"]["displaced_mass_fraction"], c
PY
grep -q "^assembly slender: " "$tmp/columns.txt" && grep -q "^assembly squat: 0 of 2 blocks fell, 0 overturned" "$tmp/columns.txt" \
    && grep -q "^all blocks: " "$tmp/columns.txt" || fail "the console's collapse lines: $(cat "$tmp/columns.txt")"

# An assembly named "all" (the group of every block) or two named alike are refused by name.
sed 's/name = "squat"/name = "all"/' "$tmp/columns.toml" > "$tmp/all.toml"
"$bin" run "$tmp/all.toml" --out "$tmp/all" -q >"$tmp/all.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "'all' names the collapse summary of every block" "$tmp/all.txt" \
    || fail "an assembly named all: $(cat "$tmp/all.txt")"
sed 's/name = "squat"/name = "slender"/' "$tmp/columns.toml" > "$tmp/twice.toml"
"$bin" run "$tmp/twice.toml" --out "$tmp/twice" -q >"$tmp/twice.txt" 2>&1
[[ $? -eq 2 ]] && grep -q "another assembly is named 'slender'" "$tmp/twice.txt" \
    || fail "two assemblies named alike: $(cat "$tmp/twice.txt")"
# Restarted at 1 s (the assemblies come back from the scenario), the same collapse groups.
"$bin" run --restart "$tmp/columns/state/t_1.000000s.h5" --out "$tmp/columns_restart" -q >"$tmp/restart.txt" 2>&1 \
    || fail "the columns' restart: $(cat "$tmp/restart.txt")"
/usr/bin/python3 -c "
import json
a, b = (json.load(open(f'$tmp/{d}/summary.json'))['collapse'] for d in ('columns', 'columns_restart'))
assert a == b, (a, b)
" || fail "the collapse groups after a restart differ"

# A two-drum column placed beside the table (nothing under it) falls for 0.3 s: the drums touch
# each other, never the ground, and the lower one was reported stable after falling 0.44 m.
# Both are named in the summary's warnings and on the console.
cat > "$tmp/beside.toml" <<TOML
dimension = 3
[simulation]
duration = 0.3
[contact]
kn = 1e8
ks = 1e8
mu = 0.6
e = 0.3
$table
[[assemblies]]
name = "d"
type = "drum_column"
radius = 0.3
height = 0.5
base = [50.0, 0.0, 0.0]
density = 2700.0
drums = 2
TOML
"$bin" run "$tmp/beside.toml" --out "$tmp/beside" >"$tmp/beside.txt" 2>&1 || fail "a column beside the table: $(cat "$tmp/beside.txt")"
/usr/bin/python3 - "$tmp/beside/summary.json" <<'PY' || fail "the warnings of a column in free fall"
import json, sys
w = json.load(open(sys.argv[1]))["warnings"]
falling = [x for x in w if "touched other bodies but never rested, directly or through them, on a fixed or driven body" in x]
assert len(falling) == 2 and "'d_1'" in falling[0] and "'d_2'" in falling[1], w
PY
grep -q "body 'd_1' touched other bodies but never rested" "$tmp/beside.txt" || fail "the console's warning: $(cat "$tmp/beside.txt")"

# A model where nothing moves (a rock mass whose blocks are all ground) is refused by name.
cat > "$tmp/still.toml" <<TOML
dimension = 3
[simulation]
duration = 0.01
dt = 1e-4
[contact]
kn = 1e8
ks = 1e8
mu = 0.8
e = 0.2
$table
TOML
"$bin" run "$tmp/still.toml" --out "$tmp/still" -q >"$tmp/still.txt" 2>&1
[[ $? -eq 2 ]] && grep -qF "still.toml: the model has no dynamic body (0 fixed, 1 driven), so nothing would move" "$tmp/still.txt" \
    || fail "a model with nothing to move: $(cat "$tmp/still.txt")"

# A box thrown at 1e200 m/s leaves at once with an infinite energy: the run stops (exit 3) naming
# it, where it named the table as the fastest body.
cat > "$tmp/thrown.toml" <<TOML
dimension = 3
[simulation]
duration = 0.05
[contact]
kn = 1e7
ks = 1e7
mu = 0.6
e = 0.3
$table
[[bodies]]
name = "b"
shape = "box"
size = [0.2, 0.2, 0.4]
position = [0.0, 0.0, 0.2]
density = 2000.0
velocity = [1e200, 0.0, 0.0]
TOML
"$bin" run "$tmp/thrown.toml" --out "$tmp/thrown" -q >"$tmp/thrown.txt" 2>&1
echo "rc=$?" >> "$tmp/thrown.txt"
grep -q "^rc=3" "$tmp/thrown.txt" && grep -q "left the model at t = .* with a kinetic energy beyond the range of a number" "$tmp/thrown.txt" \
    || fail "a body thrown at 1e200 m/s: $(cat "$tmp/thrown.txt")"

[[ $failures -eq 0 ]] && echo "all 3-D outcome checks passed"
exit $((failures > 0))
