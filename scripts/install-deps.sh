#!/usr/bin/env bash
# Installs the Debian packages parasol needs, only those that are missing.
# Needs root (or sudo) only when something is missing.
set -euo pipefail
# libsuitesparse-dev: CHOLMOD (METHODE='MULT_FRONT'); libmumps-seq-dev: MUMPS (the default
# METHODE); libmumps-dev, libopenmpi-dev, openmpi-bin: the MPI build (-DPARASOL_MUMPS_MPI=ON)
# and its `mpi` test. python3-matplotlib: the plots of the benchmarks and doc/ (label bench).
packages=(gfortran cmake ninja-build liblapack-dev libblas-dev libopenblas-dev libmetis-dev
          python3 python3-numpy python3-meshio libsuitesparse-dev libmumps-seq-dev
          libmumps-dev libopenmpi-dev openmpi-bin python3-matplotlib
          libmedc-dev libmed-tools python3-h5py    # MED plug-in; mdump and h5py check MED files
          python3-mpmath                           # tests/extremes/slab_reference.py: exact
          python3-scipy                            # tests/ec8/ec8_reference.py: Bessel, quadrature
          valgrind)                                 # the valgrind.* tests (memcheck)
missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
    echo "install-deps: all Debian packages present"
    exit 0
fi
echo "install-deps: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
