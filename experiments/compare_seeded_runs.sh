#!/bin/sh
# Seeded runs give the same best genomes and curves with two builds (issue "Layers": nothing else
# changes). Runs every config in configs/ with a small budget and a fixed seed under OLD and NEW,
# then compares, per config: best.genome (its header's version and grammar hash are skipped: the
# file version and the hash function may differ between builds), and curve.csv without its
# wall-time column. KEEP=1 keeps the run folders (their path is printed by sh -x).
#
#   experiments/compare_seeded_runs.sh OLD/shapevo NEW/shapevo [seed]
# Prints one line per config and exits 1 if any differs.
set -eu
old=$1
new=$2
seed=${3:-5}
cd "$(dirname "$0")/.."
work=$(mktemp -d)
[ -n "${KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
small="--set ga.population=40 --set ga.elitism=6 --set ga.tournament=5 --set ga.generations=12 --set run.wall_time=0 --threads 2 -q"
status=0
# genes, words and reserved (bytes 12..23), then the words (from byte 32): the magic, the version
# and the grammar hash may differ between builds
strip_genome() { head -c 24 "$1" | tail -c +13 | od -An -v -tx1; tail -c +33 "$1" | od -An -v -tx1; }
strip_curve() { cut -d, -f1,3- "$1"; }  # drop column 2, the wall time
for cfg in configs/*.toml; do
    name=$(basename "$cfg" .toml)
    for side in old new; do
        eval bin=\$$side
        "$bin" run "$cfg" --seed "$seed" $small --out "$work/$side-$name" > "$work/$side-$name.log" 2>&1 || {
            echo "$name: $side run failed:"; tail -3 "$work/$side-$name.log"; status=1; continue 2; }
    done
    if [ "$(strip_genome "$work/old-$name/best.genome")" = "$(strip_genome "$work/new-$name/best.genome")" ] &&
       [ "$(strip_curve "$work/old-$name/curve.csv")" = "$(strip_curve "$work/new-$name/curve.csv")" ]; then
        echo "$name: same best genome and curve ($(tail -1 "$work/new-$name/curve.csv" | cut -d, -f1,4))"
    else
        echo "$name: DIFFERENT"; strip_curve "$work/old-$name/curve.csv" > "$work/a"; strip_curve "$work/new-$name/curve.csv" > "$work/b"
        diff "$work/a" "$work/b" | head -5; status=1
    fi
done
exit $status
