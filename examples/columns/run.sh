#!/usr/bin/env bash
# Three columns under three records, each scaled to a PGA of 0.5 g, and the outcome of every drum
# (docs/outputs.md, "Outcomes"): the 3-drum (0.6 x 0.9 m), 4-drum and slender 3-drum (0.4 x 0.9 m)
# columns under El Centro 1940 (RSN 6, 180), Northridge 1994 Rinaldi (228) and Loma Prieta 1989
# Gilroy - Gavilan College (067). The records are read from ../shared/data/ground-motions next
# to the repository. Usage: examples/columns/run.sh [BLOCKDEM] [OUT]
#   (defaults: build/blockdem, out/columns)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
blockdem=${1:-$root/build/blockdem}
out=${2:-$root/out/columns}
records=$root/../shared/data/ground-motions/peer-at2
if [ ! -d "$records" ]; then
  echo "columns example: no ground-motion data set at $records" >&2
  exit 2
fi
# name, file relative to the scenario's folder, component in the file's header
motions=(
  "elcentro ../../../shared/data/ground-motions/peer-at2/RSN6_IMPVALL.I_I-ELC180.AT2 180"
  "rinaldi ../../../shared/data/ground-motions/peer-at2/Rinaldi228.AT2 228"
  "gilroy ../../../shared/data/ground-motions/peer-at2/RSN763_LOMAP_GIL067.AT2 67"
)
for column in column3 column4 slender3; do
  for m in "${motions[@]}"; do
    read -r name file component <<<"$m"
    echo "== $column under $name"
    "$blockdem" run "$here/${column}_elcentro.toml" --out "$out/$column-$name" -q \
      --set "table_motion.horizontal.file=\"$file\"" --set "table_motion.horizontal.component=\"$component\""
  done
done
