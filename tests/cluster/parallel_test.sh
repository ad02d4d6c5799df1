#!/usr/bin/env bash
# ctest cluster_parallel (label cluster, issue 56): docs/sharding.md's GNU parallel recipe
# (scripts/cluster/prove-parallel) gives the unsplit run's ledger; with a part lost, the merge names the
# shard and exits 2, and rerunning the recipe runs that shard alone (the others' parts stay untouched).
#   parallel_test.sh GSDOT3 SOURCE_DIR WORK_DIR
set -euo pipefail
gsdot3=$1 src=$2 work=$3
cluster=$src/scripts/cluster
same() { python3 "$src/tests/cluster/same_ledger.py" "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v parallel >/dev/null || fail "GNU parallel is not installed (Debian: parallel; scripts/setup installs it)"
rm -rf "$work"
mkdir -p "$work"
claim=eq9.rgb-sum
"$gsdot3" prove --claim "$claim" --json -o "$work/unsplit.json"

"$cluster"/prove-parallel "$gsdot3" "$work/parts" 8 --claim "$claim" >"$work/merged.json"
same "$work/merged.json" "$work/unsplit.json"

rm "$work/parts/part-5.json"
touch -d 2000-01-01 "$work"/parts/part-*.json
if "$gsdot3" prove merge "$work"/parts/part-*.json --json >/dev/null 2>"$work/merge.err"; then
  fail "the merge passed without shard 5"
else
  [[ $? == 2 ]] || fail "the merge without shard 5 did not exit 2"
fi
grep -x "gsdot3: error: merge: shard 5/8 is missing" "$work/merge.err" || fail "$(cat "$work/merge.err")"
"$cluster"/prove-parallel "$gsdot3" "$work/parts" 8 --claim "$claim" >"$work/merged.json"
same "$work/merged.json" "$work/unsplit.json"
rerun=$(find "$work/parts" -name 'part-*.json' -newer "$work/unsplit.json" -printf '%f\n')
[[ $rerun == part-5.json ]] || fail "the rerun wrote '$rerun', not part-5.json alone"
echo "cluster_parallel: passed"
