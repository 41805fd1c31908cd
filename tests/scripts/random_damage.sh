#!/usr/bin/env bash
# Damage and signals at random, 20 times each kind, on 2 MPI ranks: every damaged newest
# checkpoint is skipped on every rank together (never a hang: each command runs under
# `timeout`), another run's checkpoint is refused and left as it was, and every stop signal to a
# rank gives a checkpoint, exit 0 and a resume that finishes.
# usage: tests/scripts/random_damage.sh path/to/shapevo [mpirun] [repeats]
set -euo pipefail
trap 'echo "random_damage.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
BIN=$(realpath "$1")
MPIRUN=${2:-mpirun}
REPEATS=${3:-20}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
WORK=$(mktemp -d)
trap 'pkill -9 -f "$WORK" 2>/dev/null || true; rm -rf "$WORK"' EXIT
SETS=(--set ga.population=16 --set ga.elitism=2 --set ga.tournament=3 --set migration.interval=2
      --set migration.count=2 --set checkpoint.keep=10 --set run.threads=1 -q)
M=("$MPIRUN" --oversubscribe -np 2)
RANDOM=${SEED:-7}

# Two finished runs: the one to damage, and another (other seed) to take a foreign checkpoint from.
"${M[@]}" "$BIN" run "$ROOT/configs/spaceship.toml" --seed 3 --set ga.generations=20 --set checkpoint.interval=5 \
    --out "$WORK/base" "${SETS[@]}"
"${M[@]}" "$BIN" run "$ROOT/configs/spaceship.toml" --seed 4 --set ga.generations=30 --set checkpoint.interval=30 \
    --out "$WORK/other" "${SETS[@]}"

damage() {  # damage KIND RUN: spoil RUN's newest checkpoint (or add a foreign newer one)
    local k="$2/checkpoint-000020" files f size at
    files=(run.h5 island-0000.h5 island-0001.h5)
    f="$k/${files[RANDOM % 3]}"
    case "$1" in
    flip)      size=$(stat -c %s "$f"); at=$((RANDOM * 32768 + RANDOM)); at=$((at % size))
               printf "\\x$(printf %02x $((RANDOM % 255 + 1)))" | dd of="$f" bs=1 seek="$at" conv=notrunc 2>/dev/null
               # XOR would be nicer; any different byte is damage unless it equals the old one
               ;;
    truncate)  size=$(stat -c %s "$f"); truncate -s $((RANDOM % size)) "$f" ;;
    delete)    rm -f "$f" ;;
    unlisted)  cp "$f" "$k/extra.h5" ;;
    manifest)  sed -i "/^${f##*/} /d" "$k/MANIFEST" ;;
    foreign)   cp -r "$WORK/other/checkpoint-000030" "$2/" ;;
    esac
}

for kind in flip truncate delete unlisted manifest foreign; do
    for i in $(seq 1 "$REPEATS"); do
        run="$WORK/d-$kind-$i"
        cp -r "$WORK/base" "$run"
        before=$(md5sum "$run/checkpoint-000020/"* | md5sum)
        damage "$kind" "$run"
        after=$(md5sum "$run/checkpoint-000020/"* 2>/dev/null | md5sum)
        status=0
        timeout 120 "${M[@]}" "$BIN" resume "$run" --generations 24 -q > "$run.log" 2>&1 || status=$?
        if [ "$kind" = flip ] && [ "$before" = "$after" ]; then
            [ "$status" -eq 0 ] || { echo "$kind $i: undamaged resume failed ($status)"; cat "$run.log"; exit 1; }
        elif [ "$status" -ne 0 ]; then
            echo "$kind $i: resume exit $status (124 = hang)"; cat "$run.log"; exit 1
        elif ! grep -q "trying the one before it" "$run.log"; then
            echo "$kind $i: damage was not noticed"; cat "$run.log"; exit 1
        fi
        grep -q '"generations": 24' "$run/summary.json" || { echo "$kind $i: resume did not finish"; exit 1; }
        if [ "$kind" = foreign ]; then
            cmp -s "$run/checkpoint-000030/run.h5" "$WORK/other/checkpoint-000030/run.h5" ||
                { echo "foreign $i: the other run's checkpoint was touched"; exit 1; }
        fi
        rm -rf "$run" "$run.log"
    done
    echo "damage $kind: $REPEATS times skipped together, resumed to the end"
done

signals=(TERM USR1 INT HUP)
for s in "${signals[@]}"; do
    for i in $(seq 1 "$REPEATS"); do
        run="$WORK/s-$s-$i"
        log="$run.log"
        timeout 120 "${M[@]}" "$BIN" run "$ROOT/configs/spaceship.toml" --out "$run" "${SETS[@]}" \
            --set ga.generations=100000 --set checkpoint.interval=0 --set checkpoint.seconds=0 > "$log" 2>&1 &
        launcher=$!
        for _ in $(seq 1 200); do [ -d "$run" ] && [ -n "$(pgrep -f "shapevo run .*$run" || true)" ] && break; sleep 0.05; done
        sleep "0.$((RANDOM % 4 + 1))$((RANDOM % 10))"  # 0.10-0.49 s into the run
        ranks=($(pgrep -f "^$BIN run .*$run" || true))
        [ "${#ranks[@]}" -eq 2 ] || { echo "signal $s $i: expected 2 ranks, found ${#ranks[@]}"; cat "$log"; exit 1; }
        target=${ranks[RANDOM % 2]}
        kill "-$s" "$target"
        if [ $((RANDOM % 2)) -eq 0 ]; then sleep 0.0$((RANDOM % 2)); kill "-$s" "${ranks[RANDOM % 2]}" 2>/dev/null || true; fi
        status=0
        wait "$launcher" || status=$?
        [ "$status" -eq 0 ] || { echo "signal $s $i: exit $status"; cat "$log"; exit 1; }
        grep -q "stopped on SIG$s" "$log" || { echo "signal $s $i: no stop message"; cat "$log"; exit 1; }
        [ -z "$(pgrep -f "^$BIN run .*$run" || true)" ] || { echo "signal $s $i: orphaned ranks"; exit 1; }
        last=$(grep -o '"generations": [0-9]*' "$run/summary.json" | tr -dc '0-9')
        timeout 120 "${M[@]}" "$BIN" resume "$run" --generations $((last + 2)) -q > "$log" 2>&1 ||
            { echo "signal $s $i: resume failed"; cat "$log"; exit 1; }
        grep -q "\"generations\": $((last + 2))" "$run/summary.json"
        rm -rf "$run" "$log"
    done
    echo "signal $s to a random rank (sometimes twice): $REPEATS times checkpoint, exit 0, resumed"
done
