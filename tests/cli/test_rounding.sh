#!/usr/bin/env bash
# End-to-end: [contact] rounding (docs/scenario.md). A rounded block rocks and the run ends
# normally; a rounding of a quarter of a body's least width or more is refused with exit status
# 2, naming the file, the body and the key; `bench --rounding` runs the wall with rounded bricks.
# Usage: test_rounding.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

cat > "$tmp/block.toml" <<'TOML'
[simulation]
duration = 0.3
[contact]
kn = 1.0e8
ks = 1.0e8
mu = 0.6
e = 0.5
rounding = 0.002
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.4
center = [0.0, -0.2]
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.3
height = 1.0
center = [0.0, 0.53]
rotation_deg = 3.0
density = 2000.0
TOML
# (Tilted by 3 degrees and clear of the table at first: it drops onto a corner arc.)
"$bin" run "$tmp/block.toml" --out "$tmp/run" -q > "$tmp/run.log" 2>&1 || fail "rounded run failed: $(cat "$tmp/run.log")"
[ -s "$tmp/run/history.csv" ] || fail "no history.csv from the rounded run"

out=$("$bin" run "$tmp/block.toml" --set contact.rounding=0.075 --out "$tmp/bad" -q 2>&1)
status=$?
[ "$status" -eq 2 ] || fail "rounding of a quarter of the block's width: exit status $status, expected 2 ($out)"
expect_in "$out" "block.toml"
expect_in "$out" "body 'block'"
expect_in "$out" "[contact] rounding = 0.075 m"

out=$("$bin" bench --scene wall --sizes 100 --threads 1 --warmup 5 --work 1e3 --repeats 1 --rounding 0.0002 2>&1) ||
    fail "bench --rounding failed: $out"
expect_in "$out" "| wall | 100 | 1 |"

[ "$failures" -eq 0 ] && echo "all rounding CLI checks passed"
exit $((failures > 0))
