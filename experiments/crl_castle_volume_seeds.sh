#!/bin/sh
# The CastleMaker castle rule file (grammars/castlemaker/castle-volume.rule, configs/crl-castle-volume.toml)
# against the papers' castle for several seeds, each on 2 MPI ranks within its wall time; prints
# each seed's voxel IoU, then mean, min and max.
#   experiments/crl_castle_volume_seeds.sh [SEEDS=5] [SECONDS=60] [BUILD=build]
set -eu
seeds=${1:-5}; seconds=${2:-60}; build=${3:-build}
out=$(mktemp -d)
for s in $(seq 1 "$seeds"); do
    mpirun --allow-run-as-root --oversubscribe -np 2 "$build/shapevo" run configs/crl-castle-volume.toml -q \
        --seed "$s" --set run.wall_time="$seconds" --out "$out/seed-$s" >/dev/null
    iou=$(sed -n 's/.*"voxel_iou": \([0-9.]*\).*/\1/p' "$out/seed-$s/summary.json")
    evals=$(sed -n 's/.*"evaluations": \([0-9]*\).*/\1/p' "$out/seed-$s/summary.json" | head -1)
    echo "seed $s: voxel IoU $iou ($evals evaluations)"
    echo "$iou" >> "$out/ious"
done
awk '{ s += $1; if (min == "" || $1 < min) min = $1; if ($1 > max) max = $1 } END { printf "mean %.4f  min %.4f  max %.4f over %d seeds\n", s / NR, min, max, NR }' "$out/ious"
rm -rf "$out"
