#!/usr/bin/env bash
# The settling stage in 3-D (world/settling_3d.hpp, [settling] as in 2-D): a stack of three
# 24 kg boxes laid exactly touching on the table settles before t = 0, and at t = 0 each joint is
# closed by its load over its 4 corner points: the bottom one by 3 m g / (4 kn), the middle by
# 2 m g / (4 kn), the top by m g / (4 kn) (the closed form of springs in series; asserted to 1 %
# of the smallest closure); summary.json reports the settling; a run saved at T/2 and restarted
# is the same bytes as the straight run (the restart does not settle again, the state keeps the
# record); Ctrl-C while settling stops with exit 130 and nothing written; settled once and saved at t = 0 (--save-state 0), the stack shaken from that state
# ([simulation] initial_state, settle once, shake many times) is the same bytes as the run that
# settled itself; a missing initial state is refused naming the file; a settling that cannot finish in max_time stops the run with exit 3 naming the body;
# an unknown [settling] key is refused with exit 2 naming it.
# Usage: test_settling_3d.sh BLOCKDEM
set -u
bin=$(realpath "$1")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

cat > "$tmp/stack.toml" <<'TOML'
dimension = 3
[simulation]
duration = 0.1
output_interval = 0.01
[contact]
kn = 1e8
ks = 1e8
mu = 0.6
e = 0.5
[settling]
[[bodies]]
name = "table"
kind = "driven"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "b1"
shape = "box"
size = [0.4, 0.3, 0.2]
position = [0.0, 0.0, 0.1]
density = 1000.0
[[bodies]]
name = "b2"
shape = "box"
size = [0.4, 0.3, 0.2]
position = [0.0, 0.0, 0.3]
density = 1000.0
[[bodies]]
name = "b3"
shape = "box"
size = [0.4, 0.3, 0.2]
position = [0.0, 0.0, 0.5]
density = 1000.0
[table_motion.x]
type = "sine"
amplitude = 0.05
unit = "g"
period = 0.5
TOML

"$bin" run "$tmp/stack.toml" --out "$tmp/whole" -q --threads 1 >"$tmp/log" 2>&1 || fail "the settled stack failed: $(cat "$tmp/log")"
/usr/bin/python3 - "$tmp/whole" <<'PY' || fail "the settled stack's closures"
import csv, json, sys
run = sys.argv[1]
s = json.load(open(f"{run}/summary.json"))
settling = s["settling"]
assert settling is not None and settling["steps"] > 0 and settling["friction"] == "held", settling
assert settling["kinetic_ratio"] < 1e-8, settling
first = next(csv.DictReader(open(f"{run}/history.csv")))
assert float(first["t_s"]) == 0.0
m, g, kn = 0.4 * 0.3 * 0.2 * 1000.0, 9.81, 1e8
d = [3 * m * g / (4 * kn), 2 * m * g / (4 * kn), m * g / (4 * kn)]
expected = [0.1 - d[0], 0.3 - d[0] - d[1], 0.5 - d[0] - d[1] - d[2]]
for name, z in zip(("b1", "b2", "b3"), expected):
    got = float(first[f"{name}.z_m"])
    assert abs(got - z) < 0.01 * d[2], (name, got, z, d)
energy = list(csv.DictReader(open(f"{run}/energy.csv")))
assert float(energy[0]["kinetic_J"]) == 0.0, energy[0]   # it starts from rest where it settled
PY

"$bin" run "$tmp/stack.toml" --out "$tmp/first" -q --threads 1 --save-state 0.05 >"$tmp/log" 2>&1 || fail "the saving run failed: $(cat "$tmp/log")"
"$bin" run --restart "$tmp/first/state/t_0.050000s.h5" --out "$tmp/second" -q --threads 2 >"$tmp/log" 2>&1 \
    || fail "the restart failed: $(cat "$tmp/log")"
for f in history.csv energy.csv summary.json; do
    cmp -s "$tmp/whole/$f" "$tmp/second/$f" || fail "$f differs between the straight run and the restarted one"
done

# Settle once (a run of one step, saved at t = 0), then shake from the state.
sed 's/^duration = 0.1/duration = 0.001/' "$tmp/stack.toml" > "$tmp/settle.toml"
"$bin" run "$tmp/settle.toml" --out "$tmp/settle" -q --save-state 0 >"$tmp/log" 2>&1 || fail "settle once: $(cat "$tmp/log")"
sed -e 's/^\[settling\]$//' -e 's#^\[simulation\]$#[simulation]\ninitial_state = "settle/state/t_0.000000s.h5"#' "$tmp/stack.toml" > "$tmp/shake.toml"
"$bin" run "$tmp/shake.toml" --out "$tmp/shake" -q --threads 1 >"$tmp/log" 2>&1 || fail "shake from the state: $(cat "$tmp/log")"
for f in history.csv energy.csv; do
    cmp -s "$tmp/whole/$f" "$tmp/shake/$f" || fail "$f from the initial state differs from the run that settled itself"
done
grep -q '"initial_state"' "$tmp/shake/run_info.json" || fail "run_info.json does not name the initial state"
sed -e 's/^\[settling\]$//' -e 's#^\[simulation\]$#[simulation]\ninitial_state = "nowhere.h5"#' "$tmp/stack.toml" > "$tmp/missing.toml"
"$bin" run "$tmp/missing.toml" --out "$tmp/missing" -q >"$tmp/log" 2>&1
rc=$?
[[ $rc -eq 2 ]] && grep -q "nowhere.h5" "$tmp/log" && grep -q "simulation.initial_state" "$tmp/log" \
    || fail "a missing initial state: exit $rc, $(cat "$tmp/log")"

"$bin" run "$tmp/stack.toml" --out "$tmp/short" -q --set settling.window=0.001 --set settling.max_time=0.002 >"$tmp/log" 2>&1
rc=$?
[[ $rc -eq 3 ]] && grep -q "did not settle within 0.002 s: body 'b" "$tmp/log" || fail "a settling cut short: exit $rc, $(cat "$tmp/log")"

"$bin" run "$tmp/stack.toml" --out "$tmp/bad" -q --set settling.kinetic_rato=1e-6 >"$tmp/log" 2>&1
rc=$?
[[ $rc -eq 2 ]] && grep -q "kinetic_rato" "$tmp/log" || fail "an unknown [settling] key: exit $rc, $(cat "$tmp/log")"
"$bin" run "$tmp/stack.toml" --out "$tmp/bad2" -q --set settling.kinetic_ratio=-1 >"$tmp/log" 2>&1
rc=$?
[[ $rc -eq 2 ]] && grep -q "settling.kinetic_ratio': must be > 0" "$tmp/log" || fail "a negative [settling] value: exit $rc, $(cat "$tmp/log")"

# Ctrl-C while the model settles (a window far longer than the run allows): the run stops with the
# stop's exit status (130), says nothing was written, and leaves no output folder behind.
"$bin" run "$tmp/stack.toml" --out "$tmp/stopped" -q --set settling.window=1000 --set settling.max_time=10000 >"$tmp/log" 2>&1 &
pid=$!
sleep 1
kill -INT $pid
wait $pid
rc=$?
[[ $rc -eq 130 ]] && grep -q "stopped while the model settled" "$tmp/log" && grep -q "nothing was written" "$tmp/log" \
    || fail "Ctrl-C while settling: exit $rc, $(cat "$tmp/log")"
[[ -e "$tmp/stopped/summary.json" ]] && fail "a run stopped while settling left a summary"

[[ $failures -eq 0 ]] && echo "test_settling_3d: all passed"
exit $((failures > 0))
