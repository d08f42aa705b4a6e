#!/usr/bin/env bash
# The GPU check of sbanalyze (docs/gpu.md), in two halves:
#
#   scripts/gpu-check.sh --bundle   on a build machine (CUDA toolkit, no GPU needed): builds
#                                   build-cuda/ with SBPACK_WITH_CUDA=ON and packs sbanalyze,
#                                   gpu_tests and the shared libraries they need (ldd; not libc,
#                                   the C++ runtime or CUDA's own) into .gpu-bundle/ (< 64 MiB)
#   scripts/gpu-check.sh OUTDIR     on a GPU machine, from the repository root with .gpu-bundle/
#                                   beside it: the GPU tests, then the benchmark (CPU path on all
#                                   cores against --device cuda at 500^3, 1000^3, and 2000^3 pores
#                                   where memory allows), the log, gpu-bench.csv and gpu-bench.png
#                                   into OUTDIR, in under 8 minutes. On a machine without a GPU it
#                                   rehearses: the GPU tests report skipped, the benchmark's cuda
#                                   runs report the refusal.
set -euo pipefail
cd "$(dirname "$0")/.."
bundle=.gpu-bundle

if [ "${1:-}" = "--bundle" ]; then
    cmake -S . -B build-cuda -DCMAKE_BUILD_TYPE=Release -DSBPACK_WITH_CUDA=ON \
        -DSBPACK_BUILD_PYTHON=OFF -DSBPACK_BUILD_BENCH=OFF -DSBPACK_BUILD_GENERATOR=OFF >/dev/null
    cmake --build build-cuda -j"$(nproc)" --target sbanalyze gpu_tests
    rm -rf "$bundle" && mkdir -p "$bundle/stage/lib"
    cp build-cuda/analysis/sbanalyze build-cuda/tests/gpu_tests "$bundle/stage/"
    # The libraries the image lacks: everything ldd names but glibc, the C++ runtime (the GPU
    # image's are newer) and CUDA's (the image has the toolkit and the driver).
    skip='^(libc|libm|libpthread|libdl|librt|ld-linux-x86-64|libgcc_s|libstdc\+\+|libcuda|libcufft|libcudart)\.so'
    for binary in "$bundle"/stage/sbanalyze "$bundle"/stage/gpu_tests; do
        ldd "$binary" | awk '$3 ~ /^\// {print $3}'
    done | sort -u | while read -r lib; do
        basename "$lib" | grep -Eq "$skip" || cp -L "$lib" "$bundle/stage/lib/"
    done
    strip --strip-unneeded "$bundle"/stage/sbanalyze "$bundle"/stage/gpu_tests "$bundle"/stage/lib/*
    tar -C "$bundle/stage" -cJf "$bundle/sbanalyze-cuda.tar.xz" .
    rm -rf "$bundle/stage"
    size=$(stat -c %s "$bundle/sbanalyze-cuda.tar.xz")
    echo "gpu-check: $bundle/sbanalyze-cuda.tar.xz, $((size / 1024 / 1024)) MiB"
    [ "$size" -lt $((48 * 1024 * 1024)) ] || { echo "gpu-check: the bundle is over 48 MiB" >&2; exit 1; }
    exit 0
fi

out=${1:?usage: scripts/gpu-check.sh --bundle | OUTDIR}
mkdir -p "$out"
log="$out/gpu-check.log"
exec > >(tee "$log") 2>&1
[ -f "$bundle/sbanalyze-cuda.tar.xz" ] || { echo "gpu-check: no $bundle (run --bundle first)"; exit 1; }
run=$(mktemp -d)
tar -C "$run" -xJf "$bundle/sbanalyze-cuda.tar.xz"
# cuFFT from the image: ldconfig's, the toolkit's, or the wheel nvidia-cufft beside PyTorch.
wheels=$(python3 -c 'import nvidia, os; print(os.path.dirname(nvidia.__path__[0]))' 2>/dev/null || true)
cufft=""
for candidate in $(ldconfig -p 2>/dev/null | awk '/libcufft\.so\.12 /{print $NF}') \
    /usr/local/cuda/lib64/libcufft.so.12 /usr/local/cuda/targets/*/lib/libcufft.so.12 \
    ${wheels:+$wheels/nvidia/cu*/lib/libcufft.so.12 $wheels/nvidia/cufft/lib/libcufft.so.12}; do
    if [ -f "$candidate" ]; then cufft=$candidate; break; fi
done
export LD_LIBRARY_PATH="$run/lib${cufft:+:$(dirname "$cufft")}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export SBPACK_DATA_DIR="$PWD/data"
echo "gpu-check: $(date -u +%FT%TZ) on $(hostname), $(nproc) cores, cuFFT ${cufft:-not found}"
nvidia-smi --query-gpu=name,memory.total,driver_version --format=csv,noheader 2>/dev/null ||
    echo "gpu-check: no nvidia-smi (no GPU): a rehearsal"

echo "== GPU tests"
status=0
"$run/gpu_tests" --gtest_color=no || status=$?

echo "== benchmark: data/mrj-p1.5-5000.h5, voxels + chi + pores, CPU ($(nproc) threads) vs cuda"
echo "grid,device,wall_s,voxels_s,chi_s,pores_s,stages_s,phi_voxel,chi_peak,pore_mean_w,status" >"$out/gpu-bench.csv"
bench() { # M DEVICE COMPUTE LIMIT_S
    local m=$1 device=$2 compute=$3 json="$out/bench-$1-$2.json" start end rc=0
    start=$EPOCHREALTIME
    timeout "$4" "$run/sbanalyze" data/mrj-p1.5-5000.h5 --compute "$compute" --voxels "$m" \
        --pore-voxels "$m" --pores voxel --device "$device" --threads "$(nproc)" --fft-plan estimate \
        --fft-wisdom none --json "$json" || rc=$?
    end=$EPOCHREALTIME
    python3 scripts/gpu_bench_row.py "$json" "$m" "$device" "$(awk "BEGIN {print $end - $start}")" "$rc" \
        >>"$out/gpu-bench.csv"
}
for m in 500 1000; do
    bench "$m" cpu voxels,chi,pores 150
    bench "$m" cuda voxels,chi,pores 150
done
bench 2000 cuda pores 120
bench 2000 cpu pores 150
tr , "\t" <"$out/gpu-bench.csv"
python3 scripts/gpu_bench_row.py --figure "$out/gpu-bench.csv" "$out/gpu-bench.png" ||
    /usr/bin/python3 scripts/gpu_bench_row.py --figure "$out/gpu-bench.csv" "$out/gpu-bench.png" ||
    echo "gpu-check: no figure (no matplotlib)"
rm -rf "$run"
echo "gpu-check: GPU tests exit $status"
exit "$status"
