# A one-node Slurm cluster from Debian's packages (slurmctld, slurmd, slurm-client, munge) for
# tests, sourced by bash: config, key, state, spool and logs in one folder, daemons on 127.0.0.1
# only. cluster_start FOLDER starts munged, slurmctld and slurmd and waits for the node to be
# idle; cluster_stop stops them by their PIDs (scontrol shutdown, then munged by its pid file)
# and fails if one is still running. Exports SLURM_CONF for the client commands.

cluster_pids=()
cluster_dir=""

# True while process $1 runs (a zombie, exited but not yet reaped, does not).
cluster_alive() {
  local state
  state=$(sed 's/.*) //' "/proc/$1/stat" 2> /dev/null | cut -d' ' -f1) || return 1
  [ -n "$state" ] && [ "$state" != Z ]
}

# Stops process $1 with signal $2 (if given) and waits up to 10 s; false if it still runs.
cluster_end() {
  [ -n "$1" ] || return 0
  [ -z "${2:-}" ] || kill "-$2" "$1" 2> /dev/null || true
  for _ in $(seq 100); do
    cluster_alive "$1" || break
    sleep 0.1
  done
  if cluster_alive "$1"; then
    kill -9 "$1" 2> /dev/null || true
    echo "cluster: process $1 still ran 10 s after it was told to stop: killed" >&2
    return 1
  fi
  wait "$1" 2> /dev/null || true
}

# A TCP port on 127.0.0.1 that nothing listens on.
cluster_free_port() {
  local port
  while true; do
    port=$((20000 + RANDOM % 30000))
    if ! (exec 3<> "/dev/tcp/127.0.0.1/$port") 2> /dev/null; then
      echo "$port"
      return
    fi
  done
}

cluster_write_conf() {
  local dir=$1 node=$2 ctld_port=$3 slurmd_port=$4
  cat > "$dir/slurm.conf" << CONF
ClusterName=gfieldtest
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
AuthInfo=socket=$dir/munge.socket
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
# Without CR_Core each task reserves the node's whole memory and tasks run one at a time.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
KillWait=5
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$(($(awk '/MemTotal/ {print $2}' /proc/meminfo) / 2048)) State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
}

cluster_start() {
  cluster_dir=$1
  local node
  node=$(hostname -s)
  mkdir -p "$cluster_dir"/{state,spool,log}
  mungekey -c -k "$cluster_dir/munge.key"
  munged -F -f -S "$cluster_dir/munge.socket" --key-file "$cluster_dir/munge.key" \
    --pid-file "$cluster_dir/munged.pid" --log-file "$cluster_dir/log/munged.log" \
    --seed-file "$cluster_dir/munged.seed" > "$cluster_dir/log/munged.out" 2>&1 &
  cluster_pids+=($!)
  until [ -S "$cluster_dir/munge.socket" ]; do
    sleep 0.05
  done
  cluster_write_conf "$cluster_dir" "$node" "$(cluster_free_port)" "$(cluster_free_port)"
  export SLURM_CONF=$cluster_dir/slurm.conf
  slurmctld -D -f "$SLURM_CONF" > "$cluster_dir/log/slurmctld.out" 2>&1 &
  cluster_pids+=($!)
  slurmd -D -N "$node" -f "$SLURM_CONF" > "$cluster_dir/log/slurmd.out" 2>&1 &
  cluster_pids+=($!)
  local start=$SECONDS
  until [ "$(sinfo -h -o %t 2> /dev/null)" = idle ]; do
    if [ $((SECONDS - start)) -gt 60 ]; then
      echo "cluster: the node is not idle after 60 s" >&2
      tail -n 20 "$cluster_dir"/log/*.log >&2
      return 1
    fi
    sleep 0.1
  done
  echo "cluster: node $node idle after $((SECONDS - start)) s (munged, slurmctld, slurmd:" \
    "${cluster_pids[*]})"
}

# Waits until job $1 has left the queue (sbatch --wait polls at 2, 10 and 42 s).
cluster_wait_job() {
  while [ -n "$(squeue -h -j "$1" 2> /dev/null)" ]; do
    sleep 0.2
  done
}

cluster_stop() {
  [ -n "$cluster_dir" ] || return 0
  local status=0
  scontrol shutdown > /dev/null 2>&1 || true
  cluster_end "${cluster_pids[2]:-}" || status=1  # slurmd
  cluster_end "${cluster_pids[1]:-}" || status=1  # slurmctld
  cluster_end "${cluster_pids[0]:-}" TERM || status=1  # munged
  cluster_pids=()
  cluster_dir=""
  return $status
}
