#!/usr/bin/env bash
# `blockdem check` on 3-D scenarios (docs/3d.md, "Checking a scenario"): each example under
# examples/3d is valid (exit 0) and its check prints the bodies, the contact, the start's pairs,
# the derived quantities per body, the time step and the three table components; the stable bound
# it prints is the one the run's start check uses (summary.json's critical_dt_s of the same
# scenario run for 0.01 s), and so is the chosen dt. The drum column's numbers against hand
# values. Bad input exits with status 2 naming the file and the key or the bodies.
# Usage: test_check_3d.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

# 1. Every 3-D example: valid, every section printed, the bound and dt those of the run.
for scenario in "$src"/examples/3d/*.toml; do
    name=$(basename "$scenario" .toml)
    if grep -q "shared/data" "$scenario" && [[ ! -d "$src/../shared/data" ]]; then
        echo "skipping $name: its records (../shared/data) are absent"
        continue
    fi
    out=$("$bin" check "$scenario" 2>&1); status=$?
    [[ $status -eq 0 ]] || { fail "$name: check exited $status: $out"; continue; }
    for section in ": valid (3-D)" "bodies (" "contact parameters" "dashpots of the pairs touching at the start" \
        "per dynamic body: overturning tilt" "time step: dt = " "table motion:" "  x: " "  y: " "  z: "; do
        expect_in "$out" "$section"
    done
    "$bin" run "$scenario" --out "$tmp/$name" --set simulation.duration=0.01 --set output.vtk=false -q \
        >"$tmp/$name.txt" 2>&1 || { fail "$name: the short run failed: $(cat "$tmp/$name.txt")"; continue; }
    printf '%s\n' "$out" >"$tmp/$name.check"
    /usr/bin/python3 - "$tmp/$name/summary.json" "$name" "$tmp/$name.check" <<'PY' || fail "$name: check and run disagree"
import json, re, sys
summary = json.load(open(sys.argv[1]))
text = open(sys.argv[3]).read()
run_bound = summary["critical_dt_s"]
dt = float(re.search(r"time step: dt = (\S+) s", text).group(1))
# dt is printed to 4 digits.
assert abs(dt - summary["dt_s"]) <= 5e-4 * summary["dt_s"], (sys.argv[2], dt, summary["dt_s"])
if run_bound is None:
    assert "no stable limit at the start" in text, (sys.argv[2], "the run has no bound, the check prints one")
else:
    # The bound is printed to 6 digits.
    check_bound = float(re.search(r"stable limit (\S+) s", text).group(1))
    assert abs(check_bound - run_bound) <= 5e-6 * run_bound, (sys.argv[2], check_bound, run_bound)
print(f"{sys.argv[2]}: dt {dt:.4g} s, bound {run_bound} s (check and run agree)")
PY
done

# 2. The drum column by hand: a 16-sided prism of radius 0.3 m, 0.5 m high, 2700 kg/m^3 has
# mass 2700 x 0.5 x 8 x 0.3^2 sin(2 pi / 16) = 372.0 kg; on the table (driven) its pair's M is
# its own mass; its 16 corners turn by 2 pi / 16, each a share 1/4 of kn, W = 4; the pair's
# dashpots C_n = 2 h_n sqrt(M kn W) in all with e = 0.3 -> h_n = 0.3579; two equal drums share
# M = 186.0 kg; the overturning tilt atan(0.3 cos(pi / 16) / 0.25) = 0.8665 rad; the static
# overlap 372.0 x 9.81 / (4 x 1e8) = 9.12e-6 m.
out=$("$bin" check "$src/examples/3d/drum_column.toml" 2>&1)
/usr/bin/python3 -c '
import math, re, sys
text = sys.stdin.read()
m = 2700 * 0.5 * 8 * 0.3**2 * math.sin(2 * math.pi / 16)
h_n = 0.3579
line = re.search(r"table / drum_1: 16 points, M = (\S+) kg; C_n = (\S+), C_s = (\S+) N s/m", text)
assert line, text
assert abs(float(line.group(1)) - m) < 5e-4 * m, (line.group(1), m)
cn = 2 * h_n * math.sqrt(m * 1e8 * 4)
cs = 2 * 0.3 * math.sqrt(m * 1e8 * 4)
assert abs(float(line.group(2)) - cn) < 5e-4 * cn, (line.group(2), cn)
assert abs(float(line.group(3)) - cs) < 5e-4 * cs, (line.group(3), cs)
pair = re.search(r"drum_1 / drum_2: 16 points, M = (\S+) kg", text)
assert pair and abs(float(pair.group(1)) - m / 2) < 5e-4 * m, pair
tilt = re.search(r"drum_1: overturns at a tilt of (\S+) rad", text)
assert abs(float(tilt.group(1)) - math.atan(0.3 * math.cos(math.pi / 16) / 0.25)) < 1e-4, tilt.group(1)
overlap = re.search(r"drum_1: .* static overlap (\S+) m on 16 corners", text)
assert abs(float(overlap.group(1)) - m * 9.81 / (4 * 1e8)) < 5e-3 * m * 9.81 / (4 * 1e8), overlap.group(1)
assert re.search(r"x: sine .* peak 3.432 m/s\^2 \(0.35 g\)", text)
' <<<"$out" || fail "the drum column's numbers"

# 3. Bad input: exit 2, the file and the key or the bodies named.
cat > "$tmp/box.toml" <<'TOML'
dimension = 3
[simulation]
duration = 0.01
[contact]
kn = 1e6
ks = 1e6
mu = 0.5
[[bodies]]
name = "table"
kind = "fixed"
shape = "box"
size = [2.0, 2.0, 0.2]
position = [0.0, 0.0, -0.1]
[[bodies]]
name = "block"
shape = "box"
size = [0.4, 0.4, 0.8]
position = [0.0, 0.0, 0.4]
density = 2000.0
TOML
out=$("$bin" check "$tmp/box.toml" 2>&1) || fail "the minimal box: $out"
expect_in "$out" "block: overturns at a tilt of 0.4636 rad"  # atan(0.2 / 0.4)
sed 's/^size = \[0.4, 0.4, 0.8\]/sise = [0.4, 0.4, 0.8]/' "$tmp/box.toml" >"$tmp/bad.toml"
out=$("$bin" check "$tmp/bad.toml" 2>&1); status=$?
[[ $status -eq 2 ]] || fail "unknown key: exit status $status, expected 2: $out"
expect_in "$out" "bad.toml"
expect_in "$out" "sise"
sed 's/^position = \[0.0, 0.0, 0.4\]/position = [0.0, 0.0, 0.35]/' "$tmp/box.toml" >"$tmp/overlap.toml"
out=$("$bin" check "$tmp/overlap.toml" 2>&1); status=$?
[[ $status -eq 2 ]] || fail "overlap at start: exit status $status, expected 2: $out"
expect_in "$out" "overlap.toml"
expect_in "$out" "'table' and 'block'"
out=$("$bin" check "$tmp/box.toml" --set simulation.dt=1e-2 2>&1); status=$?
[[ $status -eq 2 ]] || fail "dt above the bound: exit status $status, expected 2: $out"
expect_in "$out" "stable limit"

[ $failures -eq 0 ] && echo "all 3-D check tests passed"
exit $((failures > 0))
