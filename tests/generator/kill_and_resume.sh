#!/usr/bin/env bash
# sbgen killed with SIGKILL mid-run, then resumed from its last checkpoint, finishes with a
# valid jammed packing (checked by sbanalyze info when it is built); SIGTERM writes a checkpoint
# at the end of the running window, from which the run resumes bit for bit (compared with an
# uninterrupted run when sbanalyze is built, through its 17-digit text export).
# usage: kill_and_resume.sh SBGEN WORKDIR [SBANALYZE]
set -euo pipefail
sbgen=$1 work=$2 analyze=${3:-}
rm -rf "$work" && mkdir -p "$work" && cd "$work"
# The runs aim at 1e14 so they are still running when killed; the resumed runs stop at 1e8.
args=(--n 300 --seed 4 --gamma-slow 0.002 --pressure-final 1e14)

"$sbgen" "${args[@]}" --out a.h5 --checkpoint ck.h5 --checkpoint-interval 0.2 --quiet &
pid=$!
for _ in $(seq 600); do [[ -f ck.h5 ]] && break; sleep 0.1; done # a loaded machine is slow
sleep 0.5
kill -KILL "$pid" && ! wait "$pid" 2>/dev/null || true
[[ -f ck.h5 && ! -f a.h5 ]] || { echo "expected a checkpoint and no output after SIGKILL"; exit 1; }
# SIGKILL can land while a checkpoint is written: its temporary may stay, never ck.h5 half-written.
killed_temporaries=$(ls -a | grep '\.tmp-' || true)
# The resumed run checkpoints into the file it resumed from (scripts/reproduce-paper.sh does).
"$sbgen" --resume ck.h5 --checkpoint ck.h5 --checkpoint-interval 0.01 --pressure-final 1e8 \
    --out a.h5 --quiet
[[ -f a.h5 && -f ck.h5 ]] || { echo "resumed run wrote no output or lost its checkpoint"; exit 1; }

"$sbgen" "${args[@]}" --out b.h5 --quiet &
pid=$!
sleep 1
kill -TERM "$pid"
status=0; wait "$pid" || status=$?
[[ $status -eq 143 && -f b.checkpoint.h5 ]] || { echo "SIGTERM: status $status, no checkpoint"; exit 1; }
"$sbgen" --resume b.checkpoint.h5 --pressure-final 1e8 --out b.h5 --quiet

# Only the killed run's temporaries may remain (a later write of the same file removes them).
for temporary in $(ls -a | grep '\.tmp-' || true); do
    grep -qxF "$temporary" <<< "$killed_temporaries" ||
        { echo "temporary file $temporary left behind by a run that was not killed"; exit 1; }
done

if [[ -n "$analyze" ]]; then
    "$analyze" info a.h5 b.h5 | tee info.txt
    ! grep -qi "overlap" info.txt
    # Rotating superballs, whose mid-window checkpoints do not resume bit for bit: SIGTERM
    # waits for the window's end.
    rot=(--n 100 --p 1.5 --seed 4 --gamma-slow 0.01)
    "$sbgen" "${rot[@]}" --pressure-final 1e7 --out c.h5 --quiet
    "$sbgen" "${rot[@]}" --pressure-final 1e14 --out d.h5 --quiet &
    pid=$!
    sleep 1.3
    kill -TERM "$pid"
    wait "$pid" || true
    "$sbgen" --resume d.checkpoint.h5 --pressure-final 1e7 --out d.h5 --quiet
    "$analyze" convert c.h5 c.txt && "$analyze" convert d.h5 d.txt
    cmp -s c.txt d.txt || { echo "SIGTERM checkpoint: the resumed run differs from an uninterrupted one"; exit 1; }
fi
echo "kill and resume: ok"
