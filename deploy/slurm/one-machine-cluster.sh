#!/bin/bash
# A one-node Slurm cluster on this machine, for trying the job array (and for CI): munged,
# slurmctld and slurmd as root on private ports, with their state, logs and socket in DIR.
#   deploy/slurm/one-machine-cluster.sh start DIR   # then: export SLURM_CONF=DIR/slurm.conf
#   deploy/slurm/one-machine-cluster.sh stop DIR    # every daemon stopped by its pid
# Needs Debian's slurmctld, slurmd, slurm-client and munge. A real cluster has its own
# configuration: use deploy/slurm/submit.sh there.
set -euo pipefail
what=${1:?start or stop}
dir=$(realpath -m "${2:?the cluster folder}")
conf=$dir/slurm.conf

. "$(dirname "$0")/../stop-by-pid.sh"

case $what in
start)
  mkdir -p "$dir/munge" "$dir/ctld" "$dir/d"
  chmod 700 "$dir/munge"
  host=$(hostname -s)
  cat > "$conf" <<CONF
ClusterName=proactive
SlurmctldHost=$host
SlurmctldPort=${SLURMCTLD_PORT:-16817}
SlurmdPort=${SLURMD_PORT:-16818}
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/d
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
# no systemd, no cgroups
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
# a failed shard fails the merge at once (instead of leaving it waiting); no pause between waves
DependencyParameters=kill_invalid_depend
SchedulerParameters=batch_sched_delay=0
NodeName=$host CPUs=$(nproc) State=UNKNOWN
PartitionName=main Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  munged --force --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" \
    --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed" --key-file=/etc/munge/munge.key
  slurmctld -f "$conf" -i
  slurmd -f "$conf"
  export SLURM_CONF=$conf
  for _ in $(seq 150); do
    if sinfo -h -o %T 2>/dev/null | grep -qx idle; then
      echo "slurm cluster up in $dir: export SLURM_CONF=$conf"
      exit 0
    fi
    sleep 0.2
  done
  echo "the node did not come up within 30 s; logs in $dir" >&2
  sinfo >&2 || true
  exit 1
  ;;
stop)
  stop_pid slurmd "$dir/slurmd.pid" 10
  stop_pid slurmctld "$dir/slurmctld.pid" 10
  stop_pid munged "$dir/munge/munged.pid" 10
  ;;
*)
  echo "usage: $0 start|stop DIR" >&2
  exit 2
  ;;
esac
