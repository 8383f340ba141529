#!/usr/bin/env bash
# The figures' layout as drawn (tests/cli/check_figure_layout.py): no tick label, axis label,
# title or legend overlaps another, no legend covers a curve, and the animation is at least
# 1280 pixels wide. Runs: the paper's three examples (one with several bodies), and the tombstone
# moved to x = 1000 m (long tick labels that used to collide in the snapshot strip).
#   bash tests/cli/test_figure_layout.sh BLOCKDEM SOURCE_DIR
set -euo pipefail
blockdem=$1 source_dir=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
source "$source_dir/tests/cli/view_deps.sh"
need_package python3-matplotlib /usr/bin/python3 -c "import matplotlib, numpy"
need_package ffmpeg ffprobe -version
short="--set simulation.duration=1.5 --set output.vtk=false -q"
for name in sliding rocking collision; do
  "$blockdem" run "$source_dir/examples/paper/$name.toml" --out "$work/$name" $short >/dev/null
done
"$blockdem" run "$source_dir/examples/paper/rocking.toml" --out "$work/far" $short \
  --set 'bodies.table.center=[1000.0, -0.1]' --set 'bodies.tombstone.center=[1000.0, 0.8]' >/dev/null
/usr/bin/python3 "$source_dir/tests/cli/check_figure_layout.py" "$source_dir/tools" \
  "$work/sliding" "$work/collision" "$work/rocking" "$work/far"
echo "figure layout checks passed"
