#!/usr/bin/env bash
# A one-node Slurm cluster on this machine, for bench/slurm/campaign.sh (bench/README.md,
# "Campaigns across machines"): munged, slurmctld and slurmd, all three as root, with their key,
# configuration, state, sockets, pid files and logs in one folder of their own (nothing under
# /etc/slurm or /etc/munge is read or changed).
#
#   bench/slurm/cluster.sh start    installs slurm-wlm and munge with apt-get when missing, writes
#                                   DIR/slurm.conf (localhost, this machine's CPUs and memory from
#                                   `slurmd -C`), starts the three daemons, waits for the node to
#                                   be idle
#   bench/slurm/cluster.sh stop     stops them (slurmd, slurmctld, munged), each by its pid file
#   bench/slurm/cluster.sh status   the daemons' pids and `sinfo`
#   bench/slurm/cluster.sh env      the line to source for the clients: export SLURM_CONF=...
#
# DIR is $RAPID_SLURM_DIR, by default /var/tmp/rapid-sem-slurm. The ports are 6817 (slurmctld)
# and 6818 (slurmd), Slurm's own. Clients (sbatch, squeue, sinfo) need SLURM_CONF=DIR/slurm.conf;
# campaign.sh sets it when DIR/slurm.conf exists and SLURM_CONF is unset.
set -euo pipefail
dir=${RAPID_SLURM_DIR:-/var/tmp/rapid-sem-slurm}
conf=$dir/slurm.conf

install_missing() {
  local missing=()
  command -v slurmctld >/dev/null || missing+=(slurm-wlm)
  command -v munged >/dev/null || missing+=(munge)
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "cluster: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >/dev/null
  apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null
}

# pid of a daemon from its pid file, when it is alive
alive() {
  local f=$dir/$1.pid
  [ -s "$f" ] && kill -0 "$(cat "$f")" 2>/dev/null && cat "$f"
}

write_conf() {
  # slurmd -C: the node line Slurm itself measures (CPUs, sockets, cores, threads, RealMemory)
  local node
  node=$(slurmd -C | head -n 1 | sed -E 's/^NodeName=[^ ]+ //')
  cat >"$conf" <<EOF
# written by bench/slurm/cluster.sh: a one-node cluster on localhost
ClusterName=rapidsem
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
# no cgroups in a container: processes tracked by their parent, no task confinement
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
# one CPU a task: the array's tasks share the node
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
DefMemPerCPU=1024
MaxArraySize=100001
NodeName=localhost NodeAddr=127.0.0.1 $node State=UNKNOWN
PartitionName=main Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
}

start() {
  install_missing
  mkdir -p "$dir/state" "$dir/spool"
  chmod 700 "$dir"
  if [ -z "$(alive munged)" ]; then
    [ -s "$dir/munge.key" ] || { dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
                                 chmod 400 "$dir/munge.key"; }
    # --force: munged refuses to run as root, and a key outside /etc/munge, without it
    munged --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" \
      --pid-file="$dir/munged.pid" --log-file="$dir/munged.log" --seed-file="$dir/munged.seed"
  fi
  write_conf
  export SLURM_CONF=$conf
  [ -n "$(alive slurmctld)" ] || slurmctld -f "$conf"
  [ -n "$(alive slurmd)" ] || slurmd -f "$conf" -N localhost
  # the node registers within seconds; one left down from an earlier run is resumed
  for _ in $(seq 1 60); do
    state=$(sinfo -h -N -n localhost -o '%t' 2>/dev/null || true)
    case $state in
      idle*|mix*|alloc*) echo "cluster: up ($dir): $(sinfo -h -N -o '%N %c CPUs %m MB %t')"
                         echo "export SLURM_CONF=$conf"; return 0 ;;
      down*|drain*) scontrol update nodename=localhost state=resume 2>/dev/null || true ;;
    esac
    sleep 1
  done
  echo "cluster: the node did not come up; see $dir/slurmctld.log and $dir/slurmd.log" >&2
  sinfo -N -l >&2 || true
  exit 1
}

stop_one() {
  local pid
  pid=$(alive "$1") || { rm -f "$dir/$1.pid"; return 0; }
  kill "$pid"
  for _ in $(seq 1 30); do kill -0 "$pid" 2>/dev/null || { echo "cluster: $1 ($pid) stopped"; return 0; }
                           sleep 0.5; done
  echo "cluster: $1 ($pid) still running after 15 s" >&2
  return 1
}

stop() {
  local status=0
  # the jobs of the node first (a running array task would keep slurmd's children)
  if [ -n "$(alive slurmctld)" ] && [ -f "$conf" ]; then
    SLURM_CONF=$conf scancel --user=root 2>/dev/null || true
  fi
  stop_one slurmd || status=1
  stop_one slurmctld || status=1
  stop_one munged || status=1
  return $status
}

status() {
  for d in munged slurmctld slurmd; do
    printf '%-10s %s\n' "$d" "$(alive "$d" || echo 'not running')"
  done
  [ -n "$(alive slurmctld)" ] && SLURM_CONF=$conf sinfo -h -N -o 'node %N: %c CPUs, %m MB, %t' || true
}

case ${1:-} in
  start) start ;;
  stop) stop ;;
  status) status ;;
  env) echo "export SLURM_CONF=$conf" ;;
  *) sed -n '2,18p' "$0"; exit 2 ;;
esac
