#!/usr/bin/env bash
# Survive kill -9: start a 2-rank run, SIGKILL one rank at a random moment, resume, and repeat
# with 10 different moments. Every resume must succeed and lose at most one checkpoint interval
# (the newest complete checkpoint is at most `interval` generations behind the last generation
# the run reported before it died). Finally the run is resumed to its end.
# usage: tests/scripts/kill_resume.sh path/to/shapevo [mpirun]
set -euo pipefail
trap 'echo "kill_resume.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
BIN=$(realpath "$1")
MPIRUN=${2:-mpirun}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
WORK=$(mktemp -d)
trap 'pkill -9 -f "$WORK" 2>/dev/null || true; rm -rf "$WORK"' EXIT
RUN="$WORK/run"
INTERVAL=5
GENERATIONS=100000   # far more than the test will ever reach before the final resume
SETS=(--set ga.population=60 --set ga.elitism=6 --set ga.tournament=5 --set checkpoint.interval=$INTERVAL
      --set checkpoint.seconds=0 --set checkpoint.keep=2 --set migration.interval=2 --set migration.count=3
      --set run.threads=1 --set "ga.generations=$GENERATIONS")

newest_checkpoint() {  # generation of the newest complete checkpoint, via shapevo inspect ("" if none)
    { "$BIN" inspect "$RUN" 2>/dev/null || true; } | awk '$1 == "generation" {print $2; exit}'
}

RANDOM=${SEED:-4242}
for round in $(seq 1 10); do
    log="$WORK/round$round.log"
    if [ "$round" -eq 1 ]; then
        "$MPIRUN" --oversubscribe -np 2 "$BIN" run "$ROOT/configs/spaceship.toml" --out "$RUN" "${SETS[@]}" >"$log" 2>&1 &
    else
        "$MPIRUN" --oversubscribe -np 2 "$BIN" resume "$RUN" --generations $GENERATIONS >"$log" 2>&1 &
    fi
    launcher=$!
    # a random moment between 0.2 and 1.8 seconds after the ranks report their first generation
    for _ in $(seq 1 300); do grep -q '^gen ' "$log" && break; sleep 0.05; done
    delay=$(awk -v r=$RANDOM 'BEGIN {printf "%.2f", 0.2 + 1.6 * r / 32767}')
    sleep "$delay"
    ranks=$(pgrep -P "$launcher" -f shapevo || true)
    victim=$(echo "$ranks" | awk -v r=$RANDOM 'NF {a[n++] = $1} END {if (n) print a[r % n]}')
    if [ -z "$victim" ]; then echo "round $round: no rank to kill"; cat "$log"; exit 1; fi
    kill -9 "$victim" 2>/dev/null || true   # it may have died on its own a moment ago
    wait "$launcher" || true
    last=$( (grep -o 'gen *[0-9]*/' "$log" || true) | tail -1 | tr -dc '0-9')
    newest=$(newest_checkpoint)
    if [ -z "$newest" ]; then echo "round $round: no complete checkpoint after the kill"; cat "$log"; exit 1; fi
    last=${last:-$newest}   # killed before it reported a generation: nothing new to lose
    lost=$((last - newest))
    echo "round $round: killed rank pid $victim ${delay}s into the run, at generation $last; newest complete checkpoint $newest (lost $lost)"
    if [ "$lost" -gt "$INTERVAL" ]; then echo "lost more than one checkpoint interval"; exit 1; fi
done
# and the run can still finish: resume with a limit just past the newest checkpoint
target=$(( $(newest_checkpoint) + 3 ))
"$MPIRUN" --oversubscribe -np 2 "$BIN" resume "$RUN" --generations $target -q
test -f "$RUN/summary.json"
grep -q "\"generations\": $target" "$RUN/summary.json"
echo "resumed to generation $target after 10 kills"
