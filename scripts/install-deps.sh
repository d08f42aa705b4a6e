#!/usr/bin/env bash
# Installs the Debian packages sbpack needs, only those missing (apt-get update first).
#   install-deps.sh [--mpi]   --mpi: also OpenMPI and FFTW's MPI library (SBPACK_WITH_MPI), and
#                             Slurm and munge for the test against a real Slurm (tests/slurm)
set -euo pipefail
packages=(build-essential cmake pkg-config python3 libeigen3-dev libhdf5-dev libfftw3-dev
          libtbb-dev libopenvdb-dev libboost-iostreams-dev libimath-dev libgtest-dev
          libbenchmark-dev libcli11-dev nlohmann-json3-dev libfmt-dev clang-format clang-tidy git
          python3-numpy python3-h5py python3-matplotlib python3-dev pybind11-dev python3-pytest
          coinor-libclp-dev libspectra-dev)
if [[ "${1:-}" == "--mpi" ]]; then
  packages+=(openmpi-bin libopenmpi-dev libfftw3-mpi-dev shellcheck slurm-wlm munge)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
