#!/bin/sh
# Instructions executed inside benchmark functions, two builds side by side (callgrind counts are
# exact and repeatable, so one pass each is enough): for a change that must cost nothing, such as
# the model-family seam (issue 42: search methods call the family's operators through one virtual
# call). Each benchmark runs with a fixed iteration count (--benchmark_min_time=0: one iteration
# per repetition) and only the functions a case names are counted (callgrind --toggle-collect):
# the benchmark functions, or for a whole search run the method's initialize and step (its
# evaluations included; not the target's loading, whose TBB threads spin a varying number of
# instructions). Prints one line per case: OLD and NEW instructions and NEW/OLD - 1.
#
#   experiments/callgrind_compare.sh OLD_BUILD NEW_BUILD [CASES]
# OLD_BUILD and NEW_BUILD are build folders (their bench/ programs are run), e.g. a second build
# folder of the commit before the change; CASES, a grep -E pattern, picks cases by name. Needs
# valgrind. incremental-recording counts the GA run that bench_incremental records spaceship's
# children of generations 11-60 with (SHAPEVO_BENCH_FROM=10), evaluations included; its timed
# part (scoring the recorded children) calls no search method.
set -euf  # -f: the function patterns below are not file globs
old=$1
new=$2
pick=${3:-.*}
export SHAPEVO_BENCH_FROM=10 SHAPEVO_BENCH_WARM=5
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# name | program | benchmark filter | repetitions | functions counted
step='*::initialize(shapevo::Evaluator&) *::step(shapevo::Evaluator&)'
cases="search-hybrid|bench_search_methods|BM_SearchRun/method:0/|1|$step
search-ga|bench_search_methods|BM_SearchRun/method:1/|1|$step
search-smc|bench_search_methods|BM_SearchRun/method:2/|1|$step
search-rjmcmc|bench_search_methods|BM_SearchRun/method:4/|1|$step
operators|bench_operators|.|200|*BM_*
derive|bench_derive|.|20|*BM_*
incremental-recording|bench_incremental|scene:3/incremental:1|1|$step"

instructions() {  # build program filter repetitions functions -> instructions inside those functions
    toggles=""
    for f in $5; do toggles="$toggles --toggle-collect=$f"; done
    # shellcheck disable=SC2086  # one word per option
    valgrind --tool=callgrind --callgrind-out-file="$work/out" $toggles \
        "$1/bench/$2" --benchmark_filter="$3" --benchmark_min_time=0 --benchmark_repetitions="$4" \
        --benchmark_report_aggregates_only=true > /dev/null 2>&1
    callgrind_annotate "$work/out" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1; exit}'
}

echo "case old new change"
echo "$cases" | grep -E "^($pick)[|]" | while IFS='|' read -r name program filter reps functions; do
    a=$(instructions "$old" "$program" "$filter" "$reps" "$functions")
    b=$(instructions "$new" "$program" "$filter" "$reps" "$functions")
    awk -v n="$name" -v a="$a" -v b="$b" 'BEGIN { printf "%s %.0f %.0f %+.3f%%\n", n, a, b, (b / a - 1) * 100 }'
done
