#!/usr/bin/env bash
# Reruns tasks of a render array that were cancelled or failed, and sets the video job
# waiting on the whole array again (Slurm marks its dependency never satisfied as soon as
# one task ends badly, and requeueing the task does not undo that).
#
#   farm/slurm/rerun.sh ARRAY_JOB VIDEO_JOB FIRST-LAST TASK...
#
# FIRST-LAST is the array's --array range (e.g. 1-16); TASK... the task ids to rerun. Each
# rerun renders only the frames its earlier attempts did not finish (`--resume`).
set -euo pipefail
usage="usage: rerun.sh ARRAY_JOB VIDEO_JOB FIRST-LAST TASK..."
array=${1:?$usage}
video=${2:?$usage}
range=${3:?$usage}
shift 3
(($# > 0)) || { echo "$usage" >&2; exit 2; }
for task in "$@"; do
  scontrol requeue "${array}_$task"
  # A requeued job waits a while before it may start again; it need not.
  scontrol update jobid="${array}_$task" StartTime=now
done
deps=$(seq -s: -f "${array}_%g" "${range%-*}" "${range#*-}")
scontrol update jobid="$video" dependency="afterok:$deps"
echo "rerun.sh: requeued ${*/#/${array}_}; job $video waits for ${array}_[$range] again"
