#!/bin/sh
# A castle config against the papers' castle (default configs/castle-volume.toml, the castle
# grammar) for several seeds, each on 2 MPI ranks within its wall time; prints each seed's voxel
# IoU, then mean, min and max.
#   experiments/castle_volume_seeds.sh [SEEDS=5] [SECONDS=60] [BUILD=build] [CONFIG=configs/castle-volume.toml]
set -eu
seeds=${1:-5}; seconds=${2:-60}; build=${3:-build}; config=${4:-configs/castle-volume.toml}
out=$(mktemp -d)
for s in $(seq 1 "$seeds"); do
    mpirun --allow-run-as-root --oversubscribe -np 2 "$build/shapevo" run "$config" -q \
        --seed "$s" --set run.wall_time="$seconds" --out "$out/seed-$s" >/dev/null
    iou=$(sed -n 's/.*"voxel_iou": \([0-9.]*\).*/\1/p' "$out/seed-$s/summary.json")
    evals=$(sed -n 's/.*"evaluations": \([0-9]*\).*/\1/p' "$out/seed-$s/summary.json" | head -1)
    echo "seed $s: voxel IoU $iou ($evals evaluations)"
    echo "$iou" >> "$out/ious"
done
awk '{ s += $1; if (min == "" || $1 < min) min = $1; if ($1 > max) max = $1 } END { printf "mean %.4f  min %.4f  max %.4f over %d seeds\n", s / NR, min, max, NR }' "$out/ious"
rm -rf "$out"
