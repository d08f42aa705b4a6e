# shellcheck shell=bash
# A private single-node Slurm cluster for tests (docs/scale-out.md, "Testing against a real Slurm"):
# Debian's slurm-wlm and munge, one node with 2 CPUs, MpiDefault=none as Slurm ships it, and two
# partitions: "low" (the default) and "high", whose jobs preempt low's by requeueing them
# (PreemptType=preempt/partition_prio, PreemptMode=REQUEUE). Its own munge key and socket, its own
# ports, and every file (configuration, state, spool, logs, PID files) under one folder. Source
# this file, then:
#   cluster_start DIR   start munged, slurmctld and slurmd (run as root); exports SLURM_CONF
#   cluster_stop        cancel every job, wait for them to end, stop the daemons by their PIDs
# The daemons are started in the background here (-D / -F: they do not fork, so $! is their PID)
# and stopped by those PIDs, never by name. Status 77 from cluster_start: cannot be started here
# (not root, no slurm-wlm and no way to install it, or slurmctld/slurmd did not come up).

cluster_dir=
cluster_pids=()

cluster_log() { echo "cluster: $*" >&2; }

# 77 (skip) unless Debian's slurm-wlm and munge are installed (scripts/install-deps.sh --mpi,
# the README's test command, installs them).
cluster_install() {
    local program
    for program in slurmctld slurmd slurmstepd munged sbatch; do
        command -v "$program" > /dev/null || PATH=$PATH:/usr/sbin command -v "$program" \
            > /dev/null || {
            cluster_log "$program is missing (scripts/install-deps.sh --mpi installs slurm-wlm and munge)"
            return 77
        }
    done
}

cluster_free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# cluster_start DIR [CPUS]
cluster_start() {
    cluster_dir=$1
    local cpus=${2:-2} host ctld_port slurmd_port i
    if (( EUID != 0 )); then
        cluster_log "not root: a private slurmctld/slurmd needs root here"
        return 77
    fi
    cluster_install || return $?
    PATH=$PATH:/usr/sbin
    host=$(hostname -s)
    rm -rf "$cluster_dir"
    mkdir -p "$cluster_dir"/{state,spool,munge}
    chmod 700 "$cluster_dir/munge"
    dd if=/dev/urandom of="$cluster_dir/munge/munge.key" bs=1024 count=1 status=none
    chmod 400 "$cluster_dir/munge/munge.key"
    munged -F --force --socket="$cluster_dir/munge/socket" --key-file="$cluster_dir/munge/munge.key" \
        --pid-file="$cluster_dir/munge/munged.pid" --log-file="$cluster_dir/munge/munged.log" \
        --seed-file="$cluster_dir/munge/seed" > /dev/null 2>&1 &
    cluster_pids+=($!)
    for ((i = 0; i < 50; ++i)); do
        [[ -S $cluster_dir/munge/socket ]] && break
        sleep 0.1
    done
    if [[ ! -S $cluster_dir/munge/socket ]]; then
        cluster_log "munged did not start: $(tail -3 "$cluster_dir/munge/munged.log" 2>/dev/null)"
        return 77
    fi
    ctld_port=$(cluster_free_port)
    slurmd_port=$(cluster_free_port)
    # cred_expire: a requeued job waits this long before it may start again (Slurm's default 120 s).
    # sched_interval, bf_interval: the scheduler looks at pending jobs every second or two.
    cat > "$cluster_dir/slurm.conf" <<EOF
ClusterName=sbpacktest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$cluster_dir/munge/socket,cred_expire=${SBPACK_SLURM_CRED_EXPIRE:-10}
StateSaveLocation=$cluster_dir/state
SlurmdSpoolDir=$cluster_dir/spool
SlurmctldPidFile=$cluster_dir/slurmctld.pid
SlurmdPidFile=$cluster_dir/slurmd.pid
SlurmctldLogFile=$cluster_dir/slurmctld.log
SlurmdLogFile=$cluster_dir/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=2,bf_interval=1
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
PreemptType=preempt/partition_prio
PreemptMode=REQUEUE
KillWait=30
MinJobAge=3600
ReturnToService=2
MailProg=/bin/true
SlurmdParameters=config_overrides
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=${SBPACK_SLURM_MEMORY_MB:-6000} State=UNKNOWN
PartitionName=low Nodes=$host Default=YES PriorityTier=1 MaxTime=INFINITE State=UP
PartitionName=high Nodes=$host PriorityTier=10 MaxTime=INFINITE State=UP
EOF
    export SLURM_CONF=$cluster_dir/slurm.conf
    # Niced: the jobs (slurmd's children) share the machine politely.
    nice -n 10 slurmctld -D -i > "$cluster_dir/slurmctld.out" 2>&1 &
    cluster_pids+=($!)
    nice -n 10 slurmd -D > "$cluster_dir/slurmd.out" 2>&1 &
    cluster_pids+=($!)
    for ((i = 0; i < 60; ++i)); do
        if [[ $(sinfo -h -n "$host" -o %t 2>/dev/null | head -1) == idle ]]; then
            cluster_log "slurmctld and slurmd up ($SLURM_CONF): $(sinfo -h -o '%P %t %c CPUs' | tr '\n' ' ')"
            return 0
        fi
        sleep 0.5
    done
    cluster_log "the node did not come up:"
    tail -5 "$cluster_dir"/slurmctld.log "$cluster_dir"/slurmd.log "$cluster_dir"/*.out >&2 || true
    return 77
}

cluster_stop() {
    local pid i
    if [[ -n ${SLURM_CONF:-} && -e ${SLURM_CONF:-} ]] && (( ${#cluster_pids[@]} > 1 )); then
        scancel --full --quiet --user="$(id -un)" 2>/dev/null || true
        for ((i = 0; i < 40; ++i)); do
            [[ -z $(squeue -h -t running,completing,configuring 2>/dev/null) ]] && break
            sleep 0.5
        done
    fi
    # slurmd, then slurmctld, then munged: the reverse of their start.
    for ((i = ${#cluster_pids[@]} - 1; i >= 0; --i)); do
        pid=${cluster_pids[i]}
        kill -TERM "$pid" 2>/dev/null || continue
        for _ in $(seq 40); do
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.25
        done
        kill -KILL "$pid" 2>/dev/null || true
        wait "$pid" 2>/dev/null || true
    done
    cluster_pids=()
}
