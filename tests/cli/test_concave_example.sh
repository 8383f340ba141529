#!/usr/bin/env bash
# examples/concave runs as its README says: the L block rocks at 0.47 g (its threshold about
# the stem's corner is 0.431 g), the portal frame stands (0.516 g), so the example cannot rot.
#   bash tests/cli/test_concave_example.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

out=$("$bin" run "$src/examples/concave/concave_blocks.toml" --out "$tmp/run" -q 2>&1) || fail "run: $out"
outcome() {
  /usr/bin/python3 -c "import json, sys; s = json.load(open(sys.argv[1])); \
print([b['outcome'] for b in s['bodies'] if b['name'] == sys.argv[2]][0])" "$tmp/run/summary.json" "$1"
}
[ "$(outcome ell)" = "rocked" ] || fail "the L block should rock: $(outcome ell)"
[ "$(outcome portal)" = "stable" ] || fail "the portal should stand: $(outcome portal)"
# It rocks about the corner under its stem (its left, x = -1 m) while the table accelerates
# towards +x: counter-clockwise, above 0.003 rad (half its peak); its clockwise turns (the
# bounces of its impacts; the other corner needs 0.98 g) stay below a fifth of that.
peak=$(/usr/bin/python3 -c "import csv, sys; rot = [float(r['ell.rot']) for r in csv.DictReader(open(sys.argv[1]))]; \
print(max(rot) > 0.003 and -min(rot) < max(rot) / 5)" "$tmp/run/history.csv")
[ "$peak" = "True" ] || fail "the L block should rock counter-clockwise, past 0.003 rad"

[ $failures -eq 0 ] && echo "concave example: all checks passed"
[ $failures -eq 0 ]
