#!/usr/bin/env bash
# Figures for the paper's examples (tools/blockdem_figures.py with Debian's matplotlib):
# acceleration (Fig. 5 style), rotation and relative displacement, energy balance, snapshot strip
# (Fig. 6 style) in PNG and SVG, one animation, and the Fig. 5 comparison of two h_s runs.
#   bash tests/cli/test_figures.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1 source_dir=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
source "$source_dir/tests/cli/view_deps.sh"
need_package python3-matplotlib /usr/bin/python3 -c "import matplotlib, numpy"
figures="/usr/bin/python3 $source_dir/tools/blockdem_figures.py"
stems="acceleration energy snapshots response"

animation_done=0
for scenario in "$source_dir"/examples/paper/*.toml; do
  name=$(basename "$scenario" .toml)
  "$blockdem" run "$scenario" --out "$work/$name" -q --set output.vtk=false >/dev/null
  extra=--no-animation
  # One animation is enough to test the writer, and each costs seconds.
  [ $animation_done -eq 1 ] || extra=
  $figures run "$work/$name" --formats png,svg $extra >/dev/null
  files=()
  for stem in $stems; do
    # response.* exists only when the run has a recorded dynamic body.
    [ "$stem" = response ] && [ ! -e "$work/$name/figures/response.png" ] && continue
    files+=("$work/$name/figures/$stem.png" "$work/$name/figures/$stem.svg")
  done
  if [ -z "$extra" ]; then files+=("$(ls "$work/$name"/figures/animation.*)"); animation_done=1; fi
  echo "== $name"
  /usr/bin/python3 "$source_dir/tests/cli/check_figures.py" "${files[@]}"
done

# The paper's Fig. 5 compares shear damping ratios: two runs, stacked and overlaid.
sliding="$source_dir/examples/paper/sliding.toml"
"$blockdem" run "$sliding" --out "$work/hs0" -q --set contact.h_s=0 --set output.vtk=false >/dev/null
"$blockdem" run "$sliding" --out "$work/hs1" -q --set contact.h_s=1 --set output.vtk=false >/dev/null
$figures compare "$work/hs0" "$work/hs1" --body block --labels "h_s = 0,h_s = 1" --out "$work/cmp" >/dev/null
$figures compare "$work/hs0" "$work/hs1" --body block --overlay --formats pdf --out "$work/cmp-overlay" >/dev/null
echo "== comparison"
/usr/bin/python3 "$source_dir/tests/cli/check_figures.py" "$work/cmp/acceleration_comparison.png" \
  "$work/cmp/acceleration_comparison.svg"
[ -s "$work/cmp-overlay/acceleration_comparison.pdf" ] || { echo "FAIL: no PDF"; exit 1; }
# A wrong body name is an error naming the recorded bodies, not a traceback.
if $figures compare "$work/hs0" --body nosuch --out "$work/x" 2>"$work/err"; then echo "FAIL: bad body accepted"; exit 1; fi
grep -q "recorded: table, block" "$work/err" || { echo "FAIL: unhelpful message"; cat "$work/err"; exit 1; }
echo "figure checks passed"
