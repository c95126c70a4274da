# shellcheck shell=bash
# A private single-node Slurm cluster on this machine, for the Slurm test tier
# (tests/slurm/slurm-array-render-test) and benchmarks/slurm-makespan. Sourced, not run.
#
#   slurm_cluster_start DIR   starts munged (with a fresh key), slurmctld and slurmd, each with its
#                             configuration, state, sockets, pid and log files under DIR (which must
#                             exist and be empty), and exports SLURM_CONF, so that every Slurm command
#                             of the caller (sbatch, squeue, scontrol, ...) talks to this cluster only
#   slurm_cluster_stop        cancels the cluster's jobs, stops the daemons this shell started
#                             (scontrol shutdown, then their PIDs) and leaves DIR to the caller;
#                             safe to call more than once, and after a start that failed half-way
#   slurm_cluster_logs        prints the tails of the daemons' logs (to stderr), for a failure
#
# What it never does: touch /etc/slurm, /etc/munge or a system service, or listen anywhere but on the
# loopback. It needs root: slurmd starts job steps as the submitting user, and munged, slurmctld and
# slurmd run as the caller here, so only root can run all three. The node is this machine, named
# "localhost" in the cluster, with its real CPU layout (from `slurmd -C`) and one partition, "test".
# Plugins are the ones that need nothing from the kernel beyond /proc (proctrack/linuxproc, task/none,
# no cgroup.conf, no accounting), since containers rarely give a writable cgroup tree.
#
# Functions print one line per step to stderr, prefixed with "slurm-cluster:".

slurm_cluster_dir=""
slurm_cluster_pids=()  # the daemons this shell started, in order: munged, slurmctld, slurmd
slurm_cluster_names=() # and their names

slurm_cluster_say() {
    echo "slurm-cluster: $*" >&2
}

# A TCP port nothing on this machine listens on, from a random start in 20000..59999. Two clusters
# started side by side may still pick the same port between the check and the bind; the daemon's log
# then says so and the start fails rather than sharing a port.
slurm_cluster_free_port() {
    local port tries
    for ((tries = 0; tries < 200; tries++)); do
        port=$((20000 + RANDOM % 40000))
        if [[ -z $(ss -Htan "sport = :$port" 2>/dev/null) ]]; then
            echo "$port"
            return 0
        fi
    done
    slurm_cluster_say "no free TCP port found"
    return 1
}

# Waits until COMMAND succeeds, trying every half second for at most SECONDS.
slurm_cluster_wait_for() {
    local seconds=$1
    shift
    local deadline=$((SECONDS + seconds))
    until "$@" >/dev/null 2>&1; do
        ((SECONDS < deadline)) || return 1
        sleep 0.5
    done
}

# The node's hardware as slurmd sees it ("CPUs=2 Boards=1 SocketsPerBoard=1 CoresPerSocket=2
# ThreadsPerCore=1"), so that slurmctld finds the node as configured and does not drain it for having
# fewer sockets or cores than slurm.conf claims. Memory is left out: the node claims a small RealMemory,
# and jobs here do not ask for memory.
slurm_cluster_node_layout() {
    local layout
    layout=$(slurmd -C 2>/dev/null | head -n 1 | tr ' ' '\n' |
        grep -E '^(CPUs|Boards|SocketsPerBoard|CoresPerSocket|ThreadsPerCore)=' | paste -sd ' ') || true
    if [[ $layout == *CPUs=* ]]; then
        echo "$layout"
    else
        echo "CPUs=$(nproc)"
    fi
}

slurm_cluster_start() {
    local dir=$1
    if [[ $(id -u) -ne 0 ]]; then
        slurm_cluster_say "needs root (slurmd starts jobs as their user, munged and slurmd run as the caller)"
        return 1
    fi
    dir=$(realpath "$dir")
    slurm_cluster_dir=$dir
    # munged refuses a socket, key or log in a folder others may write to: one of its own, that others
    # may enter (to reach the socket) but not write to.
    # (Called in a condition, as `slurm_cluster_start DIR || ...`, this function runs without set -e:
    # each step that can fail says so itself.)
    mkdir -m 0755 "$dir/munge" && mkdir -m 0700 "$dir/state" "$dir/spool" || return 1

    # The controller and the node are both named "localhost": with CommunicationParameters'
    # NoCtldInAddrAny and NoInAddrAny, each daemon listens only on the address its name resolves to
    # (rather than on every interface), and localhost resolves to the loopback whatever this machine's
    # own name resolves to. slurmctld accepts "localhost" as its own name, and slurmd is told its name.
    local node=localhost ctld_port slurmd_port
    ctld_port=$(slurm_cluster_free_port) || return 1
    slurmd_port=$(slurm_cluster_free_port) || return 1
    while [[ $slurmd_port == "$ctld_port" ]]; do slurmd_port=$(slurm_cluster_free_port) || return 1; done

    # A fresh key: this cluster's credentials are valid nowhere else, and the machine's own key (if any)
    # stays unread. munged wants it owned by its user and readable by nobody else.
    dd if=/dev/urandom of="$dir/munge/munge.key" bs=1024 count=1 status=none &&
        chmod 0400 "$dir/munge/munge.key" || return 1
    local socket=$dir/munge/munge.socket
    slurm_cluster_say "starting munged (socket $socket)"
    # --force: munged refuses to run as root without it. -F keeps it in the foreground, so that the PID
    # this shell holds is the daemon's own.
    munged -F --force --socket="$socket" --key-file="$dir/munge/munge.key" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
        --seed-file="$dir/munge/munged.seed" >"$dir/munge/munged.out" 2>&1 &
    slurm_cluster_pids+=($!) slurm_cluster_names+=(munged)
    if ! slurm_cluster_wait_for 20 test -S "$socket"; then
        slurm_cluster_say "munged did not create its socket in 20 s"
        return 1
    fi

    export SLURM_CONF=$dir/slurm.conf
    # Plugin stack: an empty one of our own, not the machine's /etc/slurm/plugstack.conf.
    : >"$dir/plugstack.conf" || return 1
    cat >"$SLURM_CONF" <<EOF || return 1
# A single-node cluster on the loopback, written by tests/slurm/slurm-cluster.sh.
ClusterName=speculum-test
SlurmctldHost=$node(127.0.0.1)
CommunicationParameters=NoCtldInAddrAny,NoInAddrAny
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmctldDebug=info
SlurmdDebug=info
PlugStackConfig=$dir/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MailProg=/bin/true
InactiveLimit=0
KillWait=5
NodeName=$node NodeAddr=127.0.0.1 NodeHostname=$node $(slurm_cluster_node_layout) RealMemory=256 State=UNKNOWN
PartitionName=test Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF

    slurm_cluster_say "starting slurmctld (port $ctld_port) and slurmd (node $node, port $slurmd_port)"
    # -D: in the foreground (this shell holds their PIDs); output to files, never to the caller's
    # stdout, which a test runner reads until every process holding it has exited.
    slurmctld -D -f "$SLURM_CONF" >"$dir/slurmctld.out" 2>&1 &
    slurm_cluster_pids+=($!) slurm_cluster_names+=(slurmctld)
    slurmd -D -f "$SLURM_CONF" -N "$node" >"$dir/slurmd.out" 2>&1 &
    slurm_cluster_pids+=($!) slurm_cluster_names+=(slurmd)

    # The node registers, then turns idle: only then does a submitted job start right away.
    local state=""
    local deadline=$((SECONDS + 60))
    local i
    while ((SECONDS < deadline)); do
        state=$(sinfo -h -n "$node" -o %t 2>/dev/null || true)
        [[ $state == idle ]] && break
        # A daemon that exited (a port taken, a configuration it refuses) will not come back.
        for i in "${!slurm_cluster_pids[@]}"; do
            if ! kill -0 "${slurm_cluster_pids[i]}" 2>/dev/null; then
                slurm_cluster_say "${slurm_cluster_names[i]} exited during the start (its log says why)"
                return 1
            fi
        done
        sleep 0.5
    done
    if [[ $state != idle ]]; then
        slurm_cluster_say "the node is not idle after 60 s (state: '${state:-no answer}')"
        return 1
    fi
    slurm_cluster_say "node $node is idle ($(sinfo -h -n "$node" -o '%c CPUs'))"
}

# True when the cluster has no job pending, running or completing (squeue's default states).
slurm_cluster_no_jobs() {
    local jobs
    jobs=$(squeue -h -o %A 2>/dev/null) && [[ -z $jobs ]]
}

slurm_cluster_stop() {
    [[ -n $slurm_cluster_dir ]] || return 0
    # The daemons' PIDs, last started first: slurmd, slurmctld, then munged, which both need to the end.
    local pids=() i
    for ((i = ${#slurm_cluster_pids[@]} - 1; i >= 0; i--)); do
        pids+=("${slurm_cluster_pids[i]}")
    done
    if [[ -n ${SLURM_CONF:-} && -f $SLURM_CONF ]]; then
        # Jobs first: a job step (slurmstepd) outlives slurmd, so one left running would outlive the test.
        local jobs
        jobs=$(squeue -h -o %A 2>/dev/null | tr '\n' ' ' || true)
        if [[ -n ${jobs// /} ]]; then
            slurm_cluster_say "cancelling jobs $jobs"
            # shellcheck disable=SC2086 # one word per job id
            scancel $jobs 2>/dev/null || true
            # Until none is pending, running or completing: a job step reports its end to slurmctld,
            # and one that cannot (slurmctld already gone) stays behind retrying.
            slurm_cluster_wait_for 30 slurm_cluster_no_jobs ||
                slurm_cluster_say "jobs still completing after 30 s: $(squeue -h -o '%A %T' | paste -sd ' ')"
        fi
        timeout 10 scontrol shutdown >/dev/null 2>&1 || true
    fi
    local pid deadline
    for pid in "${pids[@]}"; do
        # Each daemon in turn: scontrol shutdown has asked slurmctld and slurmd to go, and what is
        # still there after 10 s gets SIGTERM, then SIGKILL. munged, started first, is asked last.
        if [[ $pid != "${slurm_cluster_pids[0]}" ]]; then
            deadline=$((SECONDS + 10))
            while kill -0 "$pid" 2>/dev/null && ((SECONDS < deadline)); do sleep 0.2; done
        fi
        kill -TERM "$pid" 2>/dev/null || true
        deadline=$((SECONDS + 5))
        while kill -0 "$pid" 2>/dev/null && ((SECONDS < deadline)); do sleep 0.2; done
        kill -KILL "$pid" 2>/dev/null || true
        wait "$pid" 2>/dev/null || true
    done
    # A job step that did not end with its job (slurmstepd, started by our slurmd, so with our SLURM_CONF
    # in its environment) goes now, by its process id.
    local proc comm
    [[ -n ${SLURM_CONF:-} ]] && for proc in /proc/[0-9]*; do
        comm=""
        read -r comm 2>/dev/null <"$proc/comm" || true
        [[ $comm == slurmstepd ]] || continue
        if tr '\0' '\n' 2>/dev/null <"$proc/environ" | grep -qxF "SLURM_CONF=$SLURM_CONF"; then
            slurm_cluster_say "stopping a job step left behind (pid ${proc#/proc/})"
            kill -KILL "${proc#/proc/}" 2>/dev/null || true
        fi
    done
    slurm_cluster_pids=() slurm_cluster_names=()
    slurm_cluster_say "stopped"
    slurm_cluster_dir=""
}

slurm_cluster_logs() {
    local dir=${1:-$slurm_cluster_dir} f
    [[ -n $dir ]] || return 0
    # Each daemon's log file, or what it printed when it stopped before opening one.
    for f in slurmctld slurmd munge/munged; do
        if [[ -s $dir/$f.log ]]; then
            f=$f.log
        elif [[ -s $dir/$f.out ]]; then
            f=$f.out
        else
            continue
        fi
        echo "---- $f (last 30 lines)" >&2
        tail -n 30 "$dir/$f" >&2
    done
}
