#!/usr/bin/env bash
# What a new user met (issue 12, part 6), end to end: --version; the undamped-contact warning;
# the unit of a sweep's target PGA; the scenario copy without rounding noise; history times at
# whole output intervals with a derived dt; `check` listing only the pairs that touch; and the
# messages for clockwise vertices, a folder given as the scenario, a binary record file and a
# vertical record component driving the table horizontally.
#   bash tests/cli/test_loose_ends.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1 src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
expect_not_in() { ! grep -qF -- "$2" <<<"$1" || fail "did not expect '$2' in: $1"; }
bad() {  # name, expected text, arguments...: exit status 2 and the text in the message
  local name=$1 want=$2; shift 2
  local msg; msg=$("$bin" "$@" 2>&1); local rc=$?
  [ $rc -eq 2 ] || fail "$name: exit $rc, expected 2 ($msg)"
  expect_in "$msg" "$want"
}

# A block dropped onto a table beside a far fixed wall; no dt (derived), no e.
cat > "$tmp/drop.toml" <<'EOF'
[simulation]
duration = 0.3
output_interval = 0.01
[contact]
kn = 1.0e6
ks = 1.0e6
mu = 0.3
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 2.0
height = 0.2
center = [0.0, -0.1]
[[bodies]]
name = "wall"
kind = "fixed"
shape = "rectangle"
width = 0.2
height = 1.0
center = [5.0, 0.5]
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.4
height = 0.2
center = [0.0, 0.1]
mass = 10.0
[[bodies]]
name = "falling"
shape = "rectangle"
width = 0.2
height = 0.2
center = [0.6, 0.5]
mass = 2.0
EOF

# 1. --version: the CMake project version (and the commit, in a git checkout).
version=$(grep -oP 'project\(blockdem VERSION \K[0-9.]+' "$src/CMakeLists.txt")
out=$("$bin" --version 2>&1) || fail "--version exits $?"
expect_in "$out" "blockdem $version"
commit=$(sed -n 's/.*(commit \([0-9a-f]*\)).*/\1/p' <<<"$out")
if [ -n "$commit" ]; then git -C "$src" cat-file -e "$commit^{commit}" 2>/dev/null || fail "--version names no commit of the repository: $out"; fi

# 2. No e and no h_n: the run and check warn, naming h_n = 0; giving e silences it.
out=$("$bin" run "$tmp/drop.toml" --out "$tmp/drop" -q 2>&1) || fail "drop run: $out"
expect_in "$out" "WARNING: contact: neither e (restitution) nor h_n"
expect_in "$out" "so h_n = 0 is used"
grep -q "neither e (restitution) nor h_n" "$tmp/drop/summary.json" || fail "summary.json lacks the damping warning"
out=$("$bin" check "$tmp/drop.toml" 2>&1); expect_in "$out" "so h_n = 0 is used"
out=$("$bin" check "$tmp/drop.toml" --set contact.e=0.5 2>&1); expect_not_in "$out" "neither e"
out=$("$bin" check "$tmp/drop.toml" --set contact.h_n=0 2>&1); expect_not_in "$out" "neither e"

# 3. The scenario copy holds the values as typed (toml++ wrote 0.29999999999999999).
grep -qx "mu = 0.3" "$tmp/drop/scenario.toml" || fail "scenario.toml: $(grep mu "$tmp/drop/scenario.toml")"
grep -q "0000000\|9999999" "$tmp/drop/scenario.toml" && fail "rounding noise in scenario.toml: $(grep '0000000\|9999999' "$tmp/drop/scenario.toml")"

# 4. A derived dt divides output_interval: history rows at 0, 0.01, ..., 0.3 exactly.
times=$(cut -d, -f1 "$tmp/drop/history.csv" | tail -n +2 | tr '\n' ' ')
want=$(awk 'BEGIN { for (n = 0; n <= 30; n++) printf "%s ", n / 100 }')
[ "$times" = "$want" ] || fail "history times: $times"

# 5. check lists the dashpots of the pairs touching at the start, not of every pair.
out=$("$bin" check "$tmp/drop.toml" --set contact.e=0.5 2>&1)
dashpots=$(sed -n '/^dashpots of/,/^contact period/p' <<<"$out")
expect_in "$dashpots" "table / block: 2 points"
expect_not_in "$dashpots" "wall"
expect_in "$dashpots" "touching nothing at the start (falls or flies until it meets a body): falling"

# 6. One unit rule for target PGAs: a sweep's levels must name their unit.
bad "target pga without unit" "--target-pga needs --target-pga-unit (m/s^2, gal or g)" \
  sweep "$tmp/drop.toml" --out "$tmp/sweep" --records "$tmp" --target-pga 0.3

# 7. Clockwise vertices: the message says so and numbers the vertices as written. (A concave
# outline is a body since issue 13: the wedge has a straight corner at vertex 2 instead.)
cat "$tmp/drop.toml" > "$tmp/wedge.toml"
cat >> "$tmp/wedge.toml" <<'EOF'
[[bodies]]
name = "wedge"
shape = "polygon"
vertices = [[-0.9, 0.0], [-0.9, 0.5], [-0.7, 0.25], [-0.5, 0.0]]
density = 2000.0
EOF
bad "clockwise straight corner" "not strictly convex at vertex 2 (-0.7, 0.25) m" check "$tmp/wedge.toml"
bad "clockwise straight corner" "the vertices are listed clockwise" check "$tmp/wedge.toml"
bad "collinear" "the vertices enclose no area" check "$tmp/wedge.toml" \
  --set 'bodies.wedge.vertices=[[-0.9, 0.0], [-0.8, 0.0], [-0.7, 0.0]]'

# 8. A folder given as the scenario.
bad "folder" "is a folder, not a scenario file: give one of the scenarios in it (collision.toml, rocking.toml, sliding.toml)" \
  run "$src/examples/paper" --out "$tmp/x"

# 9. A binary file as a record: a ZIP download and random bytes.
cat > "$tmp/record.toml" <<'EOF'
[simulation]
duration = 0.1
[contact]
kn = 1.0e6
ks = 1.0e6
mu = 0.3
e = 0.5
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 2.0
height = 0.2
center = [0.0, -0.1]
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.4
height = 0.2
center = [0.0, 0.1]
mass = 10.0
[table_motion.horizontal]
type = "record"
file = "download.AT2"
EOF
printf 'PK\003\004\024\000\000\000\010\000' > "$tmp/download.AT2"; head -c 300 /dev/urandom >> "$tmp/download.AT2"
bad "zip as AT2" "a binary file, not a PEER AT2 text record" check "$tmp/record.toml"
bad "zip as AT2" "ZIP archive" check "$tmp/record.toml"
bad "binary motion" "a binary file" motion "$tmp/download.AT2" --out "$tmp/m"

# 10. A vertical component under [table_motion.horizontal] is refused; accept_vertical allows it.
{ echo "PEER NGA STRONG MOTION DATABASE RECORD"
  echo "Test event, 1/1/2000, Station, UP"
  echo "ACCELERATION TIME HISTORY IN UNITS OF G"
  echo "NPTS=   10, DT=   .0100 SEC"
  echo "  .1000000E-01  .2000000E-01  .1000000E-01  .0000000E+00 -.1000000E-01"
  echo " -.2000000E-01 -.1000000E-01  .0000000E+00  .1000000E-01  .0000000E+00"; } > "$tmp/download.AT2"
bad "vertical as horizontal" "the record's component is 'UP', a vertical one" check "$tmp/record.toml"
out=$("$bin" check "$tmp/record.toml" --set table_motion.horizontal.accept_vertical=true 2>&1) || fail "accept_vertical: $out"
sed 's/table_motion.horizontal/table_motion.vertical/' "$tmp/record.toml" > "$tmp/vertical.toml"
out=$("$bin" check "$tmp/vertical.toml" 2>&1) || fail "a vertical record under [table_motion.vertical]: $out"

# 11. docs/scenario.md lists every [[assemblies]] key that src/io/assembly_keys.cpp reads
# ([settling]'s keys have their own section).
section=$(sed -n '/^## \[\[assemblies\]\]/,/^## \[table_motion\]/p' "$src/docs/scenario.md")
[ -n "$section" ] || fail "docs/scenario.md has no [[assemblies]] section"
for key in $(grep -oP '(?:\.|->)(?:string|optional_string|positive|optional_positive|number|number_or|boolean_or|whole_number|whole_number_or|optional_vec2|vec2_list|table_array|optional_table|has|choice)\("\K[a-z_]+' \
             "$src/src/io/assembly_keys.cpp" | sort -u); do
  case $key in assemblies | settling | kinetic_ratio | window | max_time | friction) continue ;; esac
  grep -qF "\`$key\`" <<<"$section" || grep -qF "assemblies.$key" <<<"$section" || fail "docs/scenario.md [[assemblies]] lacks \`$key\`"
done

[ $failures -eq 0 ] && echo "loose ends: all checks passed"
[ $failures -eq 0 ]
