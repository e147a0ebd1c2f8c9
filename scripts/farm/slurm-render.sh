#!/usr/bin/env bash
# One chunk of a shot rendered by `celform render` as one task of a Slurm job array (docs/farm.md).
#
#   scripts/farm/slurm-render.sh PROJECT FIRST LAST CHUNK OUT [RENDER OPTION...]
#
# On a login node (no SLURM_ARRAY_TASK_ID) it submits itself with one array task per CHUNK frames
# of FIRST-LAST; in a task it renders frames FIRST + ID * CHUNK ... (at most CHUNK of them, not
# past LAST) into OUT, a pattern such as /renders/sh010/sh010_####.exr. Example:
#
#   scripts/farm/slurm-render.sh sh010.celform 1 240 10 /renders/sh010/sh010_####.exr --size 1920x1080
#
# submits tasks 0-23 (frames 1-10, 11-20, ..., 231-240). A task run again (requeued after a node
# failure, or resubmitted with `sbatch --array=5,17 scripts/farm/slurm-render.sh ...` with the same
# arguments) keeps the frames already written (--skip-existing) and renders the rest. Task IDs are
# chunk numbers, so resubmitting some of them renders the same frames as the first time.
#
# Environment: CELFORM, the celform binary (default: celform on PATH); SBATCH_EXTRA, more sbatch
# options at submission (a partition, an account). Nodes need no X server and no display.
#
# The defaults below are for a 1920x1080 shot: about 0.2 GB a frame (88 bytes a pixel, 120 for an
# EXR with every pass), so 4 frames at once fit well in 4 GB. The submission's --array overrides
# the one here.
#SBATCH --job-name=celform-render
#SBATCH --array=0-23
#SBATCH --cpus-per-task=4
#SBATCH --mem=4G
#SBATCH --time=02:00:00
#SBATCH --requeue
#SBATCH --output=celform-render-%A_%a.log
set -euo pipefail

usage() {
  echo "usage: $0 PROJECT FIRST LAST CHUNK OUT [RENDER OPTION...]" >&2
  exit 2
}

# A whole number in decimal (bash would read a leading zero as octal), or a failure.
integer() {
  [[ $1 =~ ^(-?)([0-9]+)$ ]] || return 1
  echo "${BASH_REMATCH[1]}$((10#${BASH_REMATCH[2]}))"
}

[ $# -ge 5 ] || usage
project=$1
first=$(integer "$2") || usage
last=$(integer "$3") || usage
chunk=$(integer "$4") || usage
out=$5
shift 5
if [ "$chunk" -lt 1 ] || [ "$first" -gt "$last" ]; then
  usage
fi
tasks=$(((last - first) / chunk + 1))

if [ -z "${SLURM_ARRAY_TASK_ID:-}" ]; then
  # Submission: the output folder exists before any task starts; paths are made absolute, since the
  # tasks may start in another folder.
  project=$(realpath -- "$project")
  mkdir -p -- "$(dirname -- "$out")"
  out=$(realpath -m -- "$out")
  # shellcheck disable=SC2086 # SBATCH_EXTRA holds several options
  exec sbatch ${SBATCH_EXTRA:-} --array="0-$((tasks - 1))" "$0" "$project" "$first" "$last" "$chunk" "$out" "$@"
fi

task=$SLURM_ARRAY_TASK_ID
if [ "${SLURM_ARRAY_TASK_COUNT:-$tasks}" -lt "$tasks" ]; then
  echo "warning: this array has $SLURM_ARRAY_TASK_COUNT tasks and the shot $tasks chunks (fine for a resubmission)" >&2
fi
start=$((first + task * chunk))
end=$((start + chunk - 1))
if [ "$end" -gt "$last" ]; then
  end=$last
fi
if [ "$start" -gt "$last" ]; then
  echo "task $task: no frames (the shot has $tasks chunks of $chunk)"
  exit 0
fi

threads=${SLURM_CPUS_PER_TASK:-1}
echo "task $task on $(hostname): frames $start-$end, $threads at a time, into $out"
# celform render needs no display; offscreen keeps any Qt plugin from looking for one.
export QT_QPA_PLATFORM=offscreen
mkdir -p -- "$(dirname -- "$out")"
# Exit codes: 0 done, 2 usage error, 3 bad input or a frame that could not be written (the line
# before names it). Slurm marks the task failed on anything but 0; the frames written stay.
exec "${CELFORM:-celform}" render "$project" --frames "$start-$end" --out "$out" --skip-existing \
  --threads "$threads" "$@"
