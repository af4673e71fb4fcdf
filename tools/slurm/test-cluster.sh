#!/bin/bash
# A real Slurm cluster in the tests: starts munged, slurmctld and slurmd on this machine from
# Debian's packages (slurm-wlm, munge) with a config written into a temporary directory, renders
# a 3-task array capture of the default path at 64x36 with `vista farm slurm --submit`, waits for
# its merge job, compares every frame with a sequential run (bit-identical), then cancels one
# task of a second array mid-way, shows that the merge refuses (exit 2, missing frames) and that
# resubmitting the array with --resume completes it. Stops every daemon it started, also on
# failure. Needs root (slurmd runs jobs as their users); exit 77 (ctest: skipped) otherwise.
#   tools/slurm/test-cluster.sh path/to/vista
set -euo pipefail
vista=$(readlink -f "${1:?usage: test-cluster.sh VISTA_EXECUTABLE}")
here=$(cd "$(dirname "$0")" && pwd)
if [ "$(id -u)" != 0 ]; then echo "SKIP: the Slurm cluster test runs slurmd, which needs root"; exit 77; fi
for tool in munged slurmctld slurmd sbatch squeue scancel; do
    command -v "$tool" > /dev/null || [ -x "/usr/sbin/$tool" ] || { echo "SKIP: $tool missing (apt-get install slurm-wlm munge)"; exit 77; }
done
export PATH=$PATH:/usr/sbin

dir=$(mktemp -d /tmp/vista-slurm.XXXXXX)
started=()
cleanup() {
    status=$?
    scancel --quiet --full $(squeue -h -o %A 2> /dev/null | sort -u) 2> /dev/null || true
    for daemon in slurmd slurmctld munged; do
        if [ -f "$dir/$daemon.pid" ]; then
            pid=$(cat "$dir/$daemon.pid")
            kill "$pid" 2> /dev/null || true
            for _ in $(seq 50); do kill -0 "$pid" 2> /dev/null || break; sleep 0.1; done
            kill -9 "$pid" 2> /dev/null || true
        fi
    done
    if [ $status != 0 ]; then
        echo "--- logs ($dir) ---"
        tail -n 20 "$dir"/log/* "$dir"/*/slurm-*.log 2> /dev/null || true
    fi
    rm -rf "$dir"
    exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM
fail() { echo "FAIL: $*"; exit 1; }
mkdir -p "$dir/state" "$dir/spool" "$dir/log"

# munge with its own key and socket: nothing of the machine's own munge is touched.
dd if=/dev/urandom of="$dir/munge.key" bs=1024 count=1 status=none
chmod 400 "$dir/munge.key"
munged --key-file="$dir/munge.key" --socket="$dir/munge.sock" --pid-file="$dir/munged.pid" \
    --log-file="$dir/log/munged.log" --seed-file="$dir/munge.seed" -f
host=$(hostname -s)
port=$((20000 + $$ % 20000))
cat > "$dir/slurm.conf" << CONF
ClusterName=vistatest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
AuthInfo=socket=$dir/munge.sock
CredType=cred/munge
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
InactiveLimit=0
MinJobAge=300
KillWait=2
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=vista Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$dir/slurm.conf
slurmctld -f "$SLURM_CONF" -i
slurmd -f "$SLURM_CONF"
for _ in $(seq 100); do sinfo -h -o %t 2> /dev/null | grep -q idle && break; sleep 0.2; done
sinfo -h -o %t | grep -q idle || fail "the node did not come up idle: $(sinfo 2>&1)"
echo "cluster up: $(sinfo -h -o '%P %D %t %c')"

# Waits (bounded) until none of the given jobs is queued or running.
wait_jobs() {
    for _ in $(seq 600); do
        [ -z "$(squeue -h -j "$1" 2> /dev/null)" ] && return 0
        sleep 0.2
    done
    fail "jobs $1 still running after 120 s: $(squeue)"
}
state() { scontrol show job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u | tr '\n' ' '; }

cd "$dir"
# Bit-identity holds with TAA and the clouds' accumulation off (their exponential histories
# meet a stated tolerance instead: docs/farm.md); at the default 0.2 fps every frame would be a
# camera cut anyway, but the check should not rest on that.
args=(--frames 12 --size 64x36 --set postfx.taa.enabled=false --set clouds.temporal=false)
start=$(date +%s.%N)
"$vista" capture "${args[@]}" --out seq > /dev/null
seq_s=$(echo "$(date +%s.%N) - $start" | bc)

# 1. The array through the submit helper, and its merge job.
start=$(date +%s.%N)
"$vista" farm slurm --tasks 3 --out farm --backend osmesa --submit -- "${args[@]}" | tee submit.txt
read -r array_job merge_job < <(sed -n 's/.*array job \([0-9]*\).*merge job \([0-9]*\).*/\1 \2/p' submit.txt)
[ -n "$merge_job" ] || fail "no job ids in: $(cat submit.txt)"
wait_jobs "$array_job,$merge_job"
farm_s=$(echo "$(date +%s.%N) - $start" | bc)
[ "$(state "$merge_job")" = "COMPLETED " ] || fail "merge job $merge_job: $(state "$merge_job")$(cat farm/slurm-merge-*.log)"
[ -s farm/capture.mp4 ] || fail "the merge job wrote no farm/capture.mp4"
for i in $(seq 0 11); do
    f=$(printf frame_%04d.png "$i")
    cmp -s "seq/$f" "farm/$f" || fail "frame $i of the array differs from the sequential run's"
done
echo "12 frames of 3 array tasks are bit-identical to the sequential run's; merged video: $(stat -c %s farm/capture.mp4) bytes"
echo "wall time: sequential ${seq_s} s, array of 3 on $(nproc) cores + merge ${farm_s} s"

# 2. Cancel task 1 after its first frame; the merge lists what is missing; --resume completes it.
mkdir kill
job=$(sbatch --parsable --array=0-2 --output=kill/slurm-%A_%a.log "$here/capture-array.sbatch" "$vista" osmesa \
      --out kill "${args[@]}")
for _ in $(seq 600); do
    [ -f kill/manifest-shard-1-of-3.json ] && break
    sleep 0.1
done
[ -f kill/manifest-shard-1-of-3.json ] || fail "task 1 wrote no manifest within 60 s"
scancel --signal=KILL --full "${job}_1"
wait_jobs "$job"
done_frames=$(grep -c '"index"' kill/manifest-shard-1-of-3.json)
[ "$done_frames" -lt 4 ] || fail "task 1 finished its 4 frames before it was cancelled; cannot show --resume"
set +e
"$vista" farm merge kill > merge.txt 2>&1
code=$?
set -e
cat merge.txt
[ $code = 2 ] || fail "merge of an incomplete capture: exit $code, expected 2"
grep -q "frames missing" merge.txt || fail "the merge did not list the missing frames"
echo "task 1 cancelled after $done_frames of its 4 frames; merge refused (exit 2)"
job=$(sbatch --parsable --array=0-2 --output=kill/slurm-resume-%A_%a.log "$here/capture-array.sbatch" "$vista" osmesa \
      --out kill "${args[@]}")
wait_jobs "$job"
grep -h "kept" kill/slurm-resume-*.log
grep -q "($done_frames kept" kill/slurm-resume-"${job}"_1.log || fail "the resumed task 1 did not keep its $done_frames frames"
"$vista" farm merge kill
for i in $(seq 0 11); do
    f=$(printf frame_%04d.png "$i")
    cmp -s "seq/$f" "kill/$f" || fail "frame $i after --resume differs from the sequential run's"
done
echo "PASS: --resume completed the cancelled task; every frame matches the sequential run"
