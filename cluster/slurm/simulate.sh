#!/bin/bash
# Check shapevo.sbatch's run -> signal -> requeue -> resume cycle on a machine without Slurm.
#
#   cluster/slurm/simulate.sh [path/to/shapevo]      (default: build/shapevo)
#
# A fake `srun` (mpirun --oversubscribe -np $FAKE_NP, 2 by default) and a fake `scontrol`
# (records its arguments) come first on PATH; SLURM_* variables are set by hand. Each "job"
# runs the batch script as Slurm would; where Slurm would send --signal=USR1@300, this script
# sends SIGUSR1 to the job's ranks itself. The config is configs/spaceship.toml with
# ga.generations = 2000 (so a job stops on the signal long before the end) and absolute paths.
# Runs as root too (OMPI_ALLOW_RUN_AS_ROOT). Exit 0 when every check passes.
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SHAPEVO=$(realpath "${1:-$ROOT/build/shapevo}")
SBATCH_SCRIPT=$ROOT/cluster/slurm/shapevo.sbatch
WORK=$(mktemp -d "${TMPDIR:-/tmp}/shapevo-slurm-sim.XXXXXX")
RUN_DIR=$WORK/runs/long-slurm
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
job_pid=
# The ranks of the job under test: children of the mpirun that the fake srun became, a child
# of the batch script. (Found by parentage, never by name: other shapevo runs may be going.)
ranks_of_job() {
    local launcher
    for launcher in $(pgrep -P "$job_pid" -x mpirun || true); do pgrep -P "$launcher" || true; done
}
cleanup() {
    if [ -n "$job_pid" ]; then
        for pid in $(ranks_of_job); do kill -9 "$pid" 2>/dev/null || true; done
        kill "$job_pid" 2>/dev/null || true
    fi
    rm -rf "$WORK"
}
trap cleanup EXIT

mkdir -p "$WORK/bin" "$WORK/runs"
cat > "$WORK/bin/srun" <<'EOF'
#!/bin/bash
# fake srun: drop srun's own options, start the program on FAKE_NP ranks
echo "srun options: ${*%% /*}" >> "$SIM_WORK/srun.log"
while [ $# -gt 0 ] && [ "${1#-}" != "$1" ]; do shift; done
exec mpirun --oversubscribe -np "${FAKE_NP:-2}" "$@"
EOF
cat > "$WORK/bin/scontrol" <<'EOF'
#!/bin/bash
# fake scontrol: record the request
echo "scontrol $*" >> "$SIM_WORK/scontrol.log"
EOF
chmod +x "$WORK/bin/srun" "$WORK/bin/scontrol"
: > "$WORK/scontrol.log"
sed -e "s#\"\\.\\./#\"$ROOT/#" -e 's#^generations = .*#generations = 2000#' \
    "$ROOT/configs/spaceship.toml" > "$WORK/long.toml"
grep -q '^generations = 2000' "$WORK/long.toml"

fail() { echo "FAIL: $*" >&2; exit 1; }

# job N [signal-after-seconds [SIGNAL]]: run the batch script once, as Slurm would start it,
# from $WORK (the submit folder); optionally signal its ranks as --signal would.
job() {
    local n=$1 after=${2:-} sig=${3:-USR1} log=$WORK/job$1.log pids=''
    (
        cd "$WORK"
        export PATH="$WORK/bin:$PATH" SIM_WORK=$WORK SHAPEVO SLURM_JOB_ID=4242 \
               SLURM_CPUS_PER_TASK=1 SLURM_NTASKS=${FAKE_NP:-2} SLURM_JOB_NODELIST=localhost \
               SLURM_RESTART_COUNT=$((n - 1))
        exec bash "$SBATCH_SCRIPT" long.toml runs/long-slurm
    ) > "$log" 2>&1 &
    job_pid=$!
    if [ -n "$after" ]; then
        # wait for the first progress line: the ranks are up and have their signal handlers
        # (installed before generation 1; a --signal never comes that early on Slurm)
        for _ in $(seq 300); do
            grep -q '^gen ' "$log" 2>/dev/null && break
            sleep 0.05
        done
        sleep "$after"
        pids=$(ranks_of_job | tr '\n' ' ')
        [ "$(wc -w <<< "$pids")" -eq "${FAKE_NP:-2}" ] || fail "job $n: ranks not found ($pids)"
        # shellcheck disable=SC2086  # a list of pids
        kill -"$sig" $pids
    fi
    local rc=0
    wait "$job_pid" || rc=$?
    job_pid=
    echo "--- job $n (exit $rc):"
    sed 's/^/    /' "$log"
    return "$rc"
}
generation() { "$SHAPEVO" inspect "$RUN_DIR" | awk '$1 == "generation" { print $2; exit }'; }
requeues() { grep -c 'requeue' "$WORK/scontrol.log" || true; }

# 1. First start: a new run; the time-limit warning stops it; the job requeues itself.
job 1 0.3 || fail "job 1 exited non-zero"
grep -q '^shapevo run ' "$WORK/job1.log" || fail "job 1 did not start a new run"
grep -q '^stopped on SIGUSR1 after generation' "$WORK/job1.log" || fail "job 1 did not stop on SIGUSR1"
[ "$(requeues)" -eq 1 ] || fail "job 1 did not requeue"
grep -qx 'scontrol requeue 4242' "$WORK/scontrol.log" || fail "wrong requeue command"
grep -q -- '--kill-on-bad-exit=1 --cpus-per-task=1' "$WORK/srun.log" || fail "srun options"
grep -q '^threads = 1' "$RUN_DIR/config.toml" || fail "run.threads not stored in the run's config"
g1=$(generation)
echo "after job 1: checkpoint at generation $g1, $(requeues) requeue(s)"

# 2. The requeued job resumes; stopped again by the warning; requeues again.
job 2 0.3 || fail "job 2 exited non-zero"
grep -q "^resuming runs/long-slurm from .*(generation $g1)" "$WORK/job2.log" || fail "job 2 did not resume from $g1"
[ "$(requeues)" -eq 2 ] || fail "job 2 did not requeue"
g2=$(generation)
[ "$g2" -gt "$g1" ] || fail "no progress: $g1 -> $g2"
echo "after job 2: checkpoint at generation $g2, $(requeues) requeue(s)"

# 3. A stop on SIGTERM (scancel --signal=TERM) keeps the checkpoint but does not requeue.
job 3 0.3 TERM || fail "job 3 exited non-zero"
grep -q '^stopped on SIGTERM after generation' "$WORK/job3.log" || fail "job 3 did not stop on SIGTERM"
[ "$(requeues)" -eq 2 ] || fail "job 3 requeued after SIGTERM"
grep -q 'not requeueing' "$WORK/job3.log" || fail "job 3 did not say it does not requeue"
g3=$(generation)
echo "after job 3: checkpoint at generation $g3, $(requeues) requeue(s)"

# 4. Resubmitted with a generation limit close by: runs to the end, finishes, no requeue.
SHAPEVO_GENERATIONS=$((g3 + 15)) job 4 || fail "job 4 exited non-zero"
grep -q "^done: best fitness" "$WORK/job4.log" || fail "job 4 did not finish"
grep -q "shapevo finished at generation" "$WORK/job4.log" || fail "job 4 did not report the end"
[ "$(requeues)" -eq 2 ] || fail "job 4 requeued a finished run"
[ "$(generation)" -eq $((g3 + 15)) ] || fail "job 4 ended at $(generation), not $((g3 + 15))"
echo "after job 4: finished at generation $(generation), $(requeues) requeue(s)"

# The four jobs together equal one uninterrupted run to the same generation (same best model,
# same curve but for the wall-time column).
(cd "$WORK" && mpirun --oversubscribe -np 2 "$SHAPEVO" run long.toml --out runs/straight -q \
     --set run.threads=1 --set "ga.generations=$((g3 + 15))") > "$WORK/straight.log" 2>&1 \
    || { cat "$WORK/straight.log"; fail "the uninterrupted run failed"; }
[ "$(wc -l < "$RUN_DIR/curve.csv")" -eq $((g3 + 16)) ] || fail "curve.csv does not hold every generation"
cmp "$RUN_DIR/best.genome" "$WORK/runs/straight/best.genome" || fail "best.genome differs from the uninterrupted run"
diff <(cut -d, -f1,3- "$RUN_DIR/curve.csv") <(cut -d, -f1,3- "$WORK/runs/straight/curve.csv") >/dev/null \
    || fail "curve.csv differs from the uninterrupted run"
echo "jobs 1-4 equal an uninterrupted run of $((g3 + 15)) generations (best.genome, curve.csv)"

# 5. Another rank count is refused (non-zero exit, no requeue).
rc=0
FAKE_NP=3 job 5 || rc=$?
[ "$rc" -ne 0 ] || fail "job 5 resumed with 3 ranks"
grep -q 'holds 2 island(s) but 3 rank(s)' "$WORK/job5.log" || fail "job 5: no rank-count message"
[ "$(requeues)" -eq 2 ] || fail "job 5 requeued after a failure"

# 6. A run folder without a checkpoint is an error naming the folder, exit 2.
rm -rf "$RUN_DIR" && mkdir -p "$RUN_DIR"
rc=0
job 6 || rc=$?
[ "$rc" -eq 2 ] || fail "job 6 exited $rc, not 2"
grep -q 'holds no checkpoint to resume from' "$WORK/job6.log" || fail "job 6: no message"

echo "PASS: run, signal, requeue, resume, stop without requeue, finish, same as uninterrupted," \
     "rank-count refusal, empty folder"
