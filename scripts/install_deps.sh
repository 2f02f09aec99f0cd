#!/usr/bin/env bash
# Installs the Debian packages the project builds with, if any is missing.
# Usage: scripts/install_deps.sh [--profile]   (--profile: also perf and valgrind, for bench/profile.sh)
set -euo pipefail
packages=(build-essential cmake ninja-build libeigen3-dev libsuitesparse-dev libfmt-dev
          libyaml-cpp-dev libgtest-dev libbenchmark-dev libomp-dev python3 clang-format
          nlohmann-json3-dev libcli11-dev python3-matplotlib python3-vtk9 clang libclang-rt-14-dev
          python3-sfepy  # the FEM reference of paper 004 (scripts/fem/edge_notch_j.py, ctest fem_edge_notch_j)
          libtrilinos-sacado-dev libtrilinos-kokkos-dev libtrilinos-teuchos-dev  # Sacado: kernel_bench's forward-AD reference (Peridigm's AD); Debian's headers need Kokkos, Teuchos and mpi.h
          libopenblas0-pthread  # OpenBLAS: CHOLMOD's supernodal factorisation is 4x faster than with reference BLAS
          libceres-dev  # Ceres: the bounded Levenberg-Marquardt of pd calibrate (runtime/sensitivity/calibration.cpp)
          libgsl-dev  # GSL: the derivative-free simplex the calibration study compares with (bench/calibration_study.cpp)
          petsc-dev openmpi-bin libopenmpi-dev libxml2-dev zlib1g-dev)  # python3-vtk9: tests/output reads every output with VTK. petsc-dev (3.18, hypre) + OpenMPI: the distributed backend (runtime/petsc/, `mpirun -n N pd run`). libxml2-dev, zlib1g-dev: .vtu point clouds (domain.particles)
if [ "${1:-}" = "--profile" ]; then packages+=(linux-perf valgrind); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "Installing missing packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
