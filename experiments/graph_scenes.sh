#!/bin/sh
# The 2D graph-grammar scenes (docs/evolving-graph-grammars.md, "Scenes"): each scene for 5 seeds
# on 2 MPI ranks, with the default search (hybrid) and the GA within the wall time, and random
# sampling (search.method = "random": the best of as many random derivations) given the same
# number of evaluations as that seed's hybrid run. Prints one markdown row per scene and method:
# mean IoU, min-max, mean evaluations.
#   experiments/graph_scenes.sh [SEEDS=5] [SECONDS=60] [BUILD=build] [SCENES="graph-tree-sketch graph-facade-reachable graph-mosaic-logo"]
set -eu
seeds=${1:-5}; seconds=${2:-60}; build=${3:-build}
scenes=${4:-graph-tree-sketch graph-facade-reachable graph-mosaic-logo}
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
value() { sed -n "s/.*\"$1\": \([0-9.e+-]*\).*/\1/p" "$2" | head -1; }
run() {  # run CONFIG METHOD SEED FOLDER [extra --set ...]
    config=$1; method=$2; seed=$3; folder=$4; shift 4
    mpirun --allow-run-as-root --oversubscribe -np 2 "$build/shapevo" run "$config" -q --threads 1 --seed "$seed" \
        --set search.method="$method" --out "$folder" "$@" >/dev/null ||
        { status=$?; echo "graph_scenes.sh: $config, $method, seed $seed failed (exit $status)" >&2; exit 1; }
}
echo "| scene | method | mean IoU | min–max | mean evaluations |"
echo "| --- | --- | ---: | ---: | ---: |"
for scene in $scenes; do
    config=configs/$scene.toml
    population=$(sed -n 's/^population = \([0-9]*\).*/\1/p' "$config")
    for s in $(seq 1 "$seeds"); do
        run "$config" hybrid "$s" "$out/$scene-hybrid-$s" --set run.wall_time="$seconds"
        run "$config" ga "$s" "$out/$scene-ga-$s" --set run.wall_time="$seconds"
        evals=$(value evaluations "$out/$scene-hybrid-$s/summary.json")
        generations=$(( (evals + 2 * population - 1) / (2 * population) ))  # population evaluations a generation, per rank
        [ "$generations" -ge 1 ] || generations=1
        run "$config" random "$s" "$out/$scene-random-$s" --set run.wall_time=0 --set ga.generations="$generations"
    done
    for method in hybrid ga random; do
        for s in $(seq 1 "$seeds"); do
            f=$out/$scene-$method-$s/summary.json
            echo "$(value silhouette_iou "$f") $(value evaluations "$f")"
        done | awk -v scene="$scene" -v method="$method" '
            { s += $1; e += $2; if (min == "" || $1 < min) min = $1; if ($1 > max) max = $1 }
            END { printf "| %s | %s | %.3f | %.3f–%.3f | %d |\n", scene, method, s / NR, min, max, e / NR }'
    done
done
