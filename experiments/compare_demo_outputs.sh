#!/bin/sh
# Every file the demo writes, byte for byte, from two builds (issue 40, "a quick demo": making the
# demo faster must not change what it writes). Runs `run configs/spaceship.toml` with OLD and with
# NEW, each with the wall and monotonic clocks standing still (a tiny LD_PRELOAD shim built here
# with cc), so that the curves, which plot time, come out the same; then compares every file of
# the two run folders with cmp. What differs between any two runs of one build is set aside
# first, and said: run-id and .lock (a random id, a pid); best.vdb's bytes 22-57 (the UUID OpenVDB
# writes into every file); the checkpoint's files compared as h5dump prints them, with the run id
# and the attribute checksums that cover it left out; MANIFEST by its names and sizes (its hashes
# cover the run id); summary.json without cache_bytes and max_rss_bytes (they depend on the
# threads' timing).
#
#   experiments/compare_demo_outputs.sh OLD/shapevo NEW/shapevo
# Prints one line per file and exits 1 if any differs. KEEP=1 keeps the folders.
set -eu
old=$1
new=$2
cd "$(dirname "$0")/.."
work=$(mktemp -d)
[ -n "${KEEP:-}" ] && echo "folders in $work" || trap 'rm -rf "$work"' EXIT
cat > "$work/still_clock.c" <<'C'
#define _GNU_SOURCE
#include <dlfcn.h>
#include <time.h>
int clock_gettime(clockid_t id, struct timespec* ts) {
    static int (*real)(clockid_t, struct timespec*);
    if (!real) real = (int (*)(clockid_t, struct timespec*))dlsym(RTLD_NEXT, "clock_gettime");
    if (id == CLOCK_MONOTONIC || id == CLOCK_REALTIME || id == CLOCK_MONOTONIC_RAW || id == CLOCK_MONOTONIC_COARSE ||
        id == CLOCK_REALTIME_COARSE || id == CLOCK_BOOTTIME) {
        ts->tv_sec = 1000000;
        ts->tv_nsec = 0;
        return 0;
    }
    return real(id, ts);
}
C
cc -shared -fPIC -O2 -o "$work/still_clock.so" "$work/still_clock.c" -ldl
for side in old new; do
    eval bin=\$$side
    LD_PRELOAD="$work/still_clock.so" "$bin" run configs/spaceship.toml -q --out "$work/$side" > "$work/$side.log" 2>&1 || {
        echo "$side run failed:"; tail -3 "$work/$side.log"; exit 1; }
done
h5view() { h5dump "$1" | tail -n +2 | sed "s/$2/RUN_ID/" | awk '/ATTRIBUTE "attributes_xxh3_64"/ { skip = 7 } skip { skip--; next } { print }'; }
status=0
for path in $(cd "$work/old" && find . -type f | sort) $(cd "$work/new" && find . -type f | sort); do
    echo "$path"
done | sort -u > "$work/files"
while read -r path; do
    a="$work/old/$path" b="$work/new/$path"
    name=$(basename "$path")
    if [ ! -f "$a" ] || [ ! -f "$b" ]; then result="only in $([ -f "$a" ] && echo old || echo new)"
    else
        case "$name" in
        run-id|.lock) result="skipped (random id, pid)"; echo "$path: $result"; continue ;;
        best.vdb) same() { [ "$(head -c 21 "$1" | od -An -tx1)$(tail -c +58 "$1" | od -An -tx1)" = \
                                "$(head -c 21 "$2" | od -An -tx1)$(tail -c +58 "$2" | od -An -tx1)" ]; }
                  note=" (UUID bytes 22-57 set aside)" ;;
        *.h5) same() { [ "$(h5view "$1" "$(cat "$work/old/run-id")")" = "$(h5view "$2" "$(cat "$work/new/run-id")")" ]; }
              note=" (as h5dump prints it, run id set aside)" ;;
        MANIFEST) same() { [ "$(cut -d' ' -f1,2 "$1")" = "$(cut -d' ' -f1,2 "$2")" ]; }
                  note=" (names and sizes)" ;;
        summary.json) same() { [ "$(grep -v -e cache_bytes -e max_rss_bytes "$1")" = "$(grep -v -e cache_bytes -e max_rss_bytes "$2")" ]; }
                      note=" (without cache_bytes, max_rss_bytes)" ;;
        *) same() { cmp -s "$1" "$2"; }; note="" ;;
        esac
        if same "$a" "$b"; then result="same$note"; else result="DIFFERENT$note"; fi
    fi
    case "$result" in same*) ;; *) status=1 ;; esac
    echo "$path: $result"
done < "$work/files"
exit $status
