#!/usr/bin/env bash
# `blockdem motion`: facts, CSV files and errors, on the project's own samples (and on a real
# record when ../shared/data/ground-motions is present). Usage: test_motion_command.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1
source_dir=$2
samples=$source_dir/tests/data/records
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# Facts of a hand-made AT2 sample: 12 values, dt 0.01 s, PGA 0.012 g at 0.11 s.
"$blockdem" motion "$samples/legacy_pea.AT2" --out "$out/at2" --no-plot > "$out/at2.txt"
grep -q '^station     SAMPLE ARRAY #1$' "$out/at2.txt" || fail "station"
grep -q '^component   090$' "$out/at2.txt" || fail "component"
grep -q '^points      12$' "$out/at2.txt" || fail "points"
grep -qF 'PGA         -0.11768 m/s^2 (0.0120 g) at 0.1100 s' "$out/at2.txt" || { cat "$out/at2.txt"; fail "PGA line"; }
grep -q '^drift       as recorded' "$out/at2.txt" || fail "drift without correction"
grep -q 'baseline polynomial' "$out/at2.txt" || fail "drift with correction"
head -2 "$out/at2/spectrum.csv" | grep -q '^period_s,sd_m,psv_m_s,psa_m_s2,psa_g$' || fail "spectrum header"
[ "$(grep -c '^[0-9]' "$out/at2/spectrum.csv")" -eq 100 ] || fail "100 default periods"
[ "$(wc -l < "$out/at2/record.csv")" -eq 13 ] || fail "record.csv rows"

# Chosen periods, damping and method.
"$blockdem" motion "$samples/two_columns.csv" --out "$out/csv" --no-plot --periods 0 0.1 1 --damping 0.02 --method newmark > /dev/null
[ "$(grep -c '^[0-9]' "$out/csv/spectrum.csv")" -eq 3 ] || fail "3 periods"
grep -q 'damping ratio 0.02' "$out/csv/spectrum.csv" || fail "damping in header"
grep -q '^0,0,0,0.012,' "$out/csv/spectrum.csv" || fail "T = 0 gives the PGA"

# A values-only file needs units and dt; the error names the file and line, exit status 2.
set +e
"$blockdem" motion "$samples/values_only.txt" --out "$out/v" --no-plot > /dev/null 2> "$out/err.txt"
status=$?
set -e
[ $status -eq 2 ] || fail "exit status $status for missing units"
grep -q 'values_only.txt:1: the file does not state its units' "$out/err.txt" || { cat "$out/err.txt"; fail "error message"; }
"$blockdem" motion "$samples/values_only.txt" --units g --dt 0.01 --out "$out/v" --no-plot > /dev/null

# A malformed file: truncated AT2.
head -5 "$samples/legacy_pea.AT2" > "$out/cut.AT2"
set +e
"$blockdem" motion "$out/cut.AT2" --out "$out/c" --no-plot > /dev/null 2> "$out/err.txt"
status=$?
set -e
[ $status -eq 2 ] || fail "exit status $status for a truncated file"
grep -q 'cut.AT2:5: the record is truncated' "$out/err.txt" || { cat "$out/err.txt"; fail "truncated message"; }

# The figure, when matplotlib is there.
if /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then
  "$blockdem" motion "$samples/legacy_pea.AT2" --out "$out/fig" > /dev/null
  [ -s "$out/fig/motion.png" ] || fail "motion.png"
fi

# A real record when present.
real=$source_dir/../shared/data/ground-motions/peer-at2/IELC180.AT2
if [ -f "$real" ]; then
  "$blockdem" motion "$real" --out "$out/real" --no-plot > "$out/real.txt"
  grep -qF 'PGA         -3.06831 m/s^2 (0.3129 g) at 2.1500 s' "$out/real.txt" || { cat "$out/real.txt"; fail "El Centro PGA"; }
  grep -q '^D5-95       24.1000 s' "$out/real.txt" || fail "El Centro D5-95"
fi
echo "test_motion_command: ok"
