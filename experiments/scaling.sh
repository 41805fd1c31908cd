#!/bin/sh
# Island scaling on this machine: the spaceship at its default migration and checkpoint
# intervals, 1 rank vs 2 ranks (one evaluation thread each), 3 repetitions each. Prints
# evaluations per second (evaluations / wall time of the island loop, from summary.json) and the
# share of the wall time spent in migration and checkpointing (slowest rank).
# Ranks are not bound to cores (--bind-to none): with binding, OpenMPI on this 2-core VM ran
# the two ranks at 1.35x instead of 2x.
# usage: experiments/scaling.sh [path/to/shapevo] [generations]
set -eu
cd "$(dirname "$0")/.."
BIN=${1:-build/shapevo}
GENERATIONS=${2:-500}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
field() { sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"; }
REPS=${REPS:-5}
printf '| ranks | run | evaluations | wall s | evals/s | migration %% | checkpoint %% |\n|---|---|---|---|---|---|---|\n'
# 1 and 2 ranks alternate, so that drift in the machine's speed hits both alike
for rep in $(seq 1 "$REPS"); do
    for ranks in 1 2; do
        dir="$out/r$ranks-$rep"
        mpirun --oversubscribe --bind-to none -np "$ranks" "$BIN" run configs/spaceship.toml --threads 1 \
            --set "ga.generations=$GENERATIONS" --out "$dir" -q
        e=$(field evaluations "$dir/summary.json"); w=$(field wall_seconds "$dir/summary.json")
        m=$(field migration_seconds "$dir/summary.json"); c=$(field checkpoint_seconds "$dir/summary.json")
        awk -v r="$ranks" -v k="$rep" -v e="$e" -v w="$w" -v m="$m" -v c="$c" \
            'BEGIN {printf "| %d | %d | %d | %.3f | %.0f | %.2f | %.2f |\n", r, k, e, w, e / w, 100 * m / w, 100 * c / w}' |
            tee -a "$out/rows"
    done
done
# per repetition the 2-rank / 1-rank ratio (a pair runs back to back, so slow drift in the VM's
# speed cancels), then medians
awk -F'|' '{gsub(/ /, ""); r = $2; k = $3; v[r, k] = $6; o[r, k] = $7 + $8; if (k > reps) reps = k}
    function median(a, k,   i, j, t, x) { for (i = 1; i <= k; i++) t[i] = a[i]
        for (i = 1; i <= k; i++) for (j = i + 1; j <= k; j++) if (t[j] < t[i]) { x = t[i]; t[i] = t[j]; t[j] = x }
        return k % 2 ? t[(k + 1) / 2] : (t[k / 2] + t[k / 2 + 1]) / 2 }
    END { for (k = 1; k <= reps; k++) { ratio[k] = v[2, k] / v[1, k]; e1[k] = v[1, k]; e2[k] = v[2, k]; s1[k] = o[1, k]; s2[k] = o[2, k] }
          printf "\nmedian evals/s: 1 rank %.0f, 2 ranks %.0f; median paired speed-up %.2fx (min %.2f, max %.2f)\n", median(e1, reps), median(e2, reps), median(ratio, reps), min(ratio, reps), max(ratio, reps)
          printf "median migration + checkpoint share of the wall time: 1 rank %.2f %%, 2 ranks %.2f %%\n", median(s1, reps), median(s2, reps) }
    function min(a, k,   i, m) { m = a[1]; for (i = 2; i <= k; i++) if (a[i] < m) m = a[i]; return m }
    function max(a, k,   i, m) { m = a[1]; for (i = 2; i <= k; i++) if (a[i] > m) m = a[i]; return m }' "$out/rows"
