#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, on loopback, for as long as a
# command runs: munged, slurmctld and slurmd started here with their
# configuration, state and logs in a temporary folder, and stopped by their
# process ids when the command ends (a trap: also on failure or Ctrl-C).
#
# Usage: slurm_single_node.sh WORK_DIR COMMAND [ARGS...]
#   COMMAND runs with SLURM_CONF set, e.g.
#   slurm_single_node.sh /tmp/slurm salloc -N1 -n1 -c2 lab/odelab-report --executor srun ...
# Needs Debian's slurmctld, slurmd, slurm-client and munge (scripts/odelab.sh).
# Ports: two free ones on 127.0.0.1; the node's address is 127.0.0.1.
set -euo pipefail
# Slurm's daemons listen on every address (Slurm has no option to bind one,
# and in a network namespace with only loopback they cannot resolve a
# listening address); they are told only 127.0.0.1 and accept only messages
# signed with the fresh munge key below.
work=$1; shift
rm -rf "$work" && mkdir -p "$work"/{state,spool,munge} && chmod 700 "$work/munge"
work=$(cd "$work" && pwd)
node=$(hostname -s)
cpus=$(nproc)
say() { echo "slurm_single_node: $*" >&2; }

here=$(cd "$(dirname "$0")" && pwd)
source "$here/daemons.sh"
trap stop_daemons EXIT
trap 'exit 130' INT TERM


# munge: a fresh key, a socket of its own (not the system's /run/munge).
dd if=/dev/urandom of="$work/munge/munge.key" bs=1024 count=1 status=none
chmod 600 "$work/munge/munge.key"
munged --foreground --force --socket="$work/munge/socket" --key-file="$work/munge/munge.key" \
  --pid-file="$work/munge/munged.pid" --log-file="$work/munge/munged.log" \
  --seed-file="$work/munge/seed" >"$work/munge/stdout.log" 2>&1 &
daemon_pids+=($!)
for _ in $(seq 50); do [ -S "$work/munge/socket" ] && break; sleep 0.1; done
[ -S "$work/munge/socket" ] || { say "munged did not start: $(tail -n 3 "$work/munge/munged.log")"; exit 1; }

export SLURM_CONF=$work/slurm.conf
cat >"$SLURM_CONF" <<CONF
ClusterName=odelab
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$(free_port)
SlurmdPort=$(free_port)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$work/munge/socket
CredType=cred/munge
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
SchedulerParameters=batch_sched_delay=0
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$node Default=YES MaxTime=INFINITE State=UP
CONF

slurmctld -D -i -f "$SLURM_CONF" >"$work/slurmctld.stdout" 2>&1 &
daemon_pids+=($!)
slurmd -D -f "$SLURM_CONF" -N "$node" >"$work/slurmd.stdout" 2>&1 &
daemon_pids+=($!)
for _ in $(seq 100); do
  sinfo -h -o %t 2>/dev/null | grep -q '^idle' && break
  sleep 0.2
done
sinfo -h -o %t 2>/dev/null | grep -q '^idle' || {
  say "the node did not come up: $(tail -n 3 "$work/slurmctld.log" "$work/slurmd.log" 2>&1)"; exit 1; }
say "node $node ($cpus CPUs) up; slurmctld ${daemon_pids[1]}, slurmd ${daemon_pids[2]}, munged ${daemon_pids[0]}; SLURM_CONF=$SLURM_CONF"
status=0
"$@" || status=$?
exit $status
