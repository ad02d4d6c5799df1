#!/usr/bin/env bash
# ctest cluster_slurm (label cluster, issue 56): a one-node Slurm cluster started here
# (scripts/cluster/slurm-one-node) runs docs/sharding.md's job array of a claim; the merged ledger must
# equal the unsplit run's. Then scripts/cluster/submit runs the same claim in 12 shards, two arrays under
# the cluster's MaxArraySize of 8, with one shard cancelled by the scheduler: the merge must name that
# shard and fail, and `submit --resubmit` must run that shard alone and complete the ledger. Last, a shard
# killed by the scheduler while it runs (scancel) must leave no part (prove -o writes at the end,
# atomically). The cluster is stopped by its own PIDs whatever happens.
#   slurm_test.sh GSDOT3 SOURCE_DIR WORK_DIR
set -euo pipefail
gsdot3=$1 src=$2 work=$3
cluster=$src/scripts/cluster
same() { python3 "$src/tests/cluster/same_ledger.py" "$@"; }
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
trap '"$cluster"/slurm-one-node stop "$work/slurm"' EXIT
eval "$("$cluster"/slurm-one-node start "$work/slurm" MaxArraySize=8)"  # array indices 0-7: submit splits 12 shards
sinfo -N
claim=eq9.rgb-sum
"$gsdot3" prove --claim "$claim" --json -o "$work/unsplit.json"

echo "== the job array of docs/sharding.md, 8 shards of $claim"
mkdir -p "$work/parts"
job=$(sbatch --parsable --array=0-7 -o "$work/parts/%a.out" \
  "$cluster"/prove-shard.sbatch "$gsdot3" "$work/parts" 8 --claim "$claim")
while squeue -h -j "$job" | grep -q .; do sleep 0.2; done  # sbatch --wait polls every 30 s
"$gsdot3" prove merge "$work"/parts/part-*.json --json -o "$work/merged.json"
same "$work/merged.json" "$work/unsplit.json"

echo "== scripts/cluster/submit, 12 shards in two arrays (MaxArraySize 8), shard 3 cancelled before it ran"
out=$("$cluster"/submit --gsdot3 "$gsdot3" --claim "$claim" --shards 12 --sbatch --hold "$work/run")
echo "$out"
mapfile -t jobs < <(sed -n 's/^submit: .*: job \([0-9]*\), shards.*/\1/p' <<<"$out")
[[ ${#jobs[@]} == 2 ]] || fail "submit did not split 12 shards into two arrays"
grep -q "job ${jobs[0]}, shards 0-7 of 12$" <<<"$out" && grep -q "job ${jobs[1]}, shards 8-11 of 12$" <<<"$out" ||
  fail "the arrays do not hold shards 0-7 and 8-11"
scancel "${jobs[0]}_3"
scontrol release "${jobs[@]}" "$(sed -n 's/^submit: .*: merge job \([0-9]*\) .*/\1/p' <<<"$out")"
for _ in $(seq 600); do [[ -s $work/run/$claim/status ]] && break; sleep 0.2; done
[[ $(cat "$work/run/$claim/status") == 2 ]] || fail "the merge did not fail on the missing shard"
grep -x "gsdot3: error: merge: shard 3/12 is missing" "$work/run/$claim/merge.out" ||
  fail "the merge did not name shard 3: $(cat "$work/run/$claim/merge.out")"
[[ ! -e $work/run/$claim.json ]] || fail "a ledger was written without shard 3"
[[ -s $work/run/$claim/part-11.json ]] || fail "the second array (offset 8) left no part-11.json"

echo "== submit --resubmit: shard 3 alone"
out=$("$cluster"/submit --resubmit --wait "$work/run")
echo "$out"
grep -q "^submit: $claim: job [0-9]*, shards 3 of 12$" <<<"$out" || fail "the resubmission was not shard 3 alone"
same "$work/run/$claim.json" "$work/unsplit.json"

echo "== a running shard killed by the scheduler leaves no part"
# two-pass.error-bound's shards scan their whole slice (docs/sharding.md): seconds, long enough to kill.
mkdir -p "$work/killed"
job=$(sbatch --parsable --array=0 -o "$work/killed/%a.out" \
  "$cluster"/prove-shard.sbatch "$gsdot3" "$work/killed" 8 --claim two-pass.error-bound)
for _ in $(seq 300); do [[ $(squeue -h -j "$job" -o %T) == RUNNING ]] && break; sleep 0.1; done
[[ $(squeue -h -j "$job" -o %T) == RUNNING ]] || fail "shard 0 of two-pass.error-bound did not start"
sleep 1
scancel "$job"
while squeue -h -j "$job" | grep -q .; do sleep 0.2; done
[[ ! -e $work/killed/part-0.json ]] || fail "the killed shard left a part"
grep -q "CANCELLED" "$work/killed/0.out" || fail "the shard was not cancelled: $(cat "$work/killed/0.out")"
echo "cluster_slurm: passed"
