#!/usr/bin/env bash
# The subcommands' options refuse what would waste or lose the work, before it starts, with exit
# status 2 and the option named: numbers that are not finite or out of range (CLI11's own checks
# let nan and inf through and printed a 300-digit bound), an ensemble of 1e8 runs (ran out of
# memory), an output folder that is empty ("--out ''" wrote nowhere and said it had) or a file,
# an output file in a folder that does not exist (refused after the fit had run), a sweep key
# varied twice (two columns, the last winning) or none of whose values can be read; and
# `--set dimension`, which was ignored (the dimension is chosen from the file before --set);
# export --time nan or -5 (took t = 0); a settling window longer than its max_time (failed late).
# Usage: test_option_checks.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
source "$(dirname "$0")/refusal_setup.sh" "$@"

scenario=$work/rock.toml
sed 's/^duration = .*/duration = 0.05/' "$source_dir/examples/paper/rocking.toml" > "$scenario"
touch "$work/a_file"

expect_refused "'foo' is not a blockdem command; the commands are run, check," foo
expect_refused "--rtol: 'nan' is not a finite number above 0" converge "$scenario" --out "$work/cv" --rtol nan
expect_refused "--rtol: '0' is not a finite number above 0" converge "$scenario" --out "$work/cv" --rtol 0
expect_refused "--floor-rotation: 'inf' is not a finite number above 0" converge "$scenario" --out "$work/cv" --floor-rotation inf
expect_refused "--ensemble: '100000000' is not a whole number from 0 to 1000" converge "$scenario" --out "$work/cv" --ensemble 100000000
expect_refused "--threads: '-3' is not a whole number from 1 to 4096" run "$scenario" --out "$work/r" --threads -3
expect_refused "--save-state-every: 'nan' is not a finite number above 0" run "$scenario" --out "$work/r" --save-state-every nan
expect_refused "--out: an output folder must be named" run "$scenario" --out ""
expect_refused "--out: '$work/a_file' is a file, not a folder" run "$scenario" --out "$work/a_file"
expect_refused "--out: an output folder must be named" converge "$scenario" --out ""
expect_refused "--out: '$work/a_file' is a file, not a folder" motion "$source_dir/tests/data/records/legacy_pea.AT2" --out "$work/a_file"
expect_refused "--damping: 'nan' is not a finite number from 0 to 0.99" motion "$source_dir/tests/data/records/legacy_pea.AT2" --damping nan
expect_refused "its folder '$work/no_such_folder' does not exist" calibrate --toml "$work/no_such_folder/keys.toml"
expect_refused "--threads: '-3' is not a whole number from 1 to 4096" sweep "$scenario" --out "$work/sw" --vary contact.mu=0.5 --threads -3
expect_refused "key '--set dimension=3': the dimension is the scenario file's own" run "$scenario" --out "$work/r" --set dimension=3
expect_refused "key '--set dimension=4': the dimension is the scenario file's own" \
  run "$source_dir/examples/3d/drum_column.toml" --out "$work/r" --set dimension=4
"$blockdem" run "$scenario" --out "$work/done" -q > /dev/null
expect_refused "--time: 'nan' is not a finite number of at least 0" export "$work/done" --dxf "$work/x.dxf" --time nan
expect_refused "--time: '-5' is not a finite number of at least 0" export "$work/done" --dxf "$work/x.dxf" --time -5
cp "$scenario" "$work/settle.toml" && printf '\n[settling]\nwindow = 5\nmax_time = 1\n' >> "$work/settle.toml"
expect_refused "key 'settling.window': the window, 5 s, is longer than max_time, 1 s" check "$work/settle.toml"
# A place with no space at all is named as such (it blamed simulation.duration).
if [ -d /proc ]; then
  expect_refused "/proc/blockdem_out: the output folder's disk has no free space (0 B)" run "$scenario" --out /proc/blockdem_out
fi
[ ! -e "$work/r" ] && [ ! -e "$work/cv" ] || fail "a refused command left an output folder"

expect_refused "the key 'contact.mu' is varied twice" sweep "$scenario" --out "$work/sw" --vary contact.mu=0.5 --vary contact.mu=0.6
expect_refused "key 'nosuch.key': no value of the varied key can be read into the scenario" \
  sweep "$scenario" --out "$work/sw" --vary nosuch.key=1,2
expect_refused "key 'contact.mu': no value of the varied key can be read into the scenario" \
  sweep "$scenario" --out "$work/sw" --vary contact.mu=abc
[ ! -e "$work/sw" ] || fail "a refused sweep left its folder"
# A value that fails alone is recorded with its case, as before.
"$blockdem" sweep "$scenario" --out "$work/sw" --vary contact.mu=abc,0.5 -q > "$work/sweep.log"
grep -q "2 cases, 2 done (1 failed or bad input)" "$work/sweep.log" || { cat "$work/sweep.log"; fail "sweep with one bad value"; }
expect_refused "the range 0:1:nan holds a value that is not a finite number" sweep "$scenario" --out "$work/sw3" --vary contact.mu=0:1:nan
expect_refused "$work: a folder, not a case list" sweep "$scenario" --out "$work/sw3" --cases "$work"
"$blockdem" run "$source_dir/examples/3d/drum_column.toml" --out "$work/run3" -q --set simulation.duration=0.02 > /dev/null 2>&1
expect_refused "$work/run3: a 3-D run: its drawings are 2-D" export "$work/run3" --dxf "$work/x3.dxf"
# A first value failing on another axis's key does not condemn this axis.
"$blockdem" sweep "$scenario" --out "$work/sw2" --vary contact.mu=-1,0.5 --vary simulation.duration=0.01,0.02 -q > "$work/sweep2.log"
grep -q "4 cases, 4 done (2 failed or bad input)" "$work/sweep2.log" || { cat "$work/sweep2.log"; fail "sweep of two axes"; }
echo "option checks: all refused with their option named"
