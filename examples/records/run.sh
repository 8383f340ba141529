#!/usr/bin/env bash
# Runs the block-on-a-table example under the real El Centro record when the project's data set
# (../shared/data/ground-motions next to the repository) is present, else under the synthetic
# motion. Usage: examples/records/run.sh [BLOCKDEM] [OUT]   (defaults: build/blockdem, out/records)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
blockdem=${1:-$root/build/blockdem}
out=${2:-$root/out/records}
record=$root/../shared/data/ground-motions/peer-at2/RSN6_IMPVALL.I_I-ELC180.AT2
if [ -f "$record" ]; then
  scenario=$here/block_record.toml
  echo "records example: El Centro 1940 (RSN 6) from $record"
  "$blockdem" motion "$record" --out "$out/motion"
else
  scenario=$here/block_synthetic.toml
  echo "records example: no ground-motion data set at $(dirname "$(dirname "$record")"); using the synthetic motion"
fi
"$blockdem" run "$scenario" --out "$out/run"
