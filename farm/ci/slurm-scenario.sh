#!/usr/bin/env bash
# The farm test's scenario, run inside farm/ci/slurm-cluster.sh (SLURM_CONF set):
#
#   farm/ci/slurm-scenario.sh WORK FRAMES TASKS [FIRST END]
#
# WORK holds anim.toml (FRAMES frames, names frame_####.png, 25 fps). Submits the job files
# of farm/slurm as a user would — an array job of TASKS tasks numbered from 1 (so
# `--shard auto` must subtract SLURM_ARRAY_TASK_MIN) and the dependent video job — then
# cancels task 2 once it has written some of its frames and before it has written all,
# requeues it, and waits for the video job. Leaves WORK/frames, WORK/video.mp4 and the
# jobs' logs in WORK/log for the caller to check; FIRST and END (exclusive) are task 2's
# frames, when the caller knows them (render.sbatch balances the shards by predicted
# cost), else the equal-count chunk [F·1/T, F·2/T); exits non-zero, with the reason and
# the logs, when a job fails or a step takes too long. `ANIMATE` is the binary to run.
set -euo pipefail
work=$(cd "$1" && pwd)
frames=$2
tasks=$3
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work/log"

fail() {
  echo "slurm-scenario: $*" >&2
  squeue -o '%i %T %r' >&2 || true
  for f in "$work"/log/*; do echo "== $f" >&2; cat "$f" >&2; done
  exit 1
}

# Waits up to $1 seconds for the command after it to succeed.
wait_for() {
  local limit=$1 start=$SECONDS
  shift
  until "$@"; do
    ((SECONDS - start < limit)) || return 1
    sleep 0.1
  done
}

job_state() {
  { scontrol show job "$1" 2>/dev/null || true; } | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2 || true
}
is_state() { [[ $(job_state "$1") == "$2" ]]; }
gone_from_queue() { [[ -z $(squeue -h -j "$1" 2>/dev/null) ]]; }

# Task 2's chunk (index 1 of TASKS).
first=${4:-$((frames / tasks))}
end=${5:-$((2 * frames / tasks))}
chunk=()
for ((f = first; f < end; f++)); do
  chunk+=("$work/frames/$(printf 'frame_%04d.png' "$f")")
done
written() {
  local n=0 f
  for f in "${chunk[@]}"; do [[ -e $f ]] && n=$((n + 1)); done
  echo "$n"
}
some_written() { (($(written) > 0)); }

cd "$work"
# render.sbatch's own CPU request, as the README's line uses it: it must fit this cluster.
array=$(sbatch --parsable --array="1-$tasks" \
  --output="$work/log/render_%a.out" "$here/slurm/render.sbatch" anim.toml frames)
video=$(sbatch --parsable --dependency="afterok:$array" --cpus-per-task=1 \
  --output="$work/log/video.out" "$here/slurm/video.sbatch" anim.toml frames video.mp4)
echo "slurm-scenario: array job $array (tasks 1-$tasks), video job $video"

wait_for 60 is_state "${array}_2" RUNNING || fail "task 2 did not start"
wait_for 60 some_written || fail "task 2 wrote no frame"
scancel "${array}_2"
wait_for 60 is_state "${array}_2" CANCELLED || fail "task 2 was not cancelled"
done_before=$(written)
echo "slurm-scenario: cancelled task 2 with $done_before of ${#chunk[@]} frames written"
((done_before < ${#chunk[@]})) || fail "task 2 finished before it could be cancelled"
[[ $(job_state "$video") == PENDING ]] || fail "the video job did not wait for the frames"

# The rerun, as farm/README.md tells a user.
"$here/slurm/rerun.sh" "$array" "$video" "1-$tasks" 2
wait_for 120 gone_from_queue "$video" || fail "the video job did not finish"
for t in $(seq 1 "$tasks"); do
  state=$(job_state "${array}_$t")
  [[ $state == COMPLETED ]] || fail "task $t ended $state"
done
state=$(job_state "$video")
[[ $state == COMPLETED ]] || fail "the video job ended $state"
echo "slurm-scenario: every task and the video job COMPLETED"
