#!/bin/bash
# shapevo on a set of machines without a batch system: OpenMPI's mpirun over a hostfile.
#
#   cluster/mpirun-hostfile.sh HOSTFILE CONFIG [RUN_DIR]
#
# RUN_DIR defaults to runs/<config name>-mpi. If RUN_DIR already holds a checkpoint, the run
# is resumed from the newest complete one; otherwise a new run starts. One island per CPU
# socket of every host in HOSTFILE (see cluster/hostfile.example); each island evaluates on
# the cores of its socket.
#
# Stopping: Ctrl-C, `kill PID` (SIGTERM), `kill -HUP PID` or `kill -USR1 PID` on this script
# all make shapevo finish the current generation, write a checkpoint and exit 0; run the same
# command again to continue.
#
# Environment:
#   SHAPEVO        the shapevo binary, at the same path on every host
#                  (default: shapevo on PATH, else build/shapevo)
#   MPIRUN         the mpirun command (default: mpirun)
#   MAP_BY         rank placement (default: ppr:1:socket; ppr:1:package on Open MPI 5);
#                  each rank is bound to a socket and uses all of its cores
#   MPIRUN_FLAGS   more mpirun options, split at spaces, e.g. "--allow-run-as-root" or
#                  "-x LD_LIBRARY_PATH --prefix /opt/openmpi"
set -euo pipefail

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
    echo "usage: cluster/mpirun-hostfile.sh HOSTFILE CONFIG [RUN_DIR]" >&2
    exit 2
fi
HOSTFILE=$1
CONFIG=$2
RUN_DIR=${3:-runs/$(basename "$CONFIG" .toml)-mpi}
SHAPEVO=${SHAPEVO:-$(command -v shapevo || echo build/shapevo)}
MPIRUN=${MPIRUN:-mpirun}
MAP_BY=${MAP_BY:-ppr:1:socket}
read -r -a extra_flags <<< "${MPIRUN_FLAGS:-}"

if [ ! -r "$HOSTFILE" ]; then
    echo "error: $HOSTFILE: cannot read the hostfile" >&2
    exit 2
fi

# Published checkpoints are RUN_DIR/checkpoint-NNNNNN (one being written is hidden).
if compgen -G "$RUN_DIR/checkpoint-*" >/dev/null; then
    cmd=(resume "$RUN_DIR")
else
    # run.threads=0: all cores the rank is bound to (one socket, --bind-to socket below).
    cmd=(run "$CONFIG" --out "$RUN_DIR" --set run.threads=0)
fi

# Signals. Open MPI's mpirun forwards SIGUSR1 (and SIGUSR2) to every rank, and SIGUSR1 is what
# makes shapevo checkpoint and stop. On SIGTERM or SIGINT, however, mpirun kills the job
# itself: SIGTERM to the ranks, then SIGKILL a few seconds later, which can cut a checkpoint
# short (the previous complete one survives, but the generations since are lost), and mpirun
# then exits 1 even when the ranks did checkpoint. So this script catches TERM, INT, HUP and
# USR1 and sends mpirun SIGUSR1 instead. mpirun runs in its own process group (set -m), so a
# Ctrl-C in the terminal reaches only this script, not mpirun directly; its stdin is
# /dev/null (shapevo reads none), so it never stops for reading the terminal from the
# background.
mpirun_pid=
signalled=0
# shellcheck disable=SC2317  # (invoked by the traps below)
stop_gracefully() {
    signalled=1
    echo "mpirun-hostfile.sh: $1: asking shapevo to finish the generation, checkpoint and stop" >&2
    if [ -n "$mpirun_pid" ]; then kill -USR1 "$mpirun_pid" 2>/dev/null || true; fi
}
trap 'stop_gracefully SIGTERM' TERM
trap 'stop_gracefully SIGINT' INT
trap 'stop_gracefully SIGHUP' HUP
trap 'stop_gracefully SIGUSR1' USR1

set -m
"$MPIRUN" --hostfile "$HOSTFILE" --map-by "$MAP_BY" --bind-to socket "${extra_flags[@]}" \
    "$SHAPEVO" "${cmd[@]}" </dev/null &
mpirun_pid=$!
set +m
if [ "$signalled" -eq 1 ]; then kill -USR1 "$mpirun_pid" 2>/dev/null || true; fi

# `wait` returns early when a trapped signal arrives; wait again until mpirun has exited.
# (127 from a later wait means mpirun's exit was already collected: keep that status.)
status=127
while :; do
    signalled=0
    rc=0
    wait "$mpirun_pid" || rc=$?
    if [ "$rc" -eq 127 ] && [ "$status" -ne 127 ]; then break; fi
    status=$rc
    [ "$signalled" -eq 1 ] || break
done
exit "$status"
