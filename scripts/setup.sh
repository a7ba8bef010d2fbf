#!/usr/bin/env bash
# Installs everything needed to build, test and benchmark VTP_geodesics on a fresh Debian 12
# machine: compiler, CMake, CGAL 5.5 (header-only) and its dependencies, GoogleTest, Python with
# matplotlib (benchmark plots, and the colour map of the tools, sampled at configure time), cairo, libpng and a
# font for the tools' pictures, Doxygen for the manual (`doc` target) and MathJax for its formulas (read offline from
# /usr/share/javascript/mathjax), and for vtp_distance_matrix: HDF5 (the
# serial C library: all MPI ranks write the one file through MPI-IO, see apps/vtp_distance_matrix/matrix_store.h),
# Open MPI, and h5py and SciPy to read its files back in the tests; for the Python module vtp_geodesics: the
# Python headers, pybind11, pytest, and setuptools, wheel, pip and venv for `pip install --no-build-isolation .`.
# Safe to run again (apt-get install is idempotent).
set -euo pipefail

PACKAGES=(
  build-essential
  cmake
  libcgal-dev
  libeigen3-dev
  libboost-dev
  libgmp-dev
  libmpfr-dev
  libgtest-dev
  python3
  python3-matplotlib
  pkg-config
  libpng-dev
  libcairo2-dev
  fonts-dejavu-core
  doxygen
  libjs-mathjax
  libhdf5-dev
  libopenmpi-dev
  openmpi-bin
  python3-h5py
  python3-numpy
  python3-scipy
  python3-dev
  pybind11-dev
  python3-pybind11
  python3-pytest
  python3-setuptools
  python3-wheel
  python3-pip
  python3-venv
)

if [ "$(id -u)" -eq 0 ]; then
  SUDO=()
elif command -v sudo >/dev/null 2>&1; then
  SUDO=(sudo)
else
  echo "setup.sh: run as root, or install sudo" >&2
  exit 1
fi

# Skip apt entirely when everything is already installed (e.g. a second run, or an offline CI image).
missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup.sh: all dependencies are already installed"
  exit 0
fi

echo "setup.sh: installing ${missing[*]}"
"${SUDO[@]}" apt-get update
"${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${PACKAGES[@]}"
