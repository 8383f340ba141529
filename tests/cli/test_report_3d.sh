#!/usr/bin/env bash
# `blockdem report` on a 3-D run folder: the outcome table holds summary.json's numbers, the
# .vtp reader gives back the bodies where summary.json has them, the figures are made and in the
# page (check_report_3d.py); without VTK frames the report is still made and says what it lacks.
# Usage: test_report_3d.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
source_dir=$src
source "$src/tests/cli/view_deps.sh"
need_package python3-matplotlib /usr/bin/python3 -c "import matplotlib, numpy"

out=$tmp/topple
"$bin" run "$src/tests/cli/data/report_3d.toml" --out "$out" -q > "$tmp/run.log" 2>&1 || fail "run: $(tail -2 "$tmp/run.log")"
"$bin" report "$out" > "$tmp/report.log" 2>&1 || fail "report: $(tail -3 "$tmp/report.log")"
/usr/bin/python3 "$src/tests/cli/check_report_3d.py" "$out" "$src/tools" || fail "the report against the run's files"
grep -q "What this report cannot show" "$out/report.html" && fail "a complete 3-D run has nothing to declare"
# The animation (figures/animation.mp4 through ffmpeg; GIF without it): one frame per 1/25 s of
# the run, on the page.
movie=$(ls "$out/figures/"animation.* 2>/dev/null | head -1)
[ -s "$movie" ] || fail "no animation file in $out/figures"
grep -q "id='figure-animation'" "$out/report.html" || fail "the page does not show the animation"
if [[ "$movie" == *.mp4 ]]; then
    frames=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 "$movie")
    expected=$(/usr/bin/python3 -c "import json; print(int(json.load(open('$out/summary.json'))['time_s'] * 25 + 1e-9) + 1)")
    [ "$frames" = "$expected" ] || fail "the animation has $frames frames, not $expected (25 per simulated second)"
fi
# The page's script draws every zoomable plot (headless Chromium, where Debian's is installed).
if [ -x /usr/bin/chromium ] && [ -f /usr/share/javascript/dygraphs/dygraph.min.js ]; then
  plots=$(/usr/bin/python3 -c 'import json, re, sys
page = open(sys.argv[1], encoding="utf-8").read()
print(len(json.loads(re.search(r"id=\"report-data\">(.*?)</script>", page, re.S).group(1))["plots"]))' "$out/report.html")
  timeout 120 /usr/bin/chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=5000 --dump-dom \
    "file://$out/report.html" 2>/dev/null | grep -q "data-plots-drawn=\"$plots\"" || fail "the page did not draw its $plots plots"
fi

# No VTK frames: no pictures, said on stderr and in the page; everything else is there.
bare=$tmp/bare
"$bin" run "$src/tests/cli/data/report_3d.toml" --out "$bare" -q --set output.vtk=false --set simulation.duration=0.3 \
  > "$tmp/bare.log" 2>&1 || fail "run without frames: $(tail -2 "$tmp/bare.log")"
# (the tool itself, PNG only: the slow part of a report is writing each figure twice)
/usr/bin/python3 "$src/tools/blockdem_report.py" "$bare" --formats png > "$tmp/bare_report.log" 2>&1 || fail "report without frames: $(tail -3 "$tmp/bare_report.log")"
grep -q "note: No VTK frames" "$tmp/bare_report.log" || fail "no note on the missing frames"
grep -q "What this report cannot show" "$bare/report.html" || fail "the page does not say the frames are missing"
grep -q "id='outcome-table'" "$bare/report.html" || fail "no outcome table without frames"
[ -e "$bare/figures/snapshots.png" ] && fail "pictures without frames"

# [output] report = true: `blockdem run` makes the report at the end of a 3-D run too.
"$bin" run "$src/examples/3d/drum_column.toml" --out "$tmp/with_report" --set simulation.duration=0.05 \
    --set output.report=true -q > "$tmp/with_report.log" 2>&1 || fail "a 3-D run with [output] report: $(tail -3 "$tmp/with_report.log")"
grep -q "report: .*/report.html" "$tmp/with_report.log" && [ -s "$tmp/with_report/report.html" ] \
    || fail "[output] report = true made no report.html: $(tail -3 "$tmp/with_report.log")"

# A 2-D figure tool on a 3-D folder says where its figures are, with exit status 2.
/usr/bin/python3 "$src/tools/blockdem_figures.py" run "$out" > "$tmp/figures.log" 2>&1
status=$?
[ $status -eq 2 ] || fail "blockdem_figures.py on a 3-D run: exit $status, not 2"
grep -q "a 3-D run: these figures are 2-D" "$tmp/figures.log" || fail "blockdem_figures.py: $(tail -2 "$tmp/figures.log")"

[ $failures -eq 0 ] && echo "the 3-D report matches its run"
exit $failures
