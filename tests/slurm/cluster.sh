#!/usr/bin/env bash
# A one-node SLURM cluster on localhost (munged, slurmctld, slurmd), all of it under one
# directory, for the tests:
#
#   tests/slurm/cluster.sh start DIR [CPUS [MEM_MB]]   # prints SLURM_CONF=... and PATH=...
#   tests/slurm/cluster.sh stop DIR
#
# Needs root (slurmd starts every job's processes) and the Debian packages slurm-wlm
# and munge (slurmctld, slurmd, munged, mungekey, sbatch, squeue, scontrol). Client
# commands find the cluster through SLURM_CONF. start waits until the node is idle
# (about 2 s) and fails, with the daemons' log tails, if it does not get there; stop ends
# the daemons it started (by their pid files) and leaves DIR for inspection.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cmd=${1:?usage: cluster.sh start|stop DIR [CPUS [MEM_MB]]}
dir=${2:?usage: cluster.sh start|stop DIR [CPUS [MEM_MB]]}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)

stop_pidfile() {   # stop_pidfile FILE: TERM the process, then KILL it after 10 s
    local f=$1 pid
    [ -s "$f" ] || return 0
    pid=$(cat "$f")
    kill "$pid" 2>/dev/null || { rm -f "$f"; return 0; }
    for _ in $(seq 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$f"
}

free_port() {
    python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

tails() {
    for f in "$dir"/munge/munged.log "$dir"/slurmctld.log "$dir"/slurmd.log; do
        [ -f "$f" ] && { echo "--- $f"; tail -n 20 "$f"; }
    done
}

case $cmd in
start)
    cpus=${3:-2}
    mem=${4:-6000}
    for tool in munged mungekey slurmctld slurmd sbatch srun squeue sinfo scontrol scancel; do
        command -v "$tool" >/dev/null || { echo "cluster.sh: $tool not found (apt-get install slurm-wlm munge)" >&2; exit 2; }
    done
    [ "$(id -u)" = 0 ] || { echo "cluster.sh: needs root (slurmd runs the jobs)" >&2; exit 2; }
    mkdir -p "$dir/munge" "$dir/state" "$dir/spool"
    chmod 0700 "$dir/munge"
    [ -s "$dir/munge/munge.key" ] || mungekey --create --keyfile="$dir/munge/munge.key" --bits=1024
    chmod 0400 "$dir/munge/munge.key"
    munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
        --pid-file="$dir/munge/munged.pid" --log-file="$dir/munge/munged.log" \
        --seed-file="$dir/munge/munged.seed"
    host=$(hostname -s)
    sed -e "s|@DIR@|$dir|g" -e "s|@HOST@|$host|g" -e "s|@USER@|$(id -un)|g" \
        -e "s|@NODE@|jls1|g" -e "s|@CPUS@|$cpus|g" -e "s|@MEM_MB@|$mem|g" \
        -e "s|@CTLD_PORT@|$(free_port)|g" -e "s|@SLURMD_PORT@|$(free_port)|g" \
        "$here/slurm.conf.in" > "$dir/slurm.conf"
    # The slurm-jobstep executor clears every SLURM_* variable, SLURM_CONF too, before
    # it runs a job's step with srun; on a real cluster srun then reads
    # /etc/slurm/slurm.conf. This cluster keeps out of /etc (several may run on one
    # machine), so DIR/bin/srun, first on the PATH of the run, gives srun its file.
    mkdir -p "$dir/bin"
    printf '#!/bin/sh\nSLURM_CONF=${SLURM_CONF:-%s} exec %s "$@"\n' "$dir/slurm.conf" "$(command -v srun)" > "$dir/bin/srun"
    chmod 0755 "$dir/bin/srun"
    export SLURM_CONF=$dir/slurm.conf
    slurmctld -c -f "$SLURM_CONF" || { tails >&2; exit 1; }
    slurmd -N jls1 -f "$SLURM_CONF" || { tails >&2; exit 1; }
    for _ in $(seq 300); do
        state=$(sinfo -h -n jls1 -o %t 2>/dev/null || true)
        [ "$state" = idle ] && { echo "SLURM_CONF=$SLURM_CONF"; echo "PATH=$dir/bin"; exit 0; }
        sleep 0.1
    done
    echo "cluster.sh: the node did not become idle within 30 s (state: ${state:-none})" >&2
    tails >&2
    exit 1
    ;;
stop)
    export SLURM_CONF=$dir/slurm.conf
    [ -f "$SLURM_CONF" ] && scancel --full --quiet --partition=jls 2>/dev/null || true
    stop_pidfile "$dir/slurmd.pid"
    stop_pidfile "$dir/slurmctld.pid"
    stop_pidfile "$dir/munge/munged.pid"
    ;;
*)
    echo "usage: cluster.sh start|stop DIR [CPUS [MEM_MB]]" >&2
    exit 2
    ;;
esac
