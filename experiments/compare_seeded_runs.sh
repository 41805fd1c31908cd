#!/bin/sh
# Seeded runs give the same best genomes and curves with two builds (issue "Layers": nothing else
# changes). Runs every config in configs/ with a small budget and a fixed seed under OLD and NEW,
# then compares, per config: best.genome (bytes 24..31, the grammar hash, are skipped: its hash
# function may differ between the builds), and curve.csv without its wall-time column.
#
#   experiments/compare_seeded_runs.sh OLD/shapevo NEW/shapevo [seed]
# Prints one line per config and exits 1 if any differs.
set -eu
old=$1
new=$2
seed=${3:-5}
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
small="--set ga.population=40 --set ga.elitism=6 --set ga.tournament=5 --set ga.generations=12 --set run.wall_time=0 --threads 2 -q"
status=0
strip_genome() { od -An -v -tx1 "$1" | tr -s ' \n' '  ' | cut -d' ' -f1-25,34-; }
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
        echo "$name: DIFFERENT"; diff "$work/old-$name/curve.csv" "$work/new-$name/curve.csv" | head -5; status=1
    fi
done
exit $status
