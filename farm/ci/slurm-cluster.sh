#!/usr/bin/env bash
# A throw-away one-node Slurm cluster on this machine, for the farm test: munged,
# slurmctld and slurmd from Debian's packages (slurm-wlm, munge), every file (config, key,
# state, spool, logs, pid files, sockets) in one temporary folder, run as root.
#
#   farm/ci/slurm-cluster.sh DIR COMMAND [ARG...]
#
# starts the daemons with their state in DIR (created if missing), waits until the node
# is idle, runs COMMAND with SLURM_CONF pointing at the cluster (so sbatch, squeue,
# scancel, scontrol and sacct talk to it), then stops the daemons by their pid files —
# whatever happens: COMMAND fails, a daemon does not start, or this script is interrupted.
# Exits with COMMAND's status (or 1 when the cluster does not come up). Daemon logs stay in
# DIR/log.
set -euo pipefail

dir=$(mkdir -p "$1" && cd "$1" && pwd)
shift
mkdir -p "$dir"/{ctld,spool,log,run}
chmod 700 "$dir"

stop_daemons() {
  local pidfile pid
  # Jobs first, so no slurmstepd or animate outlives the cluster.
  if [[ -s $dir/run/slurmctld.pid ]] && kill -0 "$(<"$dir/run/slurmctld.pid")" 2>/dev/null; then
    SLURM_CONF=$dir/slurm.conf scancel --partition=ci 2>/dev/null || true
    for _ in $(seq 100); do
      [[ -z $(SLURM_CONF=$dir/slurm.conf squeue -h 2>/dev/null) ]] && break
      sleep 0.1
    done
  fi
  for pidfile in "$dir"/run/slurmd.pid "$dir"/run/slurmctld.pid "$dir"/run/munged.pid; do
    [[ -s $pidfile ]] || continue
    pid=$(<"$pidfile")
    kill -TERM "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
  done
}
# On SIGINT/SIGTERM: stop COMMAND too, then the EXIT trap stops the daemons.
child=
on_signal() {
  [[ -n $child ]] && kill -TERM "$child" 2>/dev/null
  exit "$1"
}
trap stop_daemons EXIT
trap 'on_signal 130' INT
trap 'on_signal 143' TERM

# Two free TCP ports for slurmctld and slurmd.
free_port() {
  local p
  while :; do
    p=$((20000 + RANDOM % 20000))
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null; then echo "$p"; return; fi
  done
}
ctld_port=$(free_port)
slurmd_port=$(free_port)
while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(free_port); done

host=$(hostname -s)
cpus=$(nproc)

# munge: a fresh key and our own socket.
dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge.key"
munged --force --key-file="$dir/munge.key" --socket="$dir/run/munge.socket" \
  --pid-file="$dir/run/munged.pid" --log-file="$dir/log/munged.log" \
  --seed-file="$dir/munge.seed"

cat >"$dir/slurm.conf" <<CONF
ClusterName=whitted-ci
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/run/munge.socket
StateSaveLocation=$dir/ctld
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/run/slurmctld.pid
SlurmdPidFile=$dir/run/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SchedulerParameters=defer_batch=0
SlurmctldParameters=enable_configless=no
MinJobAge=600
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=ci Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf

slurmctld -i -f "$SLURM_CONF"
slurmd -f "$SLURM_CONF" -N "$host"

for _ in $(seq 100); do
  state=$(sinfo -h -n "$host" -o %t 2>/dev/null || true)
  [[ $state == idle ]] && break
  sleep 0.2
done
if [[ ${state:-} != idle ]]; then
  echo "slurm-cluster: the node did not become idle (state: '${state:-none}'); logs:" >&2
  tail -n 20 "$dir"/log/*.log >&2 || true
  exit 1
fi

# In the background so that a signal is handled at once, not when COMMAND ends.
"$@" &
child=$!
status=0
wait "$child" || status=$?
child=
exit "$status"
