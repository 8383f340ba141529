#!/usr/bin/env bash
# Concave polygon bodies (issue 13, section 4), end to end: an L-shaped block on a table is
# checked and run, its VTK output draws the outline (6 corners), not its convex parts; outlines
# that cannot be one body are refused with exit status 2, the file, the body and the vertices
# named: a self-crossing outline, a keyhole (a hole cut in through a slit), a repeated vertex, a
# straight corner, no area.
#   bash tests/cli/test_concave_polygon.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
bad() {  # name, expected text, arguments...: exit status 2 and the text in the message
  local name=$1 want=$2; shift 2
  local msg; msg=$("$bin" "$@" 2>&1); local rc=$?
  [ $rc -eq 2 ] || fail "$name: exit $rc, expected 2 ($msg)"
  expect_in "$msg" "$want"
}

cat > "$tmp/l.toml" <<'TOML'
[simulation]
duration = 0.05
output_interval = 0.01
[contact]
kn = 1.0e8
ks = 1.0e8
mu = 0.6
e = 0.3
[output]
vtk = true
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 2.0
height = 0.2
center = [0.0, -0.1]
[[bodies]]
name = "ell"
shape = "polygon"
vertices = [[0.0, 0.0], [0.4, 0.0], [0.4, 0.15], [0.1, 0.15], [0.1, 0.8], [0.0, 0.8]]
density = 2500.0
TOML
out=$("$bin" check "$tmp/l.toml" 2>&1) || fail "check of the L block: $out"
out=$("$bin" run "$tmp/l.toml" --out "$tmp/run" 2>&1) || fail "run of the L block: $out"
vtp=$(ls "$tmp"/run/vtk/bodies_*.vtp 2>/dev/null | tail -1)
if [ -z "$vtp" ]; then
  fail "no VTK file in $(ls -R "$tmp/run" | head -20)"
else
  # 4 table corners + 6 outline corners.
  grep -q 'NumberOfPoints="10"' "$vtp" || fail "the VTK file should hold the 10 outline corners: $(grep -o 'NumberOfPoints="[0-9]*"' "$vtp" | head -1)"
fi

set_vertices() { echo "bodies.ell.vertices=$1"; }
out=$("$bin" check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.8], [0.1, 0.8], [0.1, 0.15], [0.4, 0.15], [0.4, 0.0], [0.0, 0.0]]')" 2>&1) ||
  fail "an L listed clockwise is a body: $out"
bad "self-crossing" "the edge from vertex 0 to vertex 1 crosses the edge from vertex 3 to vertex 4: the outline crosses itself" \
  check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.0], [0.4, 0.0], [0.4, 0.3], [0.2, 0.3], [0.3, -0.1]]')"
bad "self-crossing names the body" "ell" \
  check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.0], [0.4, 0.0], [0.4, 0.3], [0.2, 0.3], [0.3, -0.1]]')"
# A square with a square hole, reached through a slit along y = 0.2 from the left side.
keyhole='[[0.0, 0.0], [0.4, 0.0], [0.4, 0.4], [0.0, 0.4], [0.0, 0.2], [0.1, 0.2], [0.1, 0.3], [0.3, 0.3], [0.3, 0.1], [0.1, 0.1], [0.1, 0.2], [0.0, 0.2]]'
bad "keyhole" "a hole cut in through a slit (a keyhole) is not supported" check "$tmp/l.toml" --set "$(set_vertices "$keyhole")"
bad "keyhole vertices" "vertices 4 and 11 coincide at (0, 0.2) m" check "$tmp/l.toml" --set "$(set_vertices "$keyhole")"
bad "repeated vertex" "vertices 3 and 4 coincide" \
  check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.0], [0.4, 0.0], [0.4, 0.15], [0.1, 0.15], [0.1, 0.15], [0.1, 0.8], [0.0, 0.8]]')"
bad "straight corner" "straight corner at vertex 4 (0.1, 0.5) m" \
  check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.0], [0.4, 0.0], [0.4, 0.15], [0.1, 0.15], [0.1, 0.5], [0.1, 0.8], [0.0, 0.8]]')"
bad "clockwise concave" "straight corner at vertex 2 (0.1, 0.5) m" \
  check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.8], [0.1, 0.8], [0.1, 0.5], [0.1, 0.15], [0.4, 0.15], [0.4, 0.0], [0.0, 0.0]]')"
bad "clockwise concave" "the vertices are listed clockwise" \
  check "$tmp/l.toml" --set "$(set_vertices '[[0.0, 0.8], [0.1, 0.8], [0.1, 0.5], [0.1, 0.15], [0.4, 0.15], [0.4, 0.0], [0.0, 0.0]]')"

# Restart: an L and a Pi block (touching the table through both legs) on a shaken table, saved
# at T/2 and restarted to T at another thread count, write the same files as the run straight
# to T (the state file keeps the contact table's parts).
cat > "$tmp/shaken.toml" <<'TOML'
[simulation]
duration = 0.4
output_interval = 0.01
[contact]
kn = 1.0e8
ks = 1.0e8
mu = 0.4
e = 0.5
[output]
interfaces = "all"
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 3.0
height = 0.2
center = [0.0, -0.1]
density = 1000.0
[[bodies]]
name = "ell"
shape = "polygon"
vertices = [[0.0, 0.0], [0.4, 0.0], [0.4, 0.15], [0.1, 0.15], [0.1, 0.8], [0.0, 0.8]]
density = 2500.0
[[bodies]]
name = "pi"
shape = "polygon"
vertices = [[-1.0, 0.0], [-0.9, 0.0], [-0.9, 0.2], [-0.7, 0.2], [-0.7, 0.0], [-0.6, 0.0], [-0.6, 0.3], [-1.0, 0.3]]
density = 2500.0
[table_motion.horizontal]
type = "sine"
amplitude = 0.6
unit = "g"
period = 0.3
TOML
"$bin" run "$tmp/shaken.toml" --out "$tmp/full" -q --threads 1 --save-state 0.2 > /dev/null 2>&1 || fail "shaken run"
state=$(ls "$tmp"/full/state/t_*.h5 2>/dev/null | head -1)
if [ -z "$state" ]; then
  fail "no state file"
else
  "$bin" run --restart "$state" --out "$tmp/restarted" -q --threads 2 > /dev/null 2>&1 || fail "restart"
  for f in history.csv energy.csv interfaces.csv summary.json; do
    cmp -s "$tmp/full/$f" "$tmp/restarted/$f" || fail "restart: $f differs"
  done
fi
# The Pi block's interface with the table sums its two legs: 4 points while it stands.
grep -q "table,pi\|pi,table" "$tmp/full/interfaces.csv" 2>/dev/null || head -2 "$tmp/full/interfaces.csv" | grep -q "pi" ||
  fail "interfaces.csv does not follow the Pi block: $(head -2 "$tmp/full/interfaces.csv")"

# check: one line per body pair however the table orders its part pairs. The Pi block (listed
# first) meets the table with its two legs and the lintel with its parts' tops, so its table
# entries alternate table, lintel, table, lintel; the pi / table line counts both legs' 4 points,
# each with the dashpot of M / 4 (C_n = 2 h sqrt(M kn / 4), h = 0.358 for e = 0.3 and M = 200 kg).
cat > "$tmp/pi_lintel.toml" <<'TOML'
[simulation]
duration = 0.05
output_interval = 0.01
[contact]
kn = 1.0e8
ks = 1.0e8
mu = 0.6
e = 0.3
[[bodies]]
name = "pi"
shape = "polygon"
vertices = [[0.0, 0.0], [0.1, 0.0], [0.1, 0.2], [0.3, 0.2], [0.3, 0.0], [0.4, 0.0], [0.4, 0.3], [0.0, 0.3]]
density = 2500.0
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 2.0
height = 0.2
center = [0.2, -0.1]
[[bodies]]
name = "lintel"
shape = "rectangle"
width = 0.4
height = 0.1
center = [0.2, 0.35]
density = 2500.0
TOML
out=$("$bin" check "$tmp/pi_lintel.toml" 2>&1) || fail "check of the Pi block under a lintel: $out"
expect_in "$out" "pi / table: 4 points, M = 200 kg; C_n = 5.061e+04"
[ "$(grep -c 'pi / table' <<<"$out")" -eq 1 ] || fail "one line for the Pi block on the table: $out"
[ "$(grep -c 'pi / lintel' <<<"$out")" -eq 1 ] || fail "one line for the Pi block under the lintel: $out"

[ $failures -eq 0 ] && echo "concave polygons: all checks passed"
[ $failures -eq 0 ]
