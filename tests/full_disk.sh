#!/usr/bin/env bash
# A full disk (issue 20, defect 2): every writer of sbgen and sbanalyze (HDF5 packing and
# results, JSON, text, XYZ, VDB) fails with exit 1 and a message naming the file and the
# system's reason, leaves the earlier file at that path as it was and no temporary behind.
# As root on a small tmpfs ("No space left on device"); elsewhere under a file-size limit
# (RLIMIT_FSIZE, SIGXFSZ ignored: "File too large").
# usage: full_disk.sh SBGEN SBANALYZE PACKING.h5 WORKDIR
set -uo pipefail
sbgen=$1 sbanalyze=$2 packing=$3 work=$4
umount "$work/disk" 2>/dev/null
rm -rf "$work" && mkdir -p "$work/disk" && cd "$work" || exit 1
if mount -t tmpfs -o size=2m tmpfs disk 2>/dev/null; then
    mode=tmpfs reason="No space left on device"
    trap 'umount "$work/disk"' EXIT
    limited() { "$@"; }
else
    mode=ulimit reason="File too large"
    limited() { (trap '' XFSZ; ulimit -f 1; exec "$@"); } # 512-byte files at most
fi
d=disk
# Earlier outputs, written while there is room.
"$sbanalyze" convert "$packing" $d/p.txt >/dev/null 2>&1
"$sbanalyze" convert "$packing" $d/p.xyz >/dev/null 2>&1
"$sbanalyze" convert "$packing" $d/p.h5 >/dev/null 2>&1
"$sbanalyze" "$packing" --compute voxels --voxels 40 --vdb $d --quiet --out $d/r.h5 --json $d/r.json \
    --fft-wisdom none || exit 1
"$sbgen" --n 20 --pressure-switch 1e2 --pressure-final 1e3 --quiet --out $d/g.h5 || exit 1
md5sum $d/* > before.md5
if [[ $mode == tmpfs ]]; then # fill the disk
    dd if=/dev/zero of=$d/filler bs=4k 2>/dev/null
    md5sum $d/[!f]* > before.md5
fi
failures=0
expect_full() { # command... : exit 1 and the reason
    local output rc
    output=$(limited "$@" 2>&1); rc=$?
    if [[ $rc -ne 1 || "$output" != *"$reason"* ]]; then
        echo "FAIL (rc $rc): $*: $output"; failures=$((failures + 1))
    fi
}
expect_full "$sbanalyze" convert "$packing" $d/p.txt
expect_full "$sbanalyze" convert "$packing" $d/p.xyz
expect_full "$sbanalyze" convert "$packing" $d/p.h5
expect_full "$sbanalyze" "$packing" --compute voxels --voxels 40 --quiet --out $d/r.h5 --fft-wisdom none
expect_full "$sbanalyze" "$packing" --compute voxels --voxels 40 --quiet --json $d/r.json --fft-wisdom none
expect_full "$sbanalyze" "$packing" --compute voxels --voxels 40 --vdb $d --quiet --json - --fft-wisdom none
expect_full "$sbgen" --n 20 --pressure-switch 1e2 --pressure-final 1e3 --quiet --out $d/g.h5
md5sum -c --quiet before.md5 || { echo "FAIL: an earlier output changed"; failures=$((failures + 1)); }
leftovers=$(ls -A $d | grep '\.tmp-' || true)
[[ -z "$leftovers" ]] || { echo "FAIL: temporaries left: $leftovers"; failures=$((failures + 1)); }
[[ $failures -eq 0 ]] && echo "full disk ($mode): ok"
