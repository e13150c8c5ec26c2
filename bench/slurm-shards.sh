#!/bin/bash
# Missions per minute of one sweep cut into 1, 2 and 4 Slurm slices (deploy/slurm/submit.sh),
# from submission to the merge's end, against one 'sweep --jobs 2' without Slurm. Starts a
# one-node cluster in /tmp/slurm-bench (deploy/slurm/one-machine-cluster.sh) and stops it after.
#   bench/slurm-shards.sh WORLDS_DIR [ROUNDS]
# Run from the project's folder after ./mvnw package; the figures in docs/experiments.md come
# from the 24 worlds generated there, under the three noise levels.
set -euo pipefail
worlds=${1:?a folder of world files}
rounds=${2:-2}
cl=/tmp/slurm-bench
deploy/slurm/one-machine-cluster.sh stop $cl >/dev/null 2>&1 || true
rm -rf $cl
deploy/slurm/one-machine-cluster.sh start $cl
export SLURM_CONF=$cl/slurm.conf
trap 'deploy/slurm/one-machine-cluster.sh stop $cl' EXIT
options=(--worlds "$worlds" --noise none,small,realistic)
missions() { tail -n +2 "$1" | wc -l; }
for _ in $(seq "$rounds"); do
  for n in 1 2 4; do
    out=/tmp/slurm-shards-$n
    rm -rf $out
    s=$(date +%s.%N)
    deploy/slurm/submit.sh $n $out "${options[@]}" >/dev/null
    while [ -n "$(squeue -h)" ]; do sleep 0.2; done
    e=$(date +%s.%N)
    awk -v a="$s" -v b="$e" -v n=$n -v m="$(missions $out/results.csv)" \
      'BEGIN { printf "%d slices: %d missions in %.1f s, %.1f missions per minute\n", n, m, b - a, m * 60 / (b - a) }'
  done
  out=/tmp/slurm-shards-one
  rm -rf $out
  s=$(date +%s.%N)
  java -jar app/target/proactive.jar sweep "${options[@]}" --jobs 2 --out $out >/dev/null 2>&1 || true
  e=$(date +%s.%N)
  awk -v a="$s" -v b="$e" -v m="$(missions $out/results.csv)" \
    'BEGIN { printf "one sweep --jobs 2, no Slurm: %d missions in %.1f s, %.1f missions per minute\n", m, b - a, m * 60 / (b - a) }'
done
