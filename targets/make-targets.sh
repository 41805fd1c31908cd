#!/bin/sh
# Rebuild the shipped volume targets from their sources with shapevo's own commands.
# usage: targets/make-targets.sh [path/to/shapevo]      (default: build/shapevo)
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build/shapevo}
rm -f targets/spaceship-reachable.vdb targets/pcg-stairway-reachable.vdb targets/houses-reachable.vdb targets/city-zones-reachable.vdb \
      targets/spaceship-paper.vdb targets/tree-volume.vdb targets/tree-avoid.vdb targets/castle.vdb

# A reachable target: one fixed derivation of the spaceship grammar (14 genes), kept as source
# data with its chromosome (spaceship-reachable.genome). It was drawn by
#   shapevo sample grammars/spaceship.grammar --seed 7 --min-genes 14 --max-genes 18
# while sample still grew with the GA's grow mutation; sample now follows the grammar's prob and
# that command draws a different derivation, so the mesh is not rebuilt here.
"$BIN" target targets/spaceship-reachable.obj --voxel-size 0.1 -o targets/spaceship-reachable.vdb

# A reachable target for PCGR's Fig. 4 stairway (configs/pcg-stairway-volume.toml): one derivation
# of grammars/pcg/stairway.pcg (7 steps x 3 flights), kept as source data with its chromosome
# (pcg-stairway-reachable.genome), drawn by
#   shapevo sample grammars/pcg/stairway.pcg --seed 4 --genome targets/pcg-stairway-reachable.genome -o targets/pcg-stairway-reachable.obj
# The mesh's voxels differ from the scorer's voxels of the same genome at thin treads' faces: that
# genome scores voxel IoU 0.925 against it (`shapevo evaluate configs/pcg-stairway-volume.toml
# targets/pcg-stairway-reachable.genome`), the search finds 0.929 (docs/pcg-scenes.md).
"$BIN" target targets/pcg-stairway-reachable.obj --voxel-size 0.05 -o targets/pcg-stairway-reachable.vdb

# A reachable target for the houses street (configs/houses-volume.toml): one derivation of
# grammars/houses.grammar (4 genes, 103 primitives), kept as source data with its chromosome, drawn by
#   shapevo sample grammars/houses.grammar --seed 3 --genome targets/houses-reachable.genome -o targets/houses-reachable.obj
"$BIN" target targets/houses-reachable.obj --voxel-size 0.5 -o targets/houses-reachable.vdb

# A reachable target for PCGR's Fig. 7 zoned city (configs/city-zones-volume.toml): one derivation
# of grammars/city-zones.grammar (1 gene, 1,024 blocks), kept as source data with its chromosome, drawn by
#   shapevo sample grammars/city-zones.grammar --seed 3 --genome targets/city-zones-reachable.genome -o targets/city-zones-reachable.obj
"$BIN" target targets/city-zones-reachable.obj --voxel-size 1 -o targets/city-zones-reachable.vdb

# The papers' spaceship target mesh (crest01/ShapeGenetics, MIT licence: targets/shapegenetics/LICENSE).
"$BIN" target targets/shapegenetics/spaceship_target.obj --voxel-size 0.1 -o targets/spaceship-paper.vdb

# The papers' other volume targets (same source and licence): the tree to fill (80^3 voxels over
# [-5, 5]^3 in their runs), the space a tree must avoid (150^3 there), the castle a city fills
# (100^3 over [-10, 10]^3). Voxel sizes match their grids.
"$BIN" target targets/shapegenetics/target_tree.obj --voxel-size 0.125 -o targets/tree-volume.vdb
"$BIN" target targets/shapegenetics/tree_avoid.obj --voxel-size 0.125 -o targets/tree-avoid.vdb
"$BIN" target targets/shapegenetics/target_castle.obj --voxel-size 0.2 -o targets/castle.vdb
