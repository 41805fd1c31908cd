#!/bin/sh
# Makes the picture targets of the 2D graph-grammar scenes (docs/evolving-graph-grammars.md):
#   targets/graph/facade-reachable.png  the drawing of the facade grammar's genome of root seed 11
#     (`shapevo sample --seed 11 --genome`), drawn exactly through configs/graph-facade-reachable.toml's
#     camera (`shapevo target G.genome --image CONFIG`): a target the search can reach.
#   targets/graph/power-logo.png  the logo of configs/graph-mosaic-logo.toml (experiments/make_logo.py).
# Usage: experiments/make_graph_targets.sh [path/to/shapevo]   (default build/shapevo); run from
# the repository's root. Existing targets are left alone (delete one to make it again).
set -eu
bin=${1:-build/shapevo}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ ! -e targets/graph/facade-reachable.png ]; then
  "$bin" sample grammars/graph/facade.yml --seed 11 --genome "$tmp/facade-11.genome" -o "$tmp/facade-11.svg"
  # the config names the picture being made: draw through a copy that names another one
  sed "s|^image = .*|image = \"$(pwd)/targets/shapegenetics/tree_target_sketch1.png\"|; s|^file = \"\.\./|file = \"$(pwd)/|" \
    configs/graph-facade-reachable.toml > "$tmp/frame.toml"
  "$bin" target "$tmp/facade-11.genome" --image "$tmp/frame.toml" -o targets/graph/facade-reachable.png
fi
if [ ! -e targets/graph/power-logo.png ]; then
  python3 experiments/make_logo.py targets/graph/power-logo.png
  echo "wrote targets/graph/power-logo.png"
fi
