#!/usr/bin/env bash
# Special files and same-file outputs (issue 20, defects 1, 3, 11): a FIFO input is refused at
# once by every command (never a hang); a device or FIFO output is refused and left as it was
# (never renamed over); an output that is its own input (by inode, through a hard link too) is
# refused and the input is unchanged.
# usage: special_files.sh SBGEN SBANALYZE PACKING.h5 WORKDIR
set -uo pipefail
sbgen=$1 sbanalyze=$2 packing=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
cp "$packing" good.h5
sum=$(md5sum good.h5)
mkfifo fifo.h5
failures=0
expect() { # expected-message command...
    local message=$1; shift
    local output rc
    output=$(timeout 20 "$@" 2>&1); rc=$?
    if [[ $rc -eq 124 ]]; then echo "HANG: $*"; failures=$((failures + 1)); return; fi
    if [[ $rc -ne 1 || "$output" != *"$message"* ]]; then
        echo "FAIL (rc $rc): $*: $output"; failures=$((failures + 1))
    fi
}
# FIFO inputs: refused up front.
expect "is not a regular file" "$sbanalyze" info fifo.h5
expect "is not a regular file" "$sbanalyze" fifo.h5 --json -
expect "is not a regular file" "$sbanalyze" convert fifo.h5 out.txt
expect "is not a regular file" "$sbgen" --resume fifo.h5 --out x.h5
# Special outputs: refused, left as they were.
expect "not a regular file" "$sbanalyze" good.h5 --compute contacts --json fifo.h5
expect "not a regular file" "$sbanalyze" convert good.h5 fifo.h5
expect "not a regular file" "$sbgen" --n 10 --out fifo.h5
[[ -p fifo.h5 ]] || { echo "FAIL: the FIFO was replaced"; failures=$((failures + 1)); }
if [[ $(id -u) -eq 0 ]]; then # a character device of our own (the null device's numbers)
    mknod null.h5 c 1 3
    expect "not a regular file" "$sbanalyze" good.h5 --compute contacts --out null.h5
    expect "not a regular file" "$sbanalyze" convert good.h5 null.h5
    [[ -c null.h5 ]] || { echo "FAIL: the device node was replaced"; failures=$((failures + 1)); }
fi
# An output that is the input.
ln good.h5 hard.h5
expect "is also the input" "$sbanalyze" convert good.h5 good.h5
expect "is also the input" "$sbanalyze" convert good.h5 hard.h5
expect "is also the input" "$sbanalyze" good.h5 --compute contacts --out hard.h5
expect "is also the input" "$sbgen" --resume good.h5 --out hard.h5
[[ "$(md5sum good.h5)" == "$sum" ]] || { echo "FAIL: the input changed"; failures=$((failures + 1)); }
[[ $failures -eq 0 ]] && echo "special files: ok"
