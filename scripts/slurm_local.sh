#!/usr/bin/env bash
# A real, single-node Slurm on this host, FOR TESTS ONLY (tests/python/test_slurm_sweep.py,
# trying `mrsim sweep --emit slurm` by hand). See docs/slurm.md.
#
#   scripts/slurm_local.sh start    install if missing, configure, start munged + slurmctld +
#                                   slurmd, wait until the node is idle (idempotent)
#   scripts/slurm_local.sh stop     cancel all jobs, stop the three daemons (idempotent)
#   scripts/slurm_local.sh status   exit 0 when all three run and the node answers
#   scripts/slurm_local.sh env      print `export SLURM_CONF=...` for the clients:
#                                   eval "$(scripts/slurm_local.sh env)"; sbatch ...
#
# Everything lives in one private folder, $MRSIM_SLURM_DIR (default /tmp/mrsim-slurm):
# slurm.conf, munge.key, the munge socket, state, spool, logs and pid files. Nothing is written
# under /etc (the Debian packages' own /etc/munge/munge.key and systemd units are left unused),
# so the clients (sbatch, squeue, scontrol, sinfo) need SLURM_CONF=$MRSIM_SLURM_DIR/slurm.conf;
# jobs inherit it (sbatch exports the environment by default).
#
# What is needed and what breaks in a container (found on Debian 12 under gVisor, no systemd):
#  - Packages: slurmctld slurmd slurm-client munge (slurm-wlm is only a meta package pulling in
#    the same plus recommends). Their postinst tries to start the services: in a container
#    without systemd/runlevel, invoke-rc.d is denied and nothing starts; that is fine, we start
#    the daemons ourselves.
#  - No systemd: daemons are started directly (they daemonize themselves, pid files here).
#  - munged: run as root with a private key/socket/pid/log/seed. munged refuses a key file or
#    folders writable by others; the folder is 0755 (its parent /tmp is sticky, which munged
#    accepts). Slurm finds the private socket through AuthInfo=socket=... (auth/munge for the
#    daemons and clients, cred/munge for job credentials).
#  - cgroups: not used at all (ProctrackType=proctrack/linuxproc, TaskPlugin=task/none,
#    JobAcctGatherType=jobacct_gather/none, no cgroup.conf). In gVisor /sys/fs/cgroup is a
#    sandboxed v1 emulation; proctrack/cgroup and task/cgroup are not worth the risk for tests.
#  - No accounting (no slurmdbd, no sacct): AccountingStorageType=accounting_storage/none.
#  - Memory is not a consumable resource (SelectTypeParameters=CR_Core): jobs that ask for no
#    memory never wait on it. CPUs and RealMemory come from `slurmd -C`, so the node never
#    drains for "Low RealMemory/CPUs".
#  - The node address is 127.0.0.1: nothing listens beyond loopback. Ports 6817/6818 by
#    default; MRSIM_SLURM_CTLD_PORT / MRSIM_SLURM_D_PORT change them.
#  - slurmctld starts with -c (clear saved state): jobs of an earlier, interrupted test never
#    come back. `start` when everything already runs does not restart anything.
#  - A slurmd restarted while slurmctld runs may leave the node DOWN ("unexpectedly
#    rebooted"): ReturnToService=2 plus an explicit `scontrol update state=resume` while waiting.
set -euo pipefail

DIR=${MRSIM_SLURM_DIR:-/tmp/mrsim-slurm}
CONF=$DIR/slurm.conf
SOCK=$DIR/munge/munge.socket
CTLD_PORT=${MRSIM_SLURM_CTLD_PORT:-6817}
D_PORT=${MRSIM_SLURM_D_PORT:-6818}
TIMEOUT=${MRSIM_SLURM_TIMEOUT:-30}
export SLURM_CONF=$CONF

say() { echo "slurm_local: $*"; }
die() { echo "slurm_local: ERROR: $*" >&2; exit 1; }

# pid of a daemon from its pid file when that process is alive, else nothing
alive_pid() {
  local f=$1 pid
  [ -s "$f" ] || return 1
  pid=$(cat "$f" 2>/dev/null) || return 1
  [[ $pid =~ ^[0-9]+$ ]] && kill -0 "$pid" 2>/dev/null || return 1
  echo "$pid"
}

install_packages() {
  local need=() p
  for p in slurmctld slurmd slurm-client munge; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || need+=("$p")
  done
  [ ${#need[@]} -eq 0 ] && return 0
  command -v apt-get >/dev/null || die "packages missing (${need[*]}) and no apt-get"
  [ "$(id -u)" -eq 0 ] || die "packages missing (${need[*]}); run as root to install them"
  say "installing ${need[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq --no-install-recommends "${need[@]}" >"$DIR/apt.log" 2>&1 || {
    apt-get update -qq >>"$DIR/apt.log" 2>&1 &&
      apt-get install -y -qq --no-install-recommends "${need[@]}" >>"$DIR/apt.log" 2>&1
  } || { tail -20 "$DIR/apt.log" >&2; die "apt-get install ${need[*]} failed"; }
}

write_conf() {
  local host node cpus line
  host=$(hostname -s)
  # `slurmd -C` prints e.g. "NodeName=vm CPUs=2 Boards=1 SocketsPerBoard=1 CoresPerSocket=2
  # ThreadsPerCore=1 RealMemory=24105"; keep its topology and memory as they are.
  line=$(slurmd -C 2>/dev/null | head -1)
  [[ $line == NodeName=* ]] || die "slurmd -C printed nothing usable: $line"
  node=${line#NodeName=* }
  cpus=$(sed -n 's/.*CPUs=\([0-9]*\).*/\1/p' <<<"$line")
  cat >"$CONF.new" <<EOF
# Written by scripts/slurm_local.sh: a single-node Slurm for tests only. Do not edit.
ClusterName=mrsim-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$D_PORT
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$SOCK
StateSaveLocation=$DIR/state
SlurmdSpoolDir=$DIR/spool
SlurmctldPidFile=$DIR/slurmctld.pid
SlurmdPidFile=$DIR/slurmd.pid
SlurmctldLogFile=$DIR/log/slurmctld.log
SlurmdLogFile=$DIR/log/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MailProg=/bin/true
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
# short intervals: a test waits on them
SchedulerParameters=sched_interval=2
MessageTimeout=10
SlurmdTimeout=60
InactiveLimit=0
MinJobAge=300
KillWait=5
NodeName=$host $node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=debug Nodes=$host Default=YES MaxTime=INFINITE State=UP OverSubscribe=NO
EOF
  # cpus is only checked (a machine with no CPU line would be odd)
  [ -n "$cpus" ] || die "no CPUs in: $line"
  if cmp -s "$CONF.new" "$CONF"; then rm -f "$CONF.new"; return 0; fi
  # a changed configuration (other host name, CPUs, ports): running daemons restart with it
  if [ -f "$CONF" ]; then
    say "slurm.conf changed"
    stop_one slurmd
    stop_one slurmctld
  fi
  mv "$CONF.new" "$CONF"
}

tails() {
  local f
  for f in "$DIR"/log/munged.log "$DIR"/log/slurmctld.log "$DIR"/log/slurmd.log; do
    [ -f "$f" ] || continue
    echo "----- tail $f" >&2
    tail -15 "$f" >&2
  done
}

node_state() { sinfo -h -N -o '%T' 2>/dev/null | head -1; }

start() {
  mkdir -p "$DIR"
  # 0755: munged wants every folder above its socket searchable by all (else it warns
  # "Socket is inaccessible", and jobs of other users could not authenticate)
  chmod 0755 "$DIR"
  install_packages
  mkdir -p "$DIR/munge" "$DIR/state" "$DIR/spool" "$DIR/log"
  chmod 0755 "$DIR/munge"

  # munge key: created once, kept (so running jobs' credentials stay valid across restarts)
  if [ ! -s "$DIR/munge.key" ]; then
    if command -v mungekey >/dev/null; then
      mungekey --create --keyfile="$DIR/munge.key" --force
    else
      dd if=/dev/urandom of="$DIR/munge.key" bs=1 count=1024 status=none
    fi
    chmod 0400 "$DIR/munge.key"
    say "created $DIR/munge.key"
  fi

  if alive_pid "$DIR/munged.pid" >/dev/null; then
    say "munged already running (pid $(alive_pid "$DIR/munged.pid"))"
  else
    rm -f "$SOCK" "$SOCK.lock"
    # --force: root, and a socket left over by a killed munged
    munged --force --key-file="$DIR/munge.key" --socket="$SOCK" --pid-file="$DIR/munged.pid" \
      --log-file="$DIR/log/munged.log" --seed-file="$DIR/munge/munged.seed" \
      || { tails; die "munged did not start"; }
  fi
  # munge round trip through the private socket
  if ! munge -S "$SOCK" -n </dev/null | unmunge -S "$SOCK" >/dev/null 2>&1; then
    tails; die "munge/unmunge round trip through $SOCK failed"
  fi

  write_conf

  if alive_pid "$DIR/slurmctld.pid" >/dev/null; then
    say "slurmctld already running (pid $(alive_pid "$DIR/slurmctld.pid"))"
  else
    slurmctld -c -f "$CONF" >>"$DIR/log/slurmctld.out" 2>&1 ||
      { tails; die "slurmctld did not start"; }
  fi
  if alive_pid "$DIR/slurmd.pid" >/dev/null; then
    say "slurmd already running (pid $(alive_pid "$DIR/slurmd.pid"))"
  else
    slurmd -f "$CONF" >>"$DIR/log/slurmd.out" 2>&1 || { tails; die "slurmd did not start"; }
  fi

  local t0=$SECONDS st=""
  while :; do
    st=$(node_state || true)
    case "$st" in
      idle|mixed|allocated|completing) break ;;
      down*|drain*|drained*)
        scontrol update nodename="$(hostname -s)" state=resume >/dev/null 2>&1 || true ;;
    esac
    if [ $((SECONDS - t0)) -ge "$TIMEOUT" ]; then
      tails
      alive_pid "$DIR/slurmctld.pid" >/dev/null || echo "slurmctld is not running" >&2
      alive_pid "$DIR/slurmd.pid" >/dev/null || echo "slurmd is not running" >&2
      die "node not idle after ${TIMEOUT}s (sinfo state: '${st:-no answer}'); logs in $DIR/log"
    fi
    sleep 1
  done
  say "up: node $(hostname -s) $st; clients need SLURM_CONF=$CONF"
}

stop_one() {
  local name=$1 f=$DIR/$1.pid pid i
  pid=$(alive_pid "$f") || { rm -f "$f"; return 0; }
  kill "$pid" 2>/dev/null || true
  for i in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.2; done
  if kill -0 "$pid" 2>/dev/null; then kill -9 "$pid" 2>/dev/null || true; fi
  rm -f "$f"
  say "stopped $name (pid $pid)"
}

stop() {
  [ -d "$DIR" ] || { say "not running"; return 0; }
  if alive_pid "$DIR/slurmctld.pid" >/dev/null && [ -f "$CONF" ]; then
    # no job step survives us (slurmstepd processes are not ours to hunt by name)
    if [ -n "$(squeue -h -o %i 2>/dev/null)" ]; then
      scancel --full $(squeue -h -o %i) 2>/dev/null || true
      for _ in $(seq 20); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.5; done
    fi
  fi
  stop_one slurmd
  stop_one slurmctld
  stop_one munged
  rm -f "$SOCK" "$SOCK.lock"
}

status() {
  local ok=0 n
  for n in munged slurmctld slurmd; do
    if alive_pid "$DIR/$n.pid" >/dev/null; then
      say "$n running (pid $(alive_pid "$DIR/$n.pid"))"
    else
      say "$n not running"; ok=1
    fi
  done
  if [ $ok -eq 0 ]; then
    local st; st=$(node_state || true)
    say "node $(hostname -s): ${st:-no answer}"
    [ -n "$st" ] || ok=1
  fi
  return $ok
}

case "${1:-}" in
  start) start ;;
  stop) stop ;;
  status) status ;;
  env) echo "export SLURM_CONF=$CONF" ;;
  *) echo "usage: $0 start|stop|status|env" >&2; exit 2 ;;
esac
