#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for the tests and for trying `--slurm`
# (docs/cluster.md): munged with a fresh key, slurmctld and slurmd with a generated
# slurm.conf for this host, all in one temporary folder, as root or not, without systemd.
# Debian's packages slurm-wlm and munge (scripts/debian-packages.txt) provide them.
#
#   eval "$(scripts/slurm-local.sh start)"   # prints: export SLURM_CONF=DIR/slurm.conf
#   sbatch/squeue/sinfo ...                  # with that SLURM_CONF
#   scripts/slurm-local.sh status [DIR]      # is it up (DIR: default $SLURM_CONF's folder)
#   scripts/slurm-local.sh stop [DIR]        # cancels its jobs, stops every daemon and
#                                            # process it started, removes DIR
#
# start exits 3 when slurm-wlm or munge is not installed, 1 when the cluster does not come
# up (its logs are printed). The ports are free ones picked at start, so that two clusters
# (two test runs) do not meet. stop ends only the processes of this cluster: its daemons
# (their pid files) and its jobs' processes (those whose environment names its slurm.conf).
set -euo pipefail

die() { echo "slurm-local: $*" >&2; exit 1; }

dir_of() {
  if [ $# -gt 0 ] && [ -n "$1" ]; then echo "$1"; return; fi
  [ -n "${SLURM_CONF:-}" ] || die "give the cluster's folder, or set SLURM_CONF (from start)"
  dirname "$SLURM_CONF"
}

free_port() {
  python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# The pids of this cluster's job processes: their environment names its slurm.conf.
job_pids() {
  grep -lzxF "SLURM_CONF=$1" /proc/[0-9]*/environ 2>/dev/null | cut -d/ -f3
}

stop() {
  local dir conf pid f n
  dir=$(dir_of "${1:-}")
  conf=$dir/slurm.conf
  [ -f "$conf" ] || { echo "slurm-local: no cluster in $dir" >&2; return 0; }
  export SLURM_CONF=$conf
  if [ -f "$dir/slurmctld.pid" ] && kill -0 "$(cat "$dir/slurmctld.pid" 2>/dev/null)" 2>/dev/null; then
    scancel --full --quiet --user "$(id -un)" 2>/dev/null || true
    scontrol shutdown 2>/dev/null || true
  fi
  # munged has no shutdown command: its pid file.
  [ -f "$dir/munged.pid" ] && kill "$(cat "$dir/munged.pid" 2>/dev/null)" 2>/dev/null || true
  # Wait for the daemons to end (at most 5 s), then kill what is left, by pid.
  for n in $(seq 50); do
    alive=0
    for f in slurmctld slurmd munged; do
      if [ -f "$dir/$f.pid" ] && kill -0 "$(cat "$dir/$f.pid" 2>/dev/null)" 2>/dev/null; then alive=1; fi
    done
    [ $alive -eq 0 ] && break
    sleep 0.1
  done
  for f in slurmctld slurmd munged; do
    if [ -f "$dir/$f.pid" ]; then
      pid=$(cat "$dir/$f.pid" 2>/dev/null)
      kill -0 "$pid" 2>/dev/null && kill -9 "$pid" 2>/dev/null || true
    fi
  done
  # The jobs' processes (slurmstepd and what it ran), if any outlived the daemons.
  for pid in $(job_pids "$conf"); do
    [ "$pid" != "$$" ] && kill -9 "$pid" 2>/dev/null || true
  done
  rm -rf "$dir"
  echo "slurm-local: stopped; removed $dir" >&2
}

status() {
  local dir
  dir=$(dir_of "${1:-}")
  [ -f "$dir/slurm.conf" ] || { echo "slurm-local: no cluster in $dir"; return 1; }
  SLURM_CONF=$dir/slurm.conf sinfo -h -o "%P %a %D %T %N" || return 1
}

start() {
  for p in slurmctld slurmd munged mungekey sbatch sinfo; do
    command -v "$p" >/dev/null 2>&1 || PATH=$PATH:/usr/sbin command -v "$p" >/dev/null 2>&1 || {
      echo "slurm-local: $p not found: install the Debian packages slurm-wlm and munge" \
        "(make deps)" >&2
      exit 3
    }
  done
  export PATH=$PATH:/usr/sbin
  local dir user host cpus mem ctld_port d_port
  dir=$(mktemp -d "${TMPDIR:-/tmp}/sunglint-slurm.XXXXXX")
  chmod 755 "$dir"
  user=$(id -un)
  host=$(hostname -s)
  cpus=$(nproc)
  mem=$(awk '/MemTotal/ {print int($2 / 1024 / 2)}' /proc/meminfo)
  ctld_port=$(free_port)
  d_port=$(free_port)
  while [ "$d_port" = "$ctld_port" ]; do d_port=$(free_port); done
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool"
  chmod 700 "$dir/munge"
  # munge: a fresh key, its socket in the folder (the key never leaves it).
  mungekey --create --keyfile="$dir/munge/munge.key" --bits=1024 >/dev/null 2>&1 ||
    die "mungekey could not create a key"
  chmod 600 "$dir/munge/munge.key"
  munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
    --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munge/seed" ||
    die "munged did not start: $(cat "$dir/munged.log" 2>/dev/null)"
  cat >"$dir/slurm.conf" <<EOF
# A one-node cluster for sunglint's tests (scripts/slurm-local.sh), on this host only.
ClusterName=sunglint-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$d_port
SlurmUser=$user
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
ReturnToService=2
MaxArraySize=1001
InactiveLimit=0
KillWait=2
MinJobAge=300
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$mem State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
  export SLURM_CONF=$dir/slurm.conf
  if ! slurmctld -c -f "$SLURM_CONF" || ! slurmd -f "$SLURM_CONF" -N "$host"; then
    cat "$dir"/*.log >&2 2>/dev/null || true
    stop "$dir" >/dev/null 2>&1
    die "the daemons did not start"
  fi
  # Up when the node is idle (at most 20 s).
  for n in $(seq 200); do
    if sinfo -h -o "%T" 2>/dev/null | grep -qx idle; then
      echo "slurm-local: cluster up in $dir (node $host, $cpus CPUs, partition local)" >&2
      echo "export SLURM_CONF=$SLURM_CONF"
      return 0
    fi
    sleep 0.1
  done
  cat "$dir"/*.log >&2 2>/dev/null || true
  stop "$dir" >/dev/null 2>&1
  die "the node did not become idle"
}

case ${1:-} in
  start) start ;;
  stop) stop "${2:-}" ;;
  status) status "${2:-}" ;;
  *) echo "usage: $0 start|stop [DIR]|status [DIR]" >&2; exit 2 ;;
esac
