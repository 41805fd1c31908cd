#!/bin/sh
# Island scaling on this machine: the spaceship at its default migration and checkpoint
# intervals, 1 rank vs 2 ranks (one evaluation thread each), 3 repetitions each. Prints
# evaluations per second (evaluations / wall time of the island loop, from summary.json) and the
# share of the wall time spent in migration and checkpointing (slowest rank).
# usage: experiments/scaling.sh [path/to/shapevo] [generations]
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build/shapevo}
GENERATIONS=${2:-500}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
field() { sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"; }
printf '| ranks | run | evaluations | wall s | evals/s | migration %% | checkpoint %% |\n|---|---|---|---|---|---|---|\n'
for ranks in 1 2; do
    for rep in 1 2 3; do
        dir="$out/r$ranks-$rep"
        mpirun --oversubscribe -np "$ranks" "$BIN" run configs/spaceship.toml --threads 1 \
            --set "ga.generations=$GENERATIONS" --out "$dir" -q
        e=$(field evaluations "$dir/summary.json"); w=$(field wall_seconds "$dir/summary.json")
        m=$(field migration_seconds "$dir/summary.json"); c=$(field checkpoint_seconds "$dir/summary.json")
        awk -v r="$ranks" -v k="$rep" -v e="$e" -v w="$w" -v m="$m" -v c="$c" \
            'BEGIN {printf "| %d | %d | %d | %.3f | %.0f | %.2f | %.2f |\n", r, k, e, w, e / w, 100 * m / w, 100 * c / w}'
    done
done
