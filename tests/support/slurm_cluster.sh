# A real single-node Slurm cluster for the scale-out tests, started without systemd on loopback
# and stopped again (facts: ../shared/notes/slurm-single-node.md). Source it, then:
#   slurm_start        munged, slurmctld and slurmd with their key, socket, config, state and logs
#                      in a folder of their own under /tmp (munged wants execute permission for
#                      all on every folder of its socket's path, which a build folder inside a
#                      private one lacks, and slurm.conf cannot hold a path with spaces),
#                      removed when they stop; exports SLURM_CONF; waits until the node is idle; stops them all
#                      on the shell's exit (a trap), whatever happens. Fails, saying why, when a
#                      daemon cannot start: a test that needs the cluster never passes without it.
#   slurm_wait ID...   polls squeue until those jobs have left the queue (limit: 600 s)
#   slurm_state ID     the job's state (COMPLETED, FAILED, CANCELLED, ...)
#   slurm_stop         stops the daemons by PID (slurmd, slurmctld, munged)

slurm_fail() { echo "slurm_cluster: $*" >&2; [ -n "${SLURM_DIR:-}" ] && tail -n 20 "$SLURM_DIR"/*.log >&2; exit 1; }

slurm_start() {
  SLURM_DIR=$(mktemp -d /tmp/rugosim-slurm.XXXXXX)
  local d=$SLURM_DIR
  for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo scontrol; do
    command -v "$tool" >/dev/null || slurm_fail "$tool is not installed (cmake/install-deps.sh: slurm-wlm, munge)"
  done
  mkdir -p "$d/key" "$d/run" "$d/state" "$d/spool"
  chmod 755 "$d" "$d/run"
  chmod 700 "$d/key"
  SLURM_PIDS=()
  trap slurm_stop EXIT
  mungekey -c -k "$d/key/munge.key" >/dev/null 2>&1 || slurm_fail "mungekey could not make a key"
  local socket=$d/run/munge.socket
  munged -F --socket="$socket" --key-file="$d/key/munge.key" \
    --pid-file="$d/run/munged.pid" --log-file="$d/munged.log" --seed-file="$d/run/munge.seed" \
    >>"$d/munged.out" 2>&1 &
  SLURM_PIDS+=($!)
  for _ in $(seq 100); do [ -S "$socket" ] && break; sleep 0.1; done
  [ -S "$socket" ] || slurm_fail "munged did not start ($(tail -n 1 "$d/munged.out" 2>/dev/null))"

  # Ports of our own (the defaults, 6817 and 6818, may be in use).
  local port=$((20000 + ($$ % 20000)))
  local host
  host=$(hostname -s)
  local node
  node=$(slurmd -C | head -n 1 | sed 's/ UpTime=.*//')
  cat >"$d/slurm.conf" <<CONF
ClusterName=rugosim-test
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
ReturnToService=2
MailProg=/bin/true
SchedulerParameters=batch_sched_delay=0,kill_invalid_depend
StateSaveLocation=$d/state
SlurmdSpoolDir=$d/spool
SlurmctldPidFile=$d/run/slurmctld.pid
SlurmdPidFile=$d/run/slurmd.pid
SlurmctldLogFile=$d/slurmctld.log
SlurmdLogFile=$d/slurmd.log
$node NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$d/slurm.conf"
  slurmctld -D -i -f "$SLURM_CONF" >>"$d/slurmctld.log" 2>&1 &
  SLURM_PIDS+=($!)
  slurmd -D -f "$SLURM_CONF" >>"$d/slurmd.log" 2>&1 &
  SLURM_PIDS+=($!)
  for _ in $(seq 300); do
    [ "$(sinfo -h -N -o %T 2>/dev/null | head -n 1)" = "idle" ] && return 0
    sleep 0.1
  done
  slurm_fail "the node did not become idle within 30 s"
}

slurm_wait() {
  local ids
  ids=$(IFS=,; echo "$*")
  for _ in $(seq 6000); do
    [ -z "$(squeue -h -j "$ids" 2>/dev/null)" ] && return 0
    sleep 0.1
  done
  slurm_fail "jobs $ids still queued after 600 s"
}

slurm_state() { scontrol -o show job "$1" | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 | sort -u | tr '\n' ' ' | sed 's/ $//'; }

slurm_stop() {
  local i
  # slurmd, then slurmctld, then munged: the reverse of their start.
  for ((i = ${#SLURM_PIDS[@]} - 1; i >= 0; i--)); do
    kill "${SLURM_PIDS[i]}" 2>/dev/null || true
    wait "${SLURM_PIDS[i]}" 2>/dev/null || true
  done
  SLURM_PIDS=()
  if [ -n "${SLURM_DIR:-}" ]; then rm -rf "$SLURM_DIR"; fi
  SLURM_DIR=
}
