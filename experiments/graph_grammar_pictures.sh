#!/bin/sh
# Draws the pictures of docs/graph-grammars.md: shapevo's own graph grammars (grammars/graph/)
# and, where ../shared/graph-grammar/original-examples is present, the original tool's four example
# files at the seeds and step counts of its reference-output/ (the files are read, never copied;
# only shapevo's drawing of them is kept). Prints each derivation's counts.
#
#   experiments/graph_grammar_pictures.sh [BUILD_DIR]      (default build)
set -eu
cd "$(dirname "$0")/.."
bin=${1:-build}/shapevo
out=docs/figures/graph-grammars
mkdir -p "$out"
draw() {  # draw FILE NAME [sample options...]
    file=$1 name=$2
    shift 2
    rm -f "$out/$name.png"
    "$bin" sample "$file" -o "$out/$name.png" --size 360x360 "$@"
}
for g in koch tree radial tiled facade; do
    draw grammars/graph/$g.yml own-$g --seed 3
done
originals=../shared/graph-grammar/original-examples
if [ -d "$originals" ]; then
    draw $originals/koch_flake.yml original-koch_flake-s1 --seed 1 --steps 192
    draw $originals/tree.yml original-tree-s1 --seed 1 --steps 200
    draw $originals/pattern_circle.yml original-pattern_circle-s2 --seed 2
    draw $originals/pattern_square.yml original-pattern_square-s1 --seed 1 --steps 500
else
    echo "($originals is absent: only shapevo's own grammars drawn)"
fi
