#!/usr/bin/env bash
# Configures and builds tumble. Usage: scripts/build.sh [release|debug|sanitize|tsan] [TARGET...]
# The build lands in build/<kind>/; the tumble executable is build/<kind>/tumble.
set -euo pipefail
kind=${1:-release}
cd "$(dirname "$0")/.."
case "$kind" in
  release) flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  debug) flags=(-DCMAKE_BUILD_TYPE=Debug) ;;
  # The sanitizer builds are made without MPI: Open MPI's own allocations would be reported, and
  # they show that a build without MPI works (a sweep then runs in one process).
  # Nor do they build the benchmarks, whose timings under a sanitizer would mean nothing. They
  # are optimised at -O1 (the sanitizers' own advice: fast enough, and stack traces stay exact)
  # with line tables only (-g1: file and line in every report, at a fraction of full debug
  # information's compile time).
  # UBSan leaves out the four checks CMakeLists.txt names (and says why): with them Eigen's
  # kernels ran 10 to 20 times slower.
  # They are compiled by clang, which builds them in about half of GCC's time (GCC's Release build
  # holds the code to -Werror), and the sanitize build's library serves the libFuzzer target too
  # (scripts/fuzz.sh): one compile of it for both.
  sanitize) flags=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
                   "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DTUMBLE_SANITIZE=ON
                   -DTUMBLE_FUZZ=ON -DTUMBLE_MPI=OFF -DTUMBLE_BUILD_BENCH=OFF) ;;
  tsan) flags=(-DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo
               "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DTUMBLE_THREAD_SANITIZE=ON
               -DTUMBLE_MPI=OFF -DTUMBLE_BUILD_BENCH=OFF) ;;
  *) echo "usage: scripts/build.sh [release|debug|sanitize|tsan] [TARGET...]" >&2; exit 2 ;;
esac
cmake -S . -B "build/$kind" -G Ninja "${flags[@]}" >/dev/null
shift || true
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build "build/$kind" -j "$(nproc)" "${targets[@]}"
