#!/usr/bin/env bash
# Fuzzes the readers with libFuzzer under ASan + UBSan for SECONDS each (default 600), every
# target from its seed corpus (docs/reliability.md, "Fuzzing and sanitizers"):
#   fuzz_packing_reader     readPacking (HDF5) and readTextPacking (seeds: data/)
#   fuzz_packing_file       readPackingFile, the reader picked by the name (seeds: data/ and
#                           tests/fuzz/seeds/packing_file/: GSD, LAMMPS and XYZ files padded to
#                           the size that names them as their format)
#   fuzz_checkpoint_reader  sbgen --resume: readPacking, readCheckpoint, the resume constructor
#                           (seeds: tests/fuzz/seeds/checkpoint/)
#   fuzz_option_number      parseNumber, parseInteger (seeds: tests/fuzz/seeds/option_number/)
# A crash, a sanitizer report, a leak or an allocation of ours, or a refusal of the wrong type or
# not naming its file (or option), is a finding: its input is left in build-fuzz/findings/TARGET/
# and the exit status is 1; make it a regression test. Inputs on which libhdf5 itself loops,
# faults, overruns or allocates without bound (damaged heaps, attribute messages, object headers)
# are not findings once the release program refuses them, naming the file (with its read-guard
# message, io/read_guard.hpp, where libhdf5 loops): `sbanalyze info FILE` for the packing readers,
# `sbgen --resume FILE` for checkpoints; each is checked that way against the release build. An
# input that fails only after others in its job (libhdf5's state carried over) is reported as such.
#   scripts/fuzz.sh [SECONDS] [RELEASE_BUILD_DIR] [TARGET...]
# SECONDS 0 triages the findings of the last run again without fuzzing.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600} release=${2:-build}
shift $(($# < 2 ? $# : 2))
targets=("$@")
[ ${#targets[@]} -gt 0 ] ||
    targets=(fuzz_packing_reader fuzz_packing_file fuzz_checkpoint_reader fuzz_option_number)
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz -j"$(nproc)"
# Leaks inside libhdf5 on its own error paths are not ours (its library is not instrumented).
echo "leak:libhdf5" > build-fuzz/lsan.supp
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The targets' input files (and libFuzzer's job files) go there too: a crashed job leaves its own.
export TMPDIR=$scratch

seed() {
    case $1 in
        fuzz_packing_reader) cp -n data/*.h5 data/*.txt "$2"/ ;;
        fuzz_packing_file) cp -n data/*.h5 data/*.txt tests/fuzz/seeds/packing_file/* "$2"/ ;;
        fuzz_checkpoint_reader) cp -n tests/fuzz/seeds/checkpoint/*.h5 "$2"/ ;;
        fuzz_option_number) cp -n tests/fuzz/seeds/option_number/* "$2"/ ;;
    esac
}

# A finding is ours unless libhdf5 fails by itself (the first frame of the input's report, past
# the sanitizers', libFuzzer's, malloc's and libc's memcpy, is inside libhdf5) and the release
# program ends on the input with exit 1 and an error naming the file (for a timeout: the read
# guard's message, io/read_guard.hpp). Some of libhdf5's faults read memory it never initialised
# (H5A__attr_release_table after a bad attribute message) or past its buffers: ASan fills new
# memory with 0xbe, so the release program runs with glibc's MALLOC_PERTURB_=190 to meet the same
# bytes. (Outputs are captured first: with pipefail, the program's own exit 1 would fail a pipe.)
guarded() {
    local said rc
    case $1 in
        fuzz_option_number) return 1 ;; # no libhdf5 there: every finding is ours
        fuzz_checkpoint_reader)
            rm -f "$scratch"/out.h5 "$scratch"/.out*
            said=$(MALLOC_PERTURB_=190 SBPACK_READ_DEADLINE_S=5 timeout 60 \
                "$release/generator/sbgen" --quiet --resume "$2" --out "$scratch/out.h5" 2>&1) &&
                rc=0 || rc=$? ;;
        *) said=$(MALLOC_PERTURB_=190 SBPACK_READ_DEADLINE_S=5 timeout 60 \
            "$release/analysis/sbanalyze" info "$2" 2>&1) && rc=0 || rc=$? ;;
    esac
    [ "$rc" = 1 ] && grep -qE "error: '$2': ${3:-}" <<< "$said"
}
# The report of the input run alone (an allocation of more than 256 MB is reported with its
# stack, so that an out-of-memory input names the code that allocated).
report() {
    timeout 60 "build-fuzz/tests/fuzz/$1" -rss_limit_mb=2048 -malloc_limit_mb=256 "$2" 2>&1 || true
}
not_hdf5_frames="__interceptor_|__asan|__sanitizer|fuzzer::|sysdeps/x86_64/multiarch/mem"
not_hdf5_frames+="| in (malloc|calloc|realloc) "
inside_hdf5() {
    grep -E "^ +#[0-9]+ " <<< "$1" | grep -vE "$not_hdf5_frames" | head -1 | grep -q libhdf5
}

count() { find "$1" -maxdepth 1 -type f | wc -l; }

status=0
for target in "${targets[@]}"; do
    corpus=build-fuzz/corpus/$target findings=build-fuzz/findings/$target
    if [ "$seconds" != 0 ]; then # 0: triage the findings of the last run again
        rm -rf "$findings" && mkdir -p "$corpus" "$findings"
        seed "$target" "$corpus"
        echo "fuzz.sh: $target, $seconds s, corpus $corpus ($(count "$corpus") inputs)"
        LSAN_OPTIONS=suppressions=$PWD/build-fuzz/lsan.supp "build-fuzz/tests/fuzz/$target" \
            "$corpus" -fork=1 -ignore_timeouts=1 -ignore_crashes=1 -ignore_ooms=1 -timeout=10 \
            -rss_limit_mb=2048 -max_total_time="$seconds" -artifact_prefix="$findings/" 2>&1 |
            grep -E "^#|INFO: fuzzed|DONE|ERROR|SUMMARY" | tail -20 || true
        echo "fuzz.sh: $target: corpus $(count "$corpus") inputs," \
            "$(count "$findings") findings to triage"
    fi
    for input in "$findings"/*; do
        [ -e "$input" ] || continue
        verdict=
        case $(basename "$input") in
            # A loop must be libhdf5's: the release program must end with its read guard.
            timeout-*)
                guarded "$target" "$input" "(reading did not finish|the HDF5 library crashed)" &&
                    verdict=handled ;;
            *)
                said=$(report "$target" "$input")
                if ! grep -qE "ERROR: |FUZZ FINDING|runtime error" <<< "$said"; then
                    verdict="does not fail alone: fixed, or a state left by an earlier input"
                elif inside_hdf5 "$said" && guarded "$target" "$input"; then
                    verdict=handled
                fi ;;
        esac
        if [ "$verdict" = handled ]; then
            echo "fuzz.sh: $input: libhdf5 fails on it by itself (fault, overrun, loop or" \
                "allocation); the release program refuses it naming the file"
        else
            echo "fuzz.sh: FINDING $input${verdict:+ ($verdict)}"; status=1
        fi
    done
done
exit $status
