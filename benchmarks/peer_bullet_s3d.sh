#!/usr/bin/env bash
# Runs the peers' Bullet program on scene S3D on this machine, for a same-machine figure beside
# BM_BrickWall3d (docs/performance.md, "Three dimensions"). The program is the shared one
# (shared/peers/three_d/bullet/bullet_bench.cpp, not part of blockdem); it is built here into
# build/peer/. Needs libbullet-dev. Usage: benchmarks/peer_bullet_s3d.sh [SHARED_DIR] [N...]
set -euo pipefail
shared=${1:-$(dirname "$0")/../../shared}
shift || true
source_file=$shared/peers/three_d/bullet/bullet_bench.cpp
if [[ ! -f $source_file ]]; then
    echo "no $source_file: the shared peers folder is absent" >&2
    exit 2
fi
out=$(dirname "$0")/../build/peer
mkdir -p "$out"
g++ -O2 -o "$out/bullet_bench" "$source_file" $(pkg-config --cflags --libs bullet)
for n in "${@:-1000 10000}"; do
    # S3D at dt = 1e-4 s: 100 settling steps with the base still, then timed shaking steps.
    steps=$(( n >= 100000 ? 3 : n >= 10000 ? 50 : 500 ))
    "$out/bullet_bench" "$n" 1e-4 "$steps" 100 0
done
