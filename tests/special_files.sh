#!/usr/bin/env bash
# Special files and same-file outputs (issue 20, defects 1, 3, 11; issue 46, defects 1-4, 7, 8,
# 10, 13): a FIFO input is refused at once by every command (never a hang); a device or FIFO
# output is refused and left as it was (never renamed over); an output that is its own input
# (by inode, through a hard link too), an export or another output is refused and nothing
# changes; a symbolic link output stays a link to the new file; standard output that cannot be
# written is an error; a FIFO wisdom file is skipped with a warning, never opened.
# usage: special_files.sh SBGEN SBANALYZE PACKING.h5 WORKDIR
set -uo pipefail
sbgen=$1 sbanalyze=$2 packing=$3 work=$4
lattice=$(cd "$(dirname "$0")/../scripts" && pwd)/make_lattice.py
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
# The JSON summary is written into a FIFO (or device) in place, at once refused where no process
# reads the FIFO (never a wait), and read whole where one does (issue 66 item 6).
expect "a FIFO that no process is reading" "$sbanalyze" good.h5 --compute contacts --json fifo.h5
cat fifo.h5 > from-fifo.json & reader=$!
sleep 0.5 # the reader has the FIFO open before sbanalyze writes (a second at least before it does)
if ! timeout 20 "$sbanalyze" good.h5 --compute contacts --json fifo.h5 >/dev/null 2>&1; then
    echo "FAIL: --json into a read FIFO"; failures=$((failures + 1))
    kill "$reader" 2>/dev/null # still waiting for a writer
fi
wait "$reader"
grep -q '"z_mean"' from-fifo.json || { echo "FAIL: the FIFO's JSON: $(head -c 200 from-fifo.json)"; failures=$((failures + 1)); }
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
# An output that is another output or an export (issue 46, defect 1; 13).
mkdir -p v && echo precious >v/good.vdb
vdb=(--vdb v --compute voxels --voxels 40 --fft-plan estimate)
expect "is also where --vdb exports" "$sbanalyze" good.h5 --out v/good.vdb "${vdb[@]}"
expect "is also where --vdb exports" "$sbanalyze" good.h5 --json v/good.vdb "${vdb[@]}"
[[ "$(cat v/good.vdb)" == precious ]] || { echo "FAIL: an export path replaced"; failures=$((failures + 1)); }
expect "again: each packing counts once" "$sbanalyze" good.h5 hard.h5 --compute contacts --json -
expect "name the same file" "$sbgen" --n 10 --out same.h5 --checkpoint ./same.h5
# Two runs sharing an output or a checkpoint: the second is refused while the first runs.
"$sbgen" --n 2000 --seed 1 --out busy.h5 --checkpoint busy-cp.h5 --quiet & first=$!
sleep 1
expect "'busy.h5' is being written by another process (pid $first)" "$sbgen" --n 10 --out busy.h5
expect "is being written by another process" "$sbgen" --n 10 --out other.h5 --checkpoint busy-cp.h5
kill -TERM "$first"; wait "$first" 2>/dev/null
[[ ! -e .busy.h5.lock ]] || { echo "FAIL: a lock file left behind"; failures=$((failures + 1)); }
# Standard output that cannot be written (defect 2).
for command in "good.h5 --compute contacts --json -" "info good.h5" "schema --json"; do
    expect "cannot write to standard output" sh -c "\"\$0\" $command >/dev/full" "$sbanalyze"
done
# A symbolic link as output: written through, the link kept (defect 3).
mkdir -p target && ln -s target/real.h5 link.h5
if "$sbanalyze" convert good.h5 link.h5 2>/dev/null && [[ -L link.h5 && -f target/real.h5 ]]; then :
else echo "FAIL: the link output was replaced or its target not written"; failures=$((failures + 1)); fi
# A FIFO as the FFTW wisdom: skipped with a warning, the run completes (defect 4).
output=$(timeout 20 "$sbanalyze" good.h5 --compute chi --voxels 40 --fft-plan measure \
         --fft-wisdom fifo.h5 --json - 2>&1); rc=$?
if [[ $rc -ne 0 || "$output" != *"is not a regular file"* ]]; then
    echo "FAIL (rc $rc): FIFO wisdom: $output"; failures=$((failures + 1))
fi
# Bad values refused at once, naming their option or variable (defects 7, 8, 10).
expect "exceed the 200^3" "$sbanalyze" good.h5 --compute pores --pore-points 1099511627776 --json -
expect "use a smaller --pore-voxels" "$sbanalyze" good.h5 --compute pores --pores voxel --pore-voxels 10000 --json -
expect "above 1625, the largest grid of --pores refined" "$sbanalyze" good.h5 --compute pores --pore-voxels 10000 --json -
for deadline in 1e10 99999999999 1e400 0 -1 abc ""; do
    expect "SBPACK_READ_DEADLINE_S='$deadline' is not a number" \
        env SBPACK_READ_DEADLINE_S="$deadline" "$sbanalyze" info good.h5
done
expect "SBPACK_READ_DEADLINE_S='abc' is not a number" env SBPACK_READ_DEADLINE_S=abc "$sbgen" --resume good.h5 --out y.h5
# With several inputs an analysis error names its file (defect 9): aligned p = 10 cubes touching
# face to face on a 4^3 lattice leave no voxel centre void at M = 16.
python3 "$lattice" 10 4 cubes.txt && cp cubes.txt cubes2.txt
expect "'cubes.txt': pore sizes: no void voxel at M = 16" \
    "$sbanalyze" cubes.txt cubes2.txt --compute pores --pore-voxels 16 --json -
# A huge --qmax is refused by the memory estimate, in a readable message (defect 14).
expect "use a smaller --qmax" "$sbanalyze" good.h5 --compute sq --qmax 1e300 --json -
output=$("$sbanalyze" good.h5 --compute sq --qmax 1e300 --json - 2>&1)
[[ ${#output} -lt 400 ]] || { echo "FAIL: a 300-digit qmax: $output"; failures=$((failures + 1)); }
# Smaller ones (defect 14): a name of 250 characters still gets its temporary; an XYZ given to a
# reader is read (issue 66 item 1); a relative XDG_CACHE_HOME is ignored (the XDG specification).
long=$(printf 'a%.0s' {1..247}).h5
"$sbanalyze" convert good.h5 "$long" 2>/dev/null && [[ -f "$long" ]] ||
    { echo "FAIL: a 250-character output name"; failures=$((failures + 1)); }
rm -f "$long" # and sbgen's lock beside it (.NAME.lock) fits too
"$sbgen" --n 10 --out "$long" --quiet 2>/dev/null && [[ -f "$long" ]] ||
    { echo "FAIL: sbgen with a 250-character output name"; failures=$((failures + 1)); }
"$sbanalyze" convert good.h5 out.xyz 2>/dev/null
"$sbanalyze" info out.xyz > /dev/null 2>&1 ||
    { echo "FAIL: sbanalyze info of its own XYZ export"; failures=$((failures + 1)); }
mkdir -p home && HOME=$PWD/home XDG_CACHE_HOME=relative "$sbanalyze" good.h5 --compute chi \
    --voxels 40 --fft-plan measure --fft-planning-budget none --json - >/dev/null 2>&1
[[ ! -e relative && -f home/.cache/sbpack/fftw-wisdom ]] ||
    { echo "FAIL: a relative XDG_CACHE_HOME was used"; failures=$((failures + 1)); }
[[ $failures -eq 0 ]] && echo "special files: ok"
