#!/usr/bin/env bash
# Every test: installs what is missing, checks the layout of the sources
# (.clang-format), lints the core headers (.clang-tidy) and checks that the
# CMake files list every source, builds Release and runs ctest (the
# CLI, MPI, report and CUDA tests) and pytest, runs the parsers' fuzz targets
# briefly, builds the consumer and pixel-sampling examples against an installed package, then
# builds everything with AddressSanitizer + UBSan and runs the gtests (one
# process per core) and the CLI tests there. The gtests are built once, in the
# sanitizer build: compiling them is most of the build time. What only Release
# compiles (the x86-64-v3/v4 clones of the L2 and star kernels) pytest checks
# against scipy and brute force. `ctest --preset release` alone still builds
# and runs the gtests.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test
jobs=$(nproc)

echo "== layout (.clang-format), lint of the core headers (.clang-tidy), CMake source lists"
bash scripts/check-format.sh
bash scripts/check-tidy.sh
bash scripts/check-sources.sh

echo "== release build"
bash scripts/build.sh release -DSTRATUM_UNIT_TESTS=OFF
echo "== ctest (release)"
ctest --preset release -j "$jobs"
echo "== pytest"
PYTHONPATH=build/release/python /usr/bin/python3 -m pytest -q python/tests

echo "== fuzz targets (docs/fuzzing.md): 2000 inputs each from the seed corpora"
bash scripts/fuzz.sh --runs 2000

echo "== install + find_package consumer"
rm -rf build/install build/consumer
cmake --install build/release --prefix build/install >/dev/null
cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
cmake --build build/consumer >/dev/null
build/consumer/consumer
echo "== the pixel-sampling example against the installed core headers alone (docs/pixel-sampling.md)"
rm -rf build/pixel_sampler_example
cmake -S examples/pixel_sampler -B build/pixel_sampler_example -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build/pixel_sampler_example >/dev/null
build/pixel_sampler_example/pixel_sampler_example 16
echo "== the installed CLI, run through PATH from another folder, loads the installed OpenImageIO module for a TIFF"
echo "   (and no module for a PNG, which libpng writes)"
(cd / && PATH="$OLDPWD/build/install/bin:$PATH" LD_DEBUG=files \
  stratum render --width 8 --height 8 --spp 1 -q -o "$OLDPWD/build/install/check.tif") 2>build/install/ld.log
grep -q "file=$PWD/build/install/lib.*/stratum/libstratum_oiio.so" build/install/ld.log
[ -s build/install/check.tif ]
(cd / && PATH="$OLDPWD/build/install/bin:$PATH" LD_DEBUG=files \
  stratum render --width 8 --height 8 --spp 1 -q -o "$OLDPWD/build/install/check.png") 2>build/install/ld.log
! grep -q "libstratum_oiio.so" build/install/ld.log
[ -s build/install/check.png ]

echo "== sanitizers (ASan + UBSan)"
bash scripts/build.sh asan
# The preset sets ASAN_OPTIONS: leak checks on, and intercept_tls_get_addr=0
# because GCC 12's LeakSanitizer misreads the dynamic TLS of dlopen'ed modules
# on glibc 2.36 (here OpenImageIO's, loaded on first image I/O) and its tracer
# crashes at exit (google/sanitizers#1322); static TLS is still scanned.
# The gtests as one process per core (gtest's shards) rather than one process
# per test as ctest runs them: each start of the sanitizer binary costs ~0.3 s,
# ~800 times. Then the CLI and other script tests (label not gtest) under ctest.
export ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 UBSAN_OPTIONS=print_stacktrace=1
pids=()
for ((shard = 0; shard < jobs; shard++)); do
  (cd build/asan/tests && GTEST_TOTAL_SHARDS=$jobs GTEST_SHARD_INDEX=$shard ../bin/stratum_tests --gtest_brief=1 \
    >"gtest_shard_$shard.log" 2>&1) &
  pids+=($!)
done
failed=0
for ((shard = 0; shard < jobs; shard++)); do
  if ! wait "${pids[$shard]}"; then
    echo "gtest shard $shard of $jobs FAILED:"; tail -60 "build/asan/tests/gtest_shard_$shard.log"; failed=1
  else
    tail -1 "build/asan/tests/gtest_shard_$shard.log"
  fi
done
[ "$failed" = 0 ]
ctest --preset asan -j "$jobs" -LE gtest
echo "all tests passed"
