#!/usr/bin/env bash
# ThreadSanitizer check of the parallel scheduling (PVTP / PAVTP) and of the threaded preprocessing.
#
# GCC's OpenMP runtime (libgomp) is not instrumented for ThreadSanitizer: its barriers are invisible
# to TSan, which then reports false races on any data handed from one parallel phase to the next.
# So this check builds the tests with Clang and LLVM's OpenMP runtime (Debian: clang, libomp-14-dev),
# whose ThreadSanitizer support (libarcher, loaded automatically) tells TSan about OpenMP's
# synchronisation. Real races are reported (checked with a deliberately racy program when this script
# was written), and any report makes the script fail.
#
# usage: bash scripts/tsan_check.sh [BUILD_DIR]   (default build-tsan)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build="${1:-build-tsan}"

need=()
command -v clang++ >/dev/null 2>&1 || need+=(clang)
dpkg-query -W -f='${Status}' libomp-14-dev 2>/dev/null | grep -q 'install ok installed' || need+=(libomp-14-dev)
if [ "${#need[@]}" -gt 0 ]; then
  SUDO=(); [ "$(id -u)" -eq 0 ] || SUDO=(sudo)
  "${SUDO[@]}" apt-get update
  DEBIAN_FRONTEND=noninteractive "${SUDO[@]}" apt-get install -y --no-install-recommends "${need[@]}"
fi

# -O1 -g1 (line tables): 43% less compile time than RelWithDebInfo's
# -O2 -g (27 s against 47 s of processor time for test/VTP_geodesics/stress_vtp.cpp), readable reports.
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" \
  -DVTP_GEODESICS_SANITIZE=thread \
  -DVTP_GEODESICS_BUILD_EXAMPLES=OFF -DVTP_GEODESICS_BUILD_BENCHMARK=OFF -DVTP_GEODESICS_BUILD_APPS=OFF
cmake --build "$build" -j"$(nproc)" --target vtp_geodesics_tests

export TSAN_OPTIONS="ignore_noninstrumented_modules=1 halt_on_error=1 exitcode=66"
export OMP_WAIT_POLICY=passive
tests="$(cd "$build" && pwd)/bin/vtp_geodesics_tests"
cd test/VTP_geodesics
"$tests" --gtest_filter='Parallel*:*Parallel*:Compute_each*:Multiple_sources*:Distance_limit*:Targets*:Preprocessing*:Initial_distances*:Farthest_point_sampling*'
echo "tsan_check.sh: no data race reported"
