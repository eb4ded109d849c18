#!/usr/bin/env bash
# Sets up, builds and runs every test: formatting, the Release suite (with the Python module's
# pytest suite), the same suite under AddressSanitizer + UndefinedBehaviorSanitizer, the runs that
# share a model on threads under ThreadSanitizer (both built by clang), a minute of fuzzing the
# scenario and saved-state readers (on the sanitizer build's library), the main example end to
# end, the Python package as installed with half a minute of fuzzing its entry points, and the
# animation page and its videos (`tumble run --video`, checked with ffprobe) in headless Chromium.
# Each section is headed by the seconds since the start: CI's log shows where its minutes go.
set -euo pipefail
cd "$(dirname "$0")/.."
section() { echo "== $1 (at ${SECONDS} s)"; }
bash scripts/setup.sh

section "clang-format"
mapfile -t sources < <(git ls-files '*.cpp' '*.hpp' 2>/dev/null || find src app tests bench -name '*.[ch]pp')
clang-format --dry-run --Werror "${sources[@]}"

section "npm ci in web/ (the animation page's three.js, uPlot, esbuild; the browser test's playwright-core)"
(cd web && npm ci --no-audit --no-fund --loglevel=error)

section "Release build and tests"
bash scripts/build.sh release
ctest --test-dir build/release --output-on-failure -j "$(nproc)"

section "AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
bash scripts/build.sh sanitize
# Every test (but two that skip themselves there: a million parameters, whose size is what it
# checks, and a run out of memory under ulimit -v, which a sanitizer's shadow memory cannot take).
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build/sanitize --output-on-failure -j "$(nproc)"

section "ThreadSanitizer: runs of one shared model on two threads"
bash scripts/build.sh tsan tumble_thread_tests
TSAN_OPTIONS=halt_on_error=1 build/tsan/tests/tumble_thread_tests

section "Fuzzing the scenario and saved-state readers for a minute (libFuzzer)"
bash scripts/fuzz.sh 60

section "The main example"
out=$(mktemp -d)
build/release/tumble run examples/tumbling_prism.yaml --out "$out" --animate
test -s "$out/tumbling_prism.csv"
test -s "$out/tumbling_prism.html"

section "The Python package, installed as the README installs it (here under a scratch DESTDIR)"
stage=$(mktemp -d)
DESTDIR="$stage" cmake --install build/release --component python >/dev/null
site=$(find "$stage" -type d -name tumble -path '*site-packages*' | head -1)
PYTHONPATH="$(dirname "$site")" /usr/bin/python3 -m tumble run examples/tumbling_prism.yaml \
  --out "$stage/out" >/dev/null
PYTHONPATH="$(dirname "$site")" /usr/bin/python3 -c \
  "import tumble; r = tumble.load('examples/tumbling_prism.yaml').run(); assert len(r) == 401"
cmp "$stage/out/tumbling_prism.csv" "$out/tumbling_prism.csv"
section "Fuzzing the installed package's entry points for half a minute"
PYTHONPATH="$(dirname "$site")" /usr/bin/python3 fuzz/python_entry_points.py 30

section "The animation page and its videos in headless Chromium"
TUMBLE_EXE=build/release/tumble TUMBLE_ARTIFACTS=build/release/artifacts node --test tests/browser/
echo "== every test passed in ${SECONDS} s"
