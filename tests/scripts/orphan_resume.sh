#!/usr/bin/env bash
# Orphaned ranks stop: kill -9 of mpirun (what an out-of-memory killer or a node failure does)
# during a 2-rank run, in sync and in async mode. Every rank must notice, write a checkpoint and
# end within 2 seconds (no checkpoint is due before: the run's only checkpoint is the one the
# ranks write when they notice), and a resume started 2 seconds after the kill must succeed.
# usage: tests/scripts/orphan_resume.sh path/to/shapevo [mpirun]
set -euo pipefail
trap 'echo "orphan_resume.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
BIN=$(realpath "$1")
MPIRUN=${2:-mpirun}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
WORK=$(mktemp -d)
trap 'pkill -9 -f "$WORK" 2>/dev/null || true; rm -rf "$WORK"' EXIT
SETS=(--set ga.population=60 --set ga.elitism=6 --set ga.tournament=5 --set checkpoint.interval=0
      --set checkpoint.seconds=0 --set run.threads=1 --set ga.generations=100000)

ended() {  # whether process $1 has ended (gone, or a zombie its new parent has not reaped yet)
    local state
    state=$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null) || return 0
    [ "$state" = Z ]
}

for mode in sync async; do
    run="$WORK/$mode"
    log="$WORK/$mode.log"
    "$MPIRUN" --oversubscribe -np 2 "$BIN" run "$ROOT/configs/spaceship.toml" --out "$run" "${SETS[@]}" \
        --set migration.mode=$mode >"$log" 2>&1 &
    launcher=$!
    for _ in $(seq 1 100); do grep -q '^gen ' "$log" && break; sleep 0.1; done
    sleep 0.5
    ranks=$(pgrep -P "$launcher" -f shapevo || true)
    [ "$(echo "$ranks" | wc -w)" -eq 2 ] || { echo "$mode: expected 2 ranks, found '$ranks'"; cat "$log"; exit 1; }
    kill -9 "$launcher"
    killed=$(date +%s.%N)
    wait "$launcher" 2>/dev/null || true
    # every rank ends within 2 seconds of the kill
    while :; do
        alive=""
        for r in $ranks; do ended "$r" || alive="$alive $r"; done
        [ -z "$alive" ] && break
        if awk -v a="$killed" -v b="$(date +%s.%N)" 'BEGIN {exit !(b - a > 2)}'; then
            echo "$mode: rank(s)$alive still alive 2 s after mpirun was killed"; exit 1
        fi
        sleep 0.02
    done
    took=$(awk -v a="$killed" -v b="$(date +%s.%N)" 'BEGIN {printf "%.2f", b - a}')
    # the resume starts 2 seconds after the kill
    sleep "$(awk -v a="$killed" -v b="$(date +%s.%N)" 'BEGIN {d = 2 - (b - a); printf "%.3f", (d > 0 ? d : 0)}')"
    newest=$("$BIN" inspect "$run" 2>/dev/null | awk '$1 == "generation" {print $2; exit}') || true
    [ -n "$newest" ] || { echo "$mode: no checkpoint written after mpirun was killed"; ls -a "$run"; exit 1; }
    "$MPIRUN" --oversubscribe -np 2 "$BIN" resume "$run" --generations $((newest + 3)) -q
    generations=$(sed -n 's/.*"generations": \([0-9]*\).*/\1/p' "$run/summary.json")
    [ "$generations" -ge $((newest + 3)) ] || { echo "$mode: resumed run ended at generation $generations"; exit 1; }
    echo "$mode: ranks ended ${took} s after kill -9 of mpirun, checkpoint at generation $newest; resumed 2 s after the kill to generation $generations"
done
echo "orphaned ranks stop, checkpoint and release the run folder in both modes"
