#!/usr/bin/env bash
# Every test: installs what is missing, builds Release and runs ctest and
# pytest, builds the consumer example against an installed package, then
# builds the C++ tests with AddressSanitizer + UBSan and runs them.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test
jobs=$(nproc)

echo "== release build"
bash scripts/build.sh release
echo "== ctest (release)"
ctest --preset release -j "$jobs"
echo "== pytest"
PYTHONPATH=build/release/python /usr/bin/python3 -m pytest -q python/tests

echo "== install + find_package consumer"
rm -rf build/install build/consumer
cmake --install build/release --prefix build/install >/dev/null
cmake -S examples/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$PWD/build/install" >/dev/null
cmake --build build/consumer >/dev/null
build/consumer/consumer

echo "== sanitizers (ASan + UBSan)"
bash scripts/build.sh asan
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --preset asan -j "$jobs"
echo "all tests passed"
