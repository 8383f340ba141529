#!/usr/bin/env bash
# `blockdem run --threads N`: the results do not depend on the thread count. A wall of about
# 1,250 bricks and a rock slope of about 1,000 blocks (both with more than 2,048 contact pairs,
# so that the contact loops do run on threads: world/parallel.hpp), every block recorded, run
# with 1 and with 2 threads: history.csv and energy.csv are byte-identical, and so is
# summary.json once the wall-clock time is removed.
# Usage: test_threads_identical.sh BLOCKDEM SOURCE_DIR
set -u
bin=$(realpath "$1"); src=$(realpath "$2")
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# Waiting OpenMP threads sleep instead of spinning: on a shared, loaded machine spinning threads
# slow a run tenfold. It changes no result.
export OMP_WAIT_POLICY=passive

wall=("$src/examples/assemblies/wall_with_window.toml" --set simulation.duration=0.02 --set simulation.output_interval=0.002
      --set assemblies.brick.length=5 --set assemblies.brick.courses=50 --set bodies.table.width=7
      --set 'bodies.table.center=[2.5, -0.1]' --set assemblies.brick.record=true --set output.vtk=false
      --set settling.kinetic_ratio=1 --set settling.window=0.01)
slope=("$src/examples/assemblies/rock_slope.toml" --set simulation.duration=0.005 --set simulation.output_interval=0.0005
       --set assemblies.rock.record=true --set output.vtk=false --set assemblies.rock.min_block_area=0.02
       --set assemblies.rock.joint_sets.0.spacing=0.3 --set assemblies.rock.joint_sets.1.spacing=0.45
       --set settling.kinetic_ratio=1 --set settling.window=0.002)
without_wall_time() { /usr/bin/python3 -c 'import json, sys; s = json.load(open(sys.argv[1])); s.pop("wall_time_s", None); print(json.dumps(s, sort_keys=True))' "$1"; }

for scene in wall slope; do
  declare -n args=$scene
  for threads in 1 2; do
    "$bin" run "${args[@]}" --out "$tmp/$scene-$threads" -q --threads $threads > /dev/null 2> "$tmp/$scene-$threads.log" \
      || fail "$scene with $threads threads: $(cat "$tmp/$scene-$threads.log")"
  done
  blocks=$(/usr/bin/python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["bodies"]))' "$tmp/$scene-1/summary.json")
  [ "$blocks" -gt 1000 ] || fail "$scene has only $blocks bodies"
  for file in history.csv energy.csv; do
    cmp "$tmp/$scene-1/$file" "$tmp/$scene-2/$file" || fail "$scene: $file differs between 1 and 2 threads"
  done
  [ "$(without_wall_time "$tmp/$scene-1/summary.json")" = "$(without_wall_time "$tmp/$scene-2/summary.json")" ] \
    || fail "$scene: summary.json differs between 1 and 2 threads"
  echo "$scene: $blocks bodies, $(wc -l < "$tmp/$scene-1/history.csv") history lines, identical with 1 and 2 threads"
done

[ $failures -eq 0 ] && echo "results are identical for 1 and 2 threads"
exit $failures
