#!/bin/sh
# Quality of the shipped spaceship configs: 5 seeds each at the configs' own settings; prints
# seed, best fitness, voxel IoU and wall time per run and the mean IoU per config.
# usage: experiments/quality.sh [path/to/shapevo]    (default build/shapevo)
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build/shapevo}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '| config | seed | best fitness | voxel IoU | wall s |\n|---|---|---|---|---|\n'
for cfg in spaceship spaceship-paper; do
    sum=0
    for seed in 1 2 3 4 5; do
        "$BIN" run "configs/$cfg.toml" --seed "$seed" --out "$out/$cfg-$seed" -q
        f=$(sed -n 's/.*"best_fitness": \([^,]*\),/\1/p' "$out/$cfg-$seed/summary.json")
        iou=$(sed -n 's/.*"voxel_iou": \([^,]*\),/\1/p' "$out/$cfg-$seed/summary.json")
        wall=$(sed -n 's/.*"wall_seconds": \([^,]*\),/\1/p' "$out/$cfg-$seed/summary.json")
        printf '| %s | %s | %.4f | %.4f | %.3f |\n' "$cfg" "$seed" "$f" "$iou" "$wall"
        sum=$(awk "BEGIN {print $sum + $iou}")
    done
    printf "| %s | mean | | %.4f | |\n" "$cfg" "$(awk "BEGIN {print $sum / 5}")"
done
echo
echo "target derivation scored against its own target:"
"$BIN" evaluate configs/spaceship.toml targets/spaceship-reachable.genome
