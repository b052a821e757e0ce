#!/usr/bin/env bash
# Opt-in end-to-end test of the SLURM profile on a throw-away single-node cluster on this machine:
#   1. installs slurmctld + slurmd + munge from the system package manager (Debian/Ubuntu, needs root),
#   2. writes a slurm.conf for localhost with this machine's real CPUs and memory (`slurmd -C`), on ports of
#      its own, in a temporary directory, linked from /etc/slurm/slurm.conf (an existing one is moved aside
#      and put back at the end): the plugin's job step drops SLURM_CONF from the environment of the `srun`
#      it runs inside each job, so srun only finds the configuration at the default path,
#   3. starts munged, slurmctld and slurmd (in the foreground of background processes: no systemd needed),
#   4. runs a small chunked dense map through `snakemake --profile workflow/profiles/slurm` in one copy of
#      the project and with `snakemake -j2` (local) in another, and checks with xarray that the merged
#      datasets hold identical data,
#   5. stops exactly the daemons it started (by PID) and removes the temporary directory.
# Usage (from the repository root, with the venv that has snakemake-executor-plugin-slurm):
#     sudo tests/slurm/run_local_slurm_test.sh            # or: make slurm-test
# Environment: PYTHON (default .venv/bin/python), STICKSLIP_SLURM_NO_INSTALL=1 to skip apt-get,
#     STICKSLIP_SLURM_KEEP=1 to keep the temporary directory (logs) for inspection.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
PYTHON="${PYTHON:-$ROOT/.venv/bin/python}"
PYTHON="$(cd "$(dirname "$PYTHON")" && pwd)/$(basename "$PYTHON")"
WORK="$(mktemp -d /tmp/stickslip-slurm.XXXXXX)"
PIDS=()

log() { printf '[slurm-test %s] %s\n' "$(date +%H:%M:%S)" "$*"; }

cleanup() {
    local rc=$?
    for pid in "${PIDS[@]}"; do
        kill "$pid" 2>/dev/null || true
    done
    for pid in "${PIDS[@]}"; do
        wait "$pid" 2>/dev/null || true
    done
    if [[ $rc -ne 0 ]]; then
        log "FAILED (exit $rc); daemon logs:"
        tail -n 30 "$WORK"/*.log 2>/dev/null || true
    fi
    if [[ -L /etc/slurm/slurm.conf && "$(readlink /etc/slurm/slurm.conf)" == "$WORK/slurm.conf" ]]; then
        rm -f /etc/slurm/slurm.conf
        [[ -e /etc/slurm/slurm.conf.stickslip-backup ]] && mv /etc/slurm/slurm.conf.stickslip-backup /etc/slurm/slurm.conf
    fi
    if [[ "${STICKSLIP_SLURM_KEEP:-0}" == 1 ]]; then log "kept $WORK"; else rm -rf "$WORK"; fi
    exit $rc
}
trap cleanup EXIT

[[ $(id -u) -eq 0 ]] || { echo "run as root (apt-get and the daemons need it): sudo $0" >&2; exit 2; }
"$PYTHON" -c "import snakemake_executor_plugin_slurm" 2>/dev/null || {
    echo "$PYTHON lacks snakemake-executor-plugin-slurm: pip install -e '.[pipeline,test,slurm]'" >&2; exit 2; }

# --- 1. packages ---------------------------------------------------------------------------------------------
if [[ "${STICKSLIP_SLURM_NO_INSTALL:-0}" != 1 ]]; then
    log "installing slurmctld slurmd slurm-client munge"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq slurmctld slurmd slurm-client munge >/dev/null
fi
log "$(slurmd -V)"

# --- 2. configuration ----------------------------------------------------------------------------------------
HOST="$(hostname -s)"
NODE_LINE="$(slurmd -C | head -n 1)"           # NodeName=<host> CPUs=.. CoresPerSocket=.. RealMemory=..
MEM="$(sed -n 's/.*RealMemory=\([0-9]*\).*/\1/p' <<<"$NODE_LINE")"
MEM=$(( MEM * 9 / 10 ))                         # leave slurmd some room below the physical memory
NODE_LINE="$(sed "s/RealMemory=[0-9]*/RealMemory=$MEM/; s/ UpTime=.*//" <<<"$NODE_LINE")"
chmod 755 "$WORK"   # munged runs as user munge and must reach its socket directory
mkdir -p "$WORK/state" "$WORK/spool" "$WORK/munge" "$WORK/projects"
chown munge:munge "$WORK/munge"; chmod 755 "$WORK/munge"   # munged wants x for all on its socket dir
export SLURM_CONF="$WORK/slurm.conf"
cat >"$SLURM_CONF" <<CONF
ClusterName=stickslip-test
SlurmctldHost=$HOST
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$WORK/munge/munge.socket.2
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/slurmctld.log
SlurmdLogFile=$WORK/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=600
InactiveLimit=0
KillWait=10
$NODE_LINE State=UNKNOWN
PartitionName=debug Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
CONF
log "node: $NODE_LINE"
mkdir -p /etc/slurm
[[ -e /etc/slurm/slurm.conf && ! -L /etc/slurm/slurm.conf ]] && mv /etc/slurm/slurm.conf /etc/slurm/slurm.conf.stickslip-backup
ln -sfn "$SLURM_CONF" /etc/slurm/slurm.conf

# --- 3. daemons ----------------------------------------------------------------------------------------------
[[ -s /etc/munge/munge.key ]] || { mungekey --create --keyfile /etc/munge/munge.key 2>/dev/null \
    || dd if=/dev/urandom bs=1 count=1024 of=/etc/munge/munge.key 2>/dev/null; }
chown munge:munge /etc/munge/munge.key; chmod 400 /etc/munge/munge.key
runuser -u munge -- munged --foreground --socket="$WORK/munge/munge.socket.2" \
    --pid-file="$WORK/munge/munged.pid" --log-file="$WORK/munge/munged.log" --seed-file="$WORK/munge/seed" &
PIDS+=($!)
for _ in $(seq 50); do [[ -S "$WORK/munge/munge.socket.2" ]] && break; sleep 0.2; done
munge -n --socket="$WORK/munge/munge.socket.2" | unmunge --socket="$WORK/munge/munge.socket.2" >/dev/null
log "munged up"
slurmctld -D -i -f "$SLURM_CONF" >"$WORK/slurmctld.out" 2>&1 &
PIDS+=($!)
slurmd -D -f "$SLURM_CONF" >"$WORK/slurmd.out" 2>&1 &
PIDS+=($!)
for _ in $(seq 60); do
    state="$(sinfo -h -n "$HOST" -o %T 2>/dev/null || true)"
    [[ "$state" == idle* ]] && break
    [[ "$state" == down* || "$state" == drain* ]] && scontrol update nodename="$HOST" state=resume 2>/dev/null || true
    sleep 1
done
sinfo
[[ "$(sinfo -h -n "$HOST" -o %T)" == idle* ]] || { log "node $HOST did not become idle"; exit 1; }
log "sbatch smoke test: $(sbatch --wait -o "$WORK/smoke.out" --wrap 'hostname' | tr '\n' ' ')"
cat "$WORK/smoke.out"

# --- 4. the chunked sweep, through SLURM and locally ---------------------------------------------------------
cat >"$WORK/slurm_test_map.yaml" <<'YAML'
# 5 x 4 map in chunks of 6 (4 jobs, the last one short)
dense_map:
  chunk_size: 6
  maps:
    speed_damping:
      axes:
        - {name: belt_velocity, start: 0.2, stop: 1.4, num: 5, units: "mm s-1", long_name: "belt velocity V_b"}
        - {name: damping, start: 0.5, stop: 2.5, num: 4, units: "N s mm-1", long_name: "viscous damping C"}
YAML
for where in slurm local; do
    "$PYTHON" -c "import sys; sys.path.insert(0, '$ROOT/tests'); from project_run import copy_project; \
from pathlib import Path; p = Path('$WORK/projects/$where'); p.mkdir(); copy_project(p)"
done
CONFIGS=(--configfile config/test/onedof.yaml config/test/dense_map.yaml "$WORK/slurm_test_map.yaml")
TARGET=results/dense_map/speed_damping.nc
SNAKEMAKE="$(dirname "$PYTHON")/snakemake"
export PATH="$(dirname "$PYTHON"):$PATH"      # jobs on the node run this venv's python and snakemake

log "snakemake --profile workflow/profiles/slurm (SLURM)"
(cd "$WORK/projects/slurm" && "$SNAKEMAKE" --profile "$ROOT/workflow/profiles/slurm" "${CONFIGS[@]}" \
    --slurm-no-account --slurm-status-command squeue --slurm-init-seconds-before-status-checks 5 \
    --seconds-between-status-checks 5 --latency-wait 10 --jobs 4 -- "$TARGET") 2>&1 | tee "$WORK/snakemake_slurm.log" \
    | grep -E "Submitted|SLURM|Finished|steps|Error|error" || true
[[ -s "$WORK/projects/slurm/$TARGET" ]] || { log "SLURM run left no $TARGET"; tail -n 60 "$WORK/snakemake_slurm.log"; exit 1; }
jobs_seen="$(grep -c 'has been submitted with SLURM jobid\|Job .* has been submitted' "$WORK/snakemake_slurm.log" || true)"
log "SLURM jobs submitted: $jobs_seen"

log "snakemake -j2 (local)"
(cd "$WORK/projects/local" && "$SNAKEMAKE" -j2 "${CONFIGS[@]}" -- "$TARGET") >"$WORK/snakemake_local.log" 2>&1

"$PYTHON" - "$WORK/projects/slurm/$TARGET" "$WORK/projects/local/$TARGET" <<'PY'
import sys

import numpy as np
import xarray as xr

slurm, local = (xr.load_dataset(p) for p in sys.argv[1:3])
xr.testing.assert_equal(slurm, local)  # same dims, coords, data variables and values (NaN == NaN)
for name in local.data_vars:
    assert np.array_equal(slurm[name].values, local[name].values, equal_nan=True), name
assert slurm.attrs["method_chunks"] == local.attrs["method_chunks"] == 4
print(f"merged datasets IDENTICAL: {dict(local.sizes)}, {len(local.data_vars)} variables, "
      f"{int((local.solver_ok == 1).sum())} ok runs, chunks={local.attrs['method_chunks']}")
PY
log "PASSED"
