#!/usr/bin/env bash
# Fuzzes the packing readers (HDF5 and text) with libFuzzer under ASan + UBSan for SECONDS
# (default 600), starting from the packings in data/ (docs/reliability.md, "Inputs"). A crash,
# a sanitizer report or a leak of ours is a finding: its input is left in build-fuzz/findings/
# and the exit status is 1; make it a regression test. Inputs on which libhdf5 itself loops
# (damaged heaps) are timeouts, not findings, once sbanalyze ends on them with its read-deadline
# message (io/read_guard.hpp): each is checked that way against the release build.
#   scripts/fuzz.sh [SECONDS] [RELEASE_BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600} release=${2:-build}
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz -j"$(nproc)"
corpus=build-fuzz/corpus findings=build-fuzz/findings
rm -rf "$findings" && mkdir -p "$corpus" "$findings"
cp -n data/*.h5 data/*.txt "$corpus"/
# Leaks inside libhdf5 on its own error paths are not ours (its library is not instrumented).
echo "leak:libhdf5" > build-fuzz/lsan.supp
LSAN_OPTIONS=suppressions=$PWD/build-fuzz/lsan.supp build-fuzz/tests/fuzz/fuzz_packing_reader \
    "$corpus" -fork=1 -ignore_timeouts=1 -ignore_crashes=1 -timeout=10 -rss_limit_mb=2048 \
    -max_total_time="$seconds" -artifact_prefix="$findings/" 2>&1 | grep -E "^#|INFO: fuzzed|DONE|ERROR|SUMMARY" | tail -20 || true
# A finding is ours unless libhdf5 faults or loops by itself (frame #1 of the report inside it)
# and the release sbanalyze ends on the input with its read-guard message (io/read_guard.hpp).
# (Outputs are captured first: with pipefail, the program's own exit 1 would fail a grep pipe.)
guarded() {
    local said
    said=$(SBPACK_READ_DEADLINE_S=5 "$release/analysis/sbanalyze" info "$1" 2>&1 || true)
    grep -q "reading did not finish\|the HDF5 library crashed reading it" <<< "$said"
}
inside_hdf5() {
    local report
    report=$(timeout 60 build-fuzz/tests/fuzz/fuzz_packing_reader "$1" 2>&1 || true)
    grep -q "#1 .*libhdf5" <<< "$report"
}
status=0
for input in "$findings"/*; do
    [ -e "$input" ] || continue
    case $(basename "$input") in
        timeout-*) guarded "$input" && verdict=handled ;;
        *) inside_hdf5 "$input" && guarded "$input" && verdict=handled ;;
    esac
    if [ "${verdict:-}" = handled ]; then
        echo "fuzz.sh: $input: libhdf5 fails on it by itself; sbanalyze ends with its read-guard message"
    else
        echo "fuzz.sh: FINDING $input"; status=1
    fi
    verdict=
done
exit $status
