#!/usr/bin/env bash
# An install works on its own: `cmake --install BUILD --prefix P` into a temporary prefix, then the
# demo config installed under P/share/shapevo runs from another directory with the installed
# binary (its grammar and target found relative to the installed config), and the installed man
# page formats. Nothing of the source tree is used after the install.
# usage: tests/scripts/install_demo.sh BUILD_DIR
set -euo pipefail
trap 'echo "install_demo.sh: failed at line $LINENO: $BASH_COMMAND" >&2' ERR
BUILD=$(realpath "$1")
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
PREFIX=$WORK/prefix
cmake --install "$BUILD" --prefix "$PREFIX" >"$WORK/install.log"
for f in bin/shapevo share/man/man1/shapevo.1 share/shapevo/configs/spaceship.toml share/shapevo/grammars/spaceship.grammar \
         share/shapevo/targets/spaceship-reachable.vdb share/shapevo/targets/shapegenetics/LICENSE \
         share/shapevo/cluster/slurm/shapevo.sbatch share/shapevo/docs/README.md share/shapevo/README.md; do
    [ -e "$PREFIX/$f" ] || { echo "install_demo.sh: $f was not installed" >&2; exit 1; }
done
[ -x "$PREFIX/share/shapevo/cluster/slurm/shapevo.sbatch" ] || { echo "install_demo.sh: the cluster scripts lost their x bit" >&2; exit 1; }
mkdir "$WORK/elsewhere"
cd "$WORK/elsewhere"
"$PREFIX/bin/shapevo" run "$PREFIX/share/shapevo/configs/spaceship.toml" --threads 1 -q >"$WORK/run.log" 2>&1 \
    || { cat "$WORK/run.log" >&2; exit 1; }
grep -q '"voxel_iou"' runs/spaceship/summary.json
[ -s runs/spaceship/best.png ]
if command -v man >/dev/null; then
    warnings=$(MANWIDTH=100 man --warnings=w -l "$PREFIX/share/man/man1/shapevo.1" 2>&1 >/dev/null)
    [ -z "$warnings" ] || { echo "install_demo.sh: man warned: $warnings" >&2; exit 1; }
fi
echo "install_demo.sh: installed into a temporary prefix, the demo ran from another directory"
