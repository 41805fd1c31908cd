#!/bin/sh
# The street of buildings (configs/street-whale.toml) against the city (configs/city-whale.toml)
# on the whale skyline, same camera, weights and GA budget (population 100, 100 generations),
# seeds 1..N on one rank; prints each seed's silhouette IoU and the means.
#   experiments/street_vs_city_whale.sh [SEEDS=5] [BUILD=build]
set -eu
seeds=${1:-5}; build=${2:-build}
out=$(mktemp -d)
for config in street-whale city-whale; do
    for s in $(seq 1 "$seeds"); do
        "$build/shapevo" run "configs/$config.toml" -q --seed "$s" --out "$out/$config-$s" >/dev/null
        sed -n 's/.*"silhouette_iou": \([0-9.]*\).*/\1/p' "$out/$config-$s/summary.json" >> "$out/$config"
    done
    printf '%-14s' "$config"; tr '\n' ' ' < "$out/$config"
    awk '{ s += $1 } END { printf " mean %.4f\n", s / NR }' "$out/$config"
done
rm -rf "$out"
