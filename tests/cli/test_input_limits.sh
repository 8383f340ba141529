#!/usr/bin/env bash
# Every input path ends in a clear error and exit status 2 (issue 11, section 2): a record line of
# 40,000 characters (was a stack overflow, exit 139), NPTS = 1e18 (std::bad_alloc), a spectrum
# period of 1e-200 s (never ended), a CSV column "-1" (exit 139), a wall 1e9 m long (16.8 GB
# allocated), and a sweep over a folder holding such records (each case reports its error).
# Usage: test_input_limits.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1
source_dir=$2
samples=$source_dir/tests/data/records
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

source "$(dirname "$0")/expect_refused.sh"

knet_header() {  # <scale factor>
  printf 'Origin Time       2003/01/02 04:05:00\nLat.              35.0\nLong.             135.0\nDepth. (km)       10\n'
  printf 'Mag.              5.0\nStation Code      BAD001\nStation Lat.      35.1\nStation Long.     135.1\n'
  printf 'Station Height(m) 0\nRecord Time       2003/01/02 04:05:20\nSampling Freq(Hz) 4Hz\nDuration Time(s)  1\n'
  printf 'Dir.              N-S\nScale Factor      %s\nMax. Acc. (gal)   0.0\n' "$1"
  printf 'Last Correction   2003/01/02 04:05:05\nMemo.\n     1      2      3      4\n'
}

mkdir -p "$work/records"
knet_header "$(head -c 40000 /dev/zero | tr '\0' 3)(gal)/6182761" > "$work/records/long_scale.NS"
knet_header "3920(gal)/$(head -c 70000 /dev/zero | tr '\0' 7)" > "$work/records/too_long.NS"
printf 'PEER\nE, 1/2/2003, S, 90\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS= 1000000000000000000, DT= .0100 SEC\n 1 2 3\n' \
  > "$work/records/npts.AT2"
cp "$samples/legacy_pea.AT2" "$work/records/good.AT2"

expect_refused "long_scale.NS:14:19: Scale Factor '3333333333333333333333333333333333333333... (40013 characters)' has an invalid number" \
  motion "$work/records/long_scale.NS" --no-plot --out "$work/m"
expect_refused "too_long.NS:14: this line is 70028 characters long; a record line may have at most 65536" \
  motion "$work/records/too_long.NS" --no-plot --out "$work/m"
expect_refused "npts.AT2:4: NPTS = 1000000000000000000 exceeds the limit of 20000000" \
  motion "$work/records/npts.AT2" --no-plot --out "$work/m"
expect_refused "key '--periods': period 1e-200 s is outside 0.001 s to 100 s (0 gives the PGA)" \
  motion "$samples/legacy_pea.AT2" --no-plot --out "$work/m" --periods 0.1 1e-200

# Scenarios: the shared part, then the table motion or assembly under test.
scenario() {  # <name> <extra TOML>
  cat > "$work/$1.toml" <<EOF
[simulation]
duration = 0.01
dt = 1.0e-4
[contact]
kn = 1.0e7
ks = 1.0e7
mu = 0.6
e = 0.4
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]
density = 2400.0
$2
EOF
  echo "$work/$1.toml"
}
cp "$samples/two_columns.csv" "$work/"
expect_refused "key 'table_motion.horizontal.column': \"-1\" is neither a column name of" \
  check "$(scenario csv_column "$(printf '[table_motion.horizontal]\ntype = "csv"\nfile = "two_columns.csv"\nunit = "g"\ncolumn = "-1"')")"
expect_refused "key 'assemblies.b.length': the assembly would have about 1e+10 blocks" \
  check "$(scenario wall "$(printf '[[assemblies]]\ntype = "wall"\nname = "b"\ndensity = 2000.0\nlength = 1e9\ncourses = 2')")"
expect_refused "key 'assemblies.b.courses': must be a whole number from 1 to 100000000, got 1e+20" \
  check "$(scenario courses "$(printf '[[assemblies]]\ntype = "wall"\nname = "b"\ndensity = 2000.0\nlength = 2.0\ncourses = 1e20')")"

# A sweep over the folder: the good record runs, each bad one is a case with its error.
set +e
timeout 120 "$blockdem" sweep "$source_dir/studies/scenarios/pulse_block.toml" -q --threads 1 --records "$work/records" \
  --scale 1 --vary simulation.duration=0.05 --out "$work/sweep" > "$work/sweep.txt" 2>&1
status=$?
set -e
[ $status -ne 139 ] && [ $status -ne 124 ] || { cat "$work/sweep.txt"; fail "sweep exit status $status"; }
results=$work/sweep/results.csv
grep -q '^[0-9]*,0.05,good.AT2,1,completed,' "$results" || { cat "$results"; fail "good record not run"; }
grep -qF 'long_scale.NS,1,error,' "$results" || { cat "$results"; fail "long_scale.NS not reported"; }
grep -qF 'has an invalid number' "$results" || fail "long_scale.NS message"
grep -qF 'npts.AT2:4: NPTS = 1000000000000000000 exceeds the limit' "$results" || fail "npts.AT2 message"
grep -qF 'too_long.NS:14: this line is 70028 characters long' "$results" || fail "too_long.NS message"
echo "test_input_limits: ok"
