#!/usr/bin/env bash
# Table motions refused at the start of a run with exit status 2 and a message naming the file,
# key or line: a start before t = 0 (2-D and 3-D), a period shorter than 4 time steps, a CSV
# motion with negative times, a row wider than its header or its time column read as
# acceleration, a record value beyond the range of a number in m/s^2, an amplitude beyond any
# table's (1e4 m/s^2) or overflowing. Each of these ran. And a title that is not a string.
# Also: a folder given as the file, one column named for both time and acceleration (reported
# as times that do not increase), a binary file (its bytes were echoed).
# Usage: test_motion_input.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/refusal_setup.sh" "$@"

rocking=$source_dir/examples/paper/rocking.toml
short=(--set simulation.duration=0.2 --out "$work/run")

expect_refused "key 'table_motion.horizontal.start': must be >= 0 [s], got -5: a motion starts at rest" \
  run "$rocking" "${short[@]}" --set table_motion.horizontal.start=-5
expect_refused "key 'table_motion.x.start': must be >= 0 [s], got -5" \
  run "$source_dir/examples/3d/drum_column.toml" "${short[@]}" --set table_motion.x.start=-5
expect_refused "key 'table_motion.horizontal.period': the period 1e-12 s spans 5e-08 time steps of dt = 2e-05 s; it must span at least 4" \
  run "$rocking" "${short[@]}" --set table_motion.horizontal.period=1e-12
# An amplitude beyond any table (a wrong unit, a typed exponent) or one that overflows in m/s^2:
# the first was run with its blocks left behind, the second reported as a time step too large.
expect_refused "key 'table_motion.horizontal.amplitude': gives a peak table acceleration of 1.961e+04 m/s^2 (2000 g), beyond the 10000 m/s^2" \
  run "$rocking" "${short[@]}" --set table_motion.horizontal.amplitude=2000 --set 'table_motion.horizontal.unit="g"'
expect_refused "key 'table_motion.horizontal.amplitude': gives a peak table acceleration beyond the range of a number" \
  run "$rocking" "${short[@]}" --set table_motion.horizontal.amplitude=1e308 --set 'table_motion.horizontal.unit="g"'
expect_refused "key 'table_motion.z.amplitude': gives a peak table acceleration of 2.942e+04 m/s^2 (3000 g)" \
  run "$source_dir/examples/3d/drum_column.toml" "${short[@]}" --set table_motion.z.amplitude=3000
# The title and description the report prints must be strings (title = 5 was shown as "5").
sed 's/^title = .*/title = 5/' "$rocking" > "$work/title.toml"
expect_refused "title.toml:7:9: key 'title': must be a string (in quotes)" check "$work/title.toml"

# The rocking scenario with its sine replaced by a CSV motion (or a record) of the given keys.
with_motion() {  # <name> <keys of [table_motion.horizontal]>
  sed '/^\[table_motion.horizontal\]/,$d' "$rocking" > "$work/$1.toml"
  printf '[table_motion.horizontal]\n%s\n' "$2" >> "$work/$1.toml"
}

printf 't,a\n-1,0\n-0.99,1\n-0.98,0\n' > "$work/negative.csv"
with_motion negative 'type = "csv"
file = "negative.csv"'
expect_refused "negative.csv:2: time -1 s is before 0: a motion starts at rest at its first sample" \
  run "$work/negative.toml" "${short[@]}"

printf 't,a\n0,0\n0.01,1,2\n0.02,1\n' > "$work/wide.csv"
with_motion wide 'type = "csv"
file = "wide.csv"'
expect_refused "wide.csv:3: this line has 3 columns but the header has 2" run "$work/wide.toml" "${short[@]}"

printf 't,a\n0,0\n0.01,1\n0.02,0\n' > "$work/timed.csv"
with_motion dt_time 'type = "csv"
file = "timed.csv"
dt = 0.01'
expect_refused "timed.csv:1: column selects column 0 ('t'), which by its header holds time, as the acceleration: pick the acceleration column with \`column\`" \
  run "$work/dt_time.toml" "${short[@]}"

printf 'time,acc[g]\n0.00,0.1\n0.01,0.2\n0.02,1e308\n0.03,0.3\n' > "$work/huge.csv"
with_motion huge 'type = "record"
file = "huge.csv"'
expect_refused "huge.csv:4: sample 3 (1e+308 in the file's units, 9.80665 m/s^2 each) is beyond the range of a number in m/s^2" \
  run "$work/huge.toml" "${short[@]}"

# A folder for a file, one column read as both time and acceleration, a binary file's bytes.
with_motion folder 'type = "csv"
file = "."'
expect_refused "a folder, not a time-series file" run "$work/folder.toml" "${short[@]}"
with_motion same_column 'type = "csv"
file = "timed.csv"
time_column = 1
column = 1'
expect_refused "key 'table_motion.horizontal.column': names the same column as time_column and column" \
  run "$work/same_column.toml" "${short[@]}"
printf 't,a\n0,\001\002\377\n' > "$work/binary.csv"
with_motion binary 'type = "csv"
file = "binary.csv"'
expect_refused "binary.csv:2: a field of bytes that are not text, not a number (is this a binary file?)" \
  run "$work/binary.toml" "${short[@]}"

echo "ok"
