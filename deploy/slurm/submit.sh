#!/bin/bash
# A sweep as a Slurm job array of N slices, then their merge once every slice succeeded:
#   deploy/slurm/submit.sh N OUT SWEEP-OPTIONS...
#   deploy/slurm/submit.sh 8 /shared/sweep-1 --worlds /shared/worlds --noise none,small,realistic
# OUT must be on a file system every node shares; the shards write OUT/shard-0 ... OUT/shard-(N-1),
# the merge OUT/results.csv and OUT/summary.html. Run it from the project's folder (or set
# PROACTIVE_JAR to the jar's path). Prints the two job ids; 'squeue' shows them.
set -euo pipefail
n=${1:?N, the number of slices}
out=$(realpath -m "${2:?OUT, the sweep folder}")
shift 2
if ! [[ $n =~ ^[1-9][0-9]*$ ]]; then
  echo "N must be a whole number of slices, at least 1: $n" >&2
  exit 2
fi
for option in "$@"; do
  case $option in
  --shard | --shard=* | --out | --out=* | --jobs | --jobs=*)
    echo "give sweep's options but ${option%%=*}: each slice sets it (--jobs: its CPUs, --cpus-per-task)" >&2
    exit 2
    ;;
  esac
done
here=$(dirname "$0")
mkdir -p "$out"
export SWEEP_OUT=$out SWEEP_SHARDS=$n
array=$(sbatch --parsable --array=0-$((n - 1)) --chdir="$PWD" --output="$out/slurm-%A_%a.out" \
  --export=ALL "$here/sweep.sbatch" "$@")
array=${array%%;*}
# a slice that fails cancels the merge instead of leaving it pending for ever
merge=$(sbatch --parsable --dependency=afterok:"$array" --kill-on-invalid-dep=yes --chdir="$PWD" \
  --output="$out/slurm-merge-%j.out" --export=ALL "$here/merge.sbatch")
merge=${merge%%;*}
echo "array job $array ($n slices), merge job $merge; results in $out/results.csv"
