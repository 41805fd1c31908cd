#!/bin/sh
# The procedural-content-graph scenes (docs/pcg-scenes.md): for 5 seeds on 2 MPI ranks, PCGR's
# Fig. 4 stairway (configs/pcg-stairway-volume.toml) toward its reachable volume, and Fig. 3's
# tree as a .pcg graph (configs/pcg-tree-volume.toml) against grammars/tree.grammar
# (configs/tree-volume.toml) toward the papers' tree volume. The budget is a number of
# generations (the same evaluations for both trees, whatever else loads the machine); the two
# trees run alternately, seed by seed; and Fig. 7's zoned city (configs/city-zones-volume.toml)
# toward its reachable volume. Prints one markdown row per scene: mean voxel IoU, min-max, mean
# evaluations, mean seconds.
#   [SCENES="..."] experiments/pcg_scenes.sh [SEEDS=5] [TREE_GENERATIONS=1000] [STAIR_GENERATIONS=1500] [BUILD=build] [CITY_GENERATIONS=1000]
# SCENES (configs' names, space-separated) runs only those.
set -eu
seeds=${1:-5}; tree_generations=${2:-1000}; stair_generations=${3:-1500}; build=${4:-build}; city_generations=${5:-1000}
cd "$(dirname "$0")/.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
value() { sed -n "s/.*\"$1\": \([0-9.e+-]*\).*/\1/p" "$2" | head -1; }
run() {  # run CONFIG SEED GENERATIONS FOLDER
    start=$(date +%s.%N)
    mpirun --allow-run-as-root --oversubscribe -np 2 nice "$build/shapevo" run "configs/$1.toml" -q --threads 1 --seed "$2" \
        --set run.wall_time=0 --set ga.generations="$3" --out "$4" >/dev/null ||
        { status=$?; echo "pcg_scenes.sh: $1, seed $2 failed (exit $status)" >&2; exit 1; }
    awk -v a="$(date +%s.%N)" -v b="$start" 'BEGIN { print a - b }' > "$4/seconds"
}
scenes=${SCENES:-pcg-stairway-volume tree-volume pcg-tree-volume city-zones-volume}
for s in $(seq 1 "$seeds"); do
    for scene in $scenes; do
        case $scene in
        pcg-stairway-volume) generations=$stair_generations ;;
        city-zones-volume) generations=$city_generations ;;
        *) generations=$tree_generations ;;
        esac
        run "$scene" "$s" "$generations" "$out/$scene-$s"
    done
done
echo "| scene | grammar | mean voxel IoU | min–max | mean evaluations | mean seconds |"
echo "| --- | --- | ---: | ---: | ---: | ---: |"
for scene in $scenes; do
    grammar=$(sed -n 's|^file = "\.\./\(.*\)".*|\1|p' "configs/$scene.toml" | head -1)
    for s in $(seq 1 "$seeds"); do
        f=$out/$scene-$s/summary.json
        echo "$(value voxel_iou "$f") $(value evaluations "$f") $(cat "$out/$scene-$s/seconds")"
    done | awk -v scene="$scene" -v grammar="$grammar" '
        { s += $1; e += $2; t += $3; if (min == "" || $1 < min) min = $1; if ($1 > max) max = $1 }
        END { printf "| %s | %s | %.3f | %.3f–%.3f | %d | %.0f |\n", scene, grammar, s / NR, min, max, e / NR, t / NR }'
done
