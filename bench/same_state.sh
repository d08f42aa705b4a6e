#!/usr/bin/env bash
# sbgen builds compared from one state: every BINARY resumes CHECKPOINT for SECONDS of wall time,
# all at once (so the shared machine's load falls on each alike), and each is stopped by SIGTERM
# at the end of a window. Trajectories part after a few collisions, so this compares the cost
# in the same state, not the same events. Prints, per binary, the collisions it made and the
# CPU microseconds per collision and per exact evaluation, and the robust pair solver's calls
# per collision, from the provenance (bench/RESULTS.md,
# "Near-cubes: lower bounds down to the contact gap").
# usage: bench/same_state.sh SECONDS CHECKPOINT BINARY...
set -euo pipefail
if [ $# -lt 3 ]; then
    echo "usage: $0 SECONDS CHECKPOINT BINARY..." >&2
    exit 1
fi
seconds=$1 state=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
i=0
for binary in "$@"; do
    i=$((i + 1))
    timeout -s TERM "$seconds" "$binary" --resume "$state" --out "$work/out$i.h5" \
        --checkpoint "$work/stop$i.h5" --quiet > /dev/null 2>&1 &
done
wait || true
i=0
for binary in "$@"; do
    i=$((i + 1))
    /usr/bin/python3 - "$state" "$work/stop$i.h5" "$work/out$i.h5" "$binary" <<'EOF'
import os, sys
import h5py

state, stop, out, binary = sys.argv[1:]
end = stop if os.path.exists(stop) else out  # a run that finished wrote its output instead
if not os.path.exists(end):
    sys.exit(f"{binary}: neither a checkpoint nor an output (it failed: run it alone to see why)")
keys = ("collisions", "cpu_time_s", "predictor_evaluations", "predictor_robust_evaluations")
a, b = ([h5py.File(f, "r")["provenance"].attrs[k] for k in keys] for f in (state, end))
collisions, cpu, evaluations, robust = (y - x for x, y in zip(a, b))
print(f"{binary[-40:]:<40} collisions {collisions:9d}  CPU {cpu:7.1f} s  "
      f"µs/collision {cpu / collisions * 1e6:7.1f}  µs/evaluation {cpu / evaluations * 1e6:6.2f}  "
      f"robust/collision {robust / collisions:.3f}"
      + ("  (finished)" if end == out else ""))
EOF
done
