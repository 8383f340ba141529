#!/usr/bin/env bash
# `make demo`: runs the default example and writes its report.
#   scripts/demo.sh BUILD_DIR OUT_DIR
# The default example is the paper's toppling tombstone (examples/paper/rocking.toml), or the
# sliding block of Fig. 5 while that example is not there.
set -euo pipefail
build_dir=${1:-build}
out_dir=${2:-out/demo}
example=examples/paper/rocking.toml
[ -f "$example" ] || example=examples/paper/sliding.toml

"$build_dir/blockdem" run "$example" --out "$out_dir" --quiet
"$build_dir/blockdem" report "$out_dir"
echo
echo "Report: $(cd "$out_dir" && pwd)/report.html   (open it in any browser; no server needed)"
echo "Figures: $out_dir/figures/"
if [ -f "$out_dir/vtk/bodies.pvd" ]; then
  echo "ParaView: $out_dir/vtk/bodies.pvd and $out_dir/vtk/contacts.pvd"
fi
