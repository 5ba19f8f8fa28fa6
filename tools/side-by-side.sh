#!/usr/bin/env bash
# Whole-command wall time of two builds of the main job, interleaved so
# that the machine's drift falls on both alike: best and median of N
# pairs, in ms.
#
#   tools/side-by-side.sh OLD_BINARY NEW_BINARY [N=30] [-- ARGS...]
#
# e.g. (docs/performance.md): build two commits of the main job with
# `cargo build --release -p trackgen-cli`, copy each `target/release/trackgen`
# aside, then
#   tools/side-by-side.sh /tmp/trackgen_old /tmp/trackgen_new 30
set -euo pipefail
old=$1 new=$2 n=${3:-30}
shift $(( $# < 3 ? $# : 3 ))
[ "${1:-}" = "--" ] && shift
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for _ in $(seq "$n"); do
  for which in old new; do
    bin=$old; [ "$which" = new ] && bin=$new
    start=$(date +%s%N)
    "$bin" --out "$out/$which" "$@" >/dev/null 2>&1
    end=$(date +%s%N)
    echo $(( (end - start) / 1000 )) >> "$out/$which.us"
  done
done
for which in old new; do
  sort -n "$out/$which.us" | awk -v w="$which" '{a[NR] = $1}
    END {printf "%s: best %.1f ms, median %.1f ms (%d runs)\n", w, a[1] / 1000, a[int((NR + 1) / 2)] / 1000, NR}'
done
