#!/usr/bin/env bash
# SIGUSR1 to mpirun (forwarded to every rank) and SIGTERM to a single rank (the others learn it
# at the next generation) both make a 2-rank run finish its generation, write a checkpoint of
# exactly that generation, say so and exit 0; the run then resumes from there.
# usage: tests/scripts/signal_checkpoint.sh path/to/shapevo [mpirun]
set -euo pipefail
trap 'echo "signal_checkpoint.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
BIN=$(realpath "$1")
MPIRUN=${2:-mpirun}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
WORK=$(mktemp -d)
trap 'pkill -9 -f "$WORK" 2>/dev/null || true; rm -rf "$WORK"' EXIT
SETS=(--set ga.population=60 --set ga.elitism=6 --set ga.tournament=5 --set checkpoint.interval=0
      --set checkpoint.seconds=0 --set run.threads=1 --set ga.generations=100000)

for how in usr1-to-mpirun term-to-one-rank; do
    run="$WORK/$how"
    log="$WORK/$how.log"
    "$MPIRUN" --oversubscribe -np 2 "$BIN" run "$ROOT/configs/spaceship.toml" --out "$run" "${SETS[@]}" >"$log" 2>&1 &
    launcher=$!
    for _ in $(seq 1 100); do grep -q '^gen ' "$log" && break; sleep 0.1; done
    sleep 0.3
    if [ "$how" = usr1-to-mpirun ]; then
        kill -USR1 "$launcher"
    else
        kill -TERM "$(pgrep -P "$launcher" -f shapevo | tail -1)"
    fi
    status=0
    wait "$launcher" || status=$?
    if [ "$status" -ne 0 ]; then echo "$how: exit code $status"; cat "$log"; exit 1; fi
    grep -q "stopped on SIG" "$log" || { echo "$how: no stop message"; cat "$log"; exit 1; }
    last=$(grep -o 'gen *[0-9]*/' "$log" | tail -1 | tr -dc '0-9')
    newest=$("$BIN" inspect "$run" | awk '$1 == "generation" {print $2; exit}')
    echo "$how: $(grep 'stopped on' "$log")  (checkpoint at generation $newest)"
    [ "$newest" = "$last" ] || { echo "$how: checkpoint $newest is not the last generation $last"; exit 1; }
    "$MPIRUN" --oversubscribe -np 2 "$BIN" resume "$run" --generations $((last + 2)) -q
    grep -q "\"generations\": $((last + 2))" "$run/summary.json"
done
echo "both signals: checkpoint written, exit 0, resumed"
