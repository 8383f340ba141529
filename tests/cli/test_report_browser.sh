#!/usr/bin/env bash
# The report in headless Chromium (Debian's chromium, driven by playwright-core from npm): the
# page loads with no console errors and no network request, the animation advances, the canvas
# shows the blocks, the zoomable plots and the figures are there. Made both ways: by
# `blockdem run` with [output] report = true, and by `blockdem report DIR`.
# Screenshots are kept in out/test-report/ for a person to look at.
#   bash tests/cli/test_report_browser.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1 source_dir=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
source "$source_dir/tests/cli/view_deps.sh"
need_package python3-matplotlib /usr/bin/python3 -c "import matplotlib, numpy"
need_package libjs-dygraphs test -f /usr/share/javascript/dygraphs/dygraph.min.js
need_package chromium test -x /usr/bin/chromium
need_package nodejs command -v node
need_package npm command -v npm
if ! "$source_dir/tests/cli/report_browser/install.sh" >"$work/npm.log" 2>&1; then
  cat "$work/npm.log"
  echo "SKIPPED: playwright-core could not be installed from npm"
  exit 0
fi
shots=$source_dir/out/test-report
mkdir -p "$shots/sliding" "$shots/two_drops"

"$blockdem" run "$source_dir/examples/paper/sliding.toml" --out "$work/sliding" -q \
  --set output.report=true --set output.vtk=false >"$work/run.log"
grep -q "report: $work/sliding/report.html" "$work/run.log" || { echo "FAIL: run did not report the report"; cat "$work/run.log"; exit 1; }
node "$source_dir/tests/cli/report_browser/check_report.mjs" "$work/sliding/report.html" "$shots/sliding" 4

# No driven table here (a fixed one) and a pentagon: the other code paths of the report.
"$blockdem" run "$source_dir/tests/cli/data/two_drops.toml" --out "$work/drops" -q --set output.vtk=false >/dev/null
"$blockdem" report "$work/drops" --no-animation --formats png >/dev/null
grep -q "time step: dt" "$work/drops/report.html" || { echo "FAIL: no derived parameters in the report"; exit 1; }
node "$source_dir/tests/cli/report_browser/check_report.mjs" "$work/drops/report.html" "$shots/two_drops" 4
echo "report checks passed; screenshots in $shots"
