#!/usr/bin/env bash
# Integration test of `vigil slurm` against a real Slurm (scripts/slurm-local, a one-node cluster started
# and stopped here): the CI sweep as a job array of 3 tasks + the finalize job must give the results.csv of
# the single-machine gate sweep byte for byte; then, in a second sweep, one array task is cancelled in the
# middle, the finalize job must report the missing runs, and the resubmitted task must finish its shard to
# the same results.csv.
#   tests/cluster/slurm_test.sh BUILD_DIR GATE_SWEEP_DIR
# Exit 0 passed, 1 failed, 77 skipped (Slurm cannot start here: the reason is printed on one line).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "$1")
gate=$(realpath "$2")
vigil=$build/vigil
timeout_s=${VIGIL_SLURM_TEST_TIMEOUT:-600}
work=$(mktemp -d "${TMPDIR:-/tmp}/vigil-slurm-test.XXXXXX")
chmod 0755 "$work"  # munged (user munge) must reach its socket below
export VIGIL_SLURM_DIR=$work/cluster
export SLURM_CONF=$VIGIL_SLURM_DIR/slurm.conf

cleanup() {
  scripts/slurm-local down >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

say() { echo "slurm test: $*" >&2; }
fail() {
  say "FAILED: $*"
  exit 1
}

# Bad input first (no Slurm needed): one line, exit 2, nothing written.
expect_refused() {  # expect_refused WHAT COMMAND...: exit 2, one line on stderr, $work/bad not created
  local what=$1 status=0 err
  shift
  err=$("$@" 2>&1 >/dev/null) || status=$?
  [ $status -eq 2 ] || fail "$what: exit status $status, expected 2"
  [ "$(echo "$err" | wc -l)" -eq 1 ] || fail "$what: more than one line: $err"
  [ ! -e "$work/bad" ] || fail "$what: wrote $work/bad"
}
expect_refused "--shard 3/3" "$vigil" sweep configs/ci_sweep.yaml -o "$work/bad" --shard 3/3
expect_refused "--shard 0/0" "$vigil" sweep configs/ci_sweep.yaml -o "$work/bad" --shard 0/0
expect_refused "--tasks 0" "$vigil" slurm configs/ci_sweep.yaml -o "$work/bad" --tasks 0
expect_refused "--submit without sbatch" env PATH=/nonexistent "$vigil" slurm configs/ci_sweep.yaml -o "$work/bad" \
  --tasks 2 --submit

if ! up_log=$(scripts/slurm-local up 2>&1); then
  echo "slurm test: SKIPPED: the local Slurm cluster cannot start here: $(echo "$up_log" | tail -1)"
  exit 77
fi
[ -f "$gate/results.csv" ] || fail "no gate sweep at $gate (scripts/test runs it first)"

# Waits until none of the jobs $@ is pending or running (bounded by the timeout).
wait_jobs() {
  local deadline=$((SECONDS + timeout_s)) ids
  ids=$(IFS=,; echo "$*")
  while [ -n "$(squeue -h -j "$ids" -o %i 2>/dev/null)" ]; do
    [ $SECONDS -lt $deadline ] || fail "jobs $ids still queued after ${timeout_s}s: $(squeue -j "$ids")"
    sleep 1
  done
}

job_state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2; }

# Every run directory is complete (no half run, whatever happened to its task).
check_runs() {
  local d
  for d in "$1"/runs/*/; do
    case "$d" in *.tmp-*) continue ;; esac
    [ -f "$d/metrics.json" ] || fail "half-written run directory $d"
  done
}

# 1. The CI sweep as 3 array tasks + finalize.
start=$SECONDS
submit() {  # submit DIR: the CI sweep as 3 tasks + finalize; sets $array and $finalize
  local ids
  ids=$("$vigil" slurm configs/ci_sweep.yaml -o "$1" --tasks 3 --submit) || fail "vigil slurm --submit failed"
  array=$(echo "$ids" | sed -n 1p)
  finalize=$(echo "$ids" | sed -n 2p)
}
submit "$work/sharded"
[ -n "${finalize:-}" ] || fail "vigil slurm --submit printed no job ids"
wait_jobs "$array" "$finalize"
say "CI sweep as 3 Slurm tasks + finalize: $((SECONDS - start)) s (array $array, finalize $finalize)"
[ "$(job_state "$finalize")" = COMPLETED ] || fail "finalize job $finalize: $(job_state "$finalize"); $(cat "$work"/sharded/slurm/finalize_*.log)"
check_runs "$work/sharded"
cmp "$work/sharded/results.csv" "$gate/results.csv" || fail "results.csv of the 3 shards differs from the gate sweep"
for f in table2.md table3.md table4.md summary.md; do
  cmp "$work/sharded/$f" "$gate/$f" || fail "$f of the 3 shards differs from the gate sweep"
done

# 2. A second sweep: cancel task 1 once it has committed a run, then resubmit it.
submit "$work/cancelled"
mapfile -t shard1 < <("$vigil" sweep configs/ci_sweep.yaml --list --shard 1/3)
deadline=$((SECONDS + timeout_s))
until [ -f "$work/cancelled/runs/${shard1[0]}/metrics.json" ]; do
  [ $SECONDS -lt $deadline ] || fail "task 1 committed no run within ${timeout_s}s"
  sleep 0.2
done
scancel "${array}_1"
wait_jobs "$array" "$finalize"
check_runs "$work/cancelled"
missing=0
for id in "${shard1[@]}"; do [ -f "$work/cancelled/runs/$id/metrics.json" ] || missing=$((missing + 1)); done
[ $missing -gt 0 ] || fail "task 1 finished before it was cancelled: nothing to resubmit"
[ "$(job_state "$finalize")" = FAILED ] || fail "finalize job $finalize after a cancelled task: $(job_state "$finalize") (expected FAILED: runs are missing)"
grep -q "missing runs" "$work"/cancelled/slurm/finalize_"$finalize".log || fail "the finalize log does not report the missing runs"
say "task 1 cancelled with $missing of ${#shard1[@]} runs unfinished; finalize reported them"

resubmitted=$(sbatch --parsable --array=1 "$work/cancelled/slurm/array.sbatch")
resubmitted=${resubmitted%%;*}
finalize=$(sbatch --parsable --dependency=afterany:"$resubmitted" "$work/cancelled/slurm/finalize.sbatch")
finalize=${finalize%%;*}
wait_jobs "$resubmitted" "$finalize"
[ "$(job_state "$finalize")" = COMPLETED ] || fail "finalize job $finalize after the resubmission: $(job_state "$finalize")"
grep -Eq "[0-9]+ executed, [1-9][0-9]* resumed" "$work"/cancelled/slurm/"${resubmitted}"_1.log || fail "the resubmitted task did not resume its shard"
check_runs "$work/cancelled"
cmp "$work/cancelled/results.csv" "$gate/results.csv" || fail "results.csv after the resubmission differs from the gate sweep"
say "PASSED: 3 shards and a cancelled + resubmitted shard give the gate sweep's results.csv byte for byte"
