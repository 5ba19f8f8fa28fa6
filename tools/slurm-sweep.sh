#!/usr/bin/env bash
# The design sweep of examples/sweep.rs on a Slurm cluster: one job-array
# task per slice of the grid (`sweep --slice K/N`), then a merge job that
# waits for all of them (`sweep --merge`) and checks that the slices cover
# the grid exactly once. Slurm does the distribution; the sweep's runs
# share nothing, so nothing else is needed.
#
# Submit from the repository's root on a login node (the jobs run in the
# directory they were submitted from, on a shared file system):
#
#   cargo build --release --example sweep
#   tools/slurm-sweep.sh                   # 4 slices, into sweep-out/
#   SWEEP_SLICES=6 tools/slurm-sweep.sh    # 6 slices
#   SWEEP_ARGS="--grid small" tools/slurm-sweep.sh
#
# which submits, as you could by hand:
#
#   mkdir -p sweep-out
#   jobid=$(sbatch --parsable --array=1-4 tools/slurm-sweep.sh)
#   sbatch --dependency=afterany:$jobid --job-name=trackgen-sweep-merge \
#       --output=sweep-out/merge-%j.log --wrap "tools/slurm-sweep.sh merge"
#
# Array task K of N writes sweep-out/slice-K.csv (and its log
# sweep-out/slurm-<job>_<K>.log); the merge writes sweep-out/sweep.csv,
# the same file as `sweep --out sweep.csv` on one machine. The array must
# be numbered 1 to N (`--array=1-N`, with any `%limit`): task K runs
# `--slice K/$SLURM_ARRAY_TASK_COUNT`, and the sweep refuses K = 0. The
# merge runs even if a slice failed (`afterany`), and then names the grid
# points that are missing; a run that failed inside a slice is a row with
# its error, and the exit code of the slice and the merge is 1.
# `squeue --me` shows the jobs; `sacct -j <jobid>` how they ended.
#
# Settings (environment variables, passed on to the jobs):
#   SWEEP_SLICES  number of array tasks when submitting (default 4)
#   SWEEP_DIR     output folder (default sweep-out)
#   SWEEP_BIN     the sweep binary (default target/release/examples/sweep)
#   SWEEP_ARGS    more options for every sweep call, e.g. "--grid small"
#
# The #SBATCH lines are the array tasks' defaults; sbatch options on the
# command line override them. Each task runs its slice's variants on its
# cpus (rayon, RAYON_NUM_THREADS = the cpus per task).
#
#SBATCH --job-name=trackgen-sweep
#SBATCH --array=1-4
#SBATCH --ntasks=1
#SBATCH --cpus-per-task=4
#SBATCH --time=01:00:00
#SBATCH --output=sweep-out/slurm-%A_%a.log

set -euo pipefail

dir=${SWEEP_DIR:-sweep-out}
bin=${SWEEP_BIN:-target/release/examples/sweep}
# Word-split on purpose: several options.
read -r -a extra <<< "${SWEEP_ARGS:-}"

if [[ ! -x $bin ]]; then
  echo "slurm-sweep: no sweep binary at $bin (cargo build --release --example sweep, or set SWEEP_BIN)" >&2
  exit 1
fi

if [[ ${1:-} == merge ]]; then
  shopt -s nullglob
  files=("$dir"/slice-*.csv)
  if (( ${#files[@]} == 0 )); then
    echo "slurm-sweep: no slice CSVs in $dir to merge" >&2
    exit 1
  fi
  exec "$bin" ${extra[@]+"${extra[@]}"} --merge "${files[@]}" --out "$dir/sweep.csv"
elif [[ -n ${SLURM_ARRAY_TASK_ID:-} ]]; then
  # An array task: one slice.
  export RAYON_NUM_THREADS=${SLURM_CPUS_PER_TASK:-1}
  exec "$bin" ${extra[@]+"${extra[@]}"} --slice "$SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT" \
    --out "$dir/slice-$SLURM_ARRAY_TASK_ID.csv"
elif [[ $# -eq 0 ]]; then
  # On the login node: submit the array and the merge.
  slices=${SWEEP_SLICES:-4}
  if ! [[ $slices =~ ^[1-9][0-9]*$ ]]; then
    echo "slurm-sweep: SWEEP_SLICES must be a positive whole number, got '$slices'" >&2
    exit 1
  fi
  if ! command -v sbatch > /dev/null; then
    echo "slurm-sweep: no sbatch here: submit from a Slurm login node" >&2
    exit 1
  fi
  mkdir -p "$dir"
  if compgen -G "$dir/slice-*.csv" > /dev/null || [[ -e $dir/sweep.csv ]]; then
    echo "slurm-sweep: $dir holds the CSVs of an earlier sweep: move them, or set SWEEP_DIR" >&2
    exit 1
  fi
  array=$(sbatch --parsable --array="1-$slices" --output="$dir/slurm-%A_%a.log" "$0")
  array=${array%%;*}
  merge=$(sbatch --parsable --dependency="afterany:$array" --job-name=trackgen-sweep-merge \
    --output="$dir/merge-%j.log" --wrap "$(printf %q "$0") merge")
  merge=${merge%%;*}
  echo "submitted $slices slices as job $array and the merge as job $merge; results in $dir/sweep.csv"
else
  echo "usage: tools/slurm-sweep.sh          (submit, on a login node)" >&2
  echo "       tools/slurm-sweep.sh merge    (the merge job)" >&2
  exit 2
fi
