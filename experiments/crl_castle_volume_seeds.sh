#!/bin/sh
# The CastleMaker castle rule file (grammars/castlemaker/castle-volume.rule, configs/crl-castle-volume.toml)
# against the papers' castle for several seeds, each on 2 MPI ranks within its wall time; prints
# each seed's voxel IoU, then mean, min and max (castle_volume_seeds.sh with this config).
#   experiments/crl_castle_volume_seeds.sh [SEEDS=5] [SECONDS=60] [BUILD=build]
exec "$(dirname "$0")/castle_volume_seeds.sh" "${1:-5}" "${2:-60}" "${3:-build}" configs/crl-castle-volume.toml
