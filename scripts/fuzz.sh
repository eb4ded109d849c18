#!/usr/bin/env bash
# Fuzzes the scenario reader and model builder with clang's libFuzzer (AddressSanitizer and
# UndefinedBehaviorSanitizer on) for SECONDS (default 60), from the examples as seed corpus.
#   scripts/fuzz.sh            a minute (scripts/test.sh runs this)
#   scripts/fuzz.sh 36000      ten hours; the corpus grows in build/fuzz/corpus across runs
# An input that crashes, hangs past 1 s, leaks or throws anything but a located ScenarioError is
# written to build/fuzz/ (crash-*, timeout-*, leak-*) and the script fails; copy it into
# tests/data/fuzz/ as a regression test (FuzzRegressions reads every file there).
# SEED (default 1) fixes the mutations' order, so that CI's minute explores the same inputs on
# every run of the same code; give SEED=0 for a random order on long runs.
set -euo pipefail
seconds=${1:-60}
seed=${SEED:-1}
cd "$(dirname "$0")/.."
# On the sanitizer build's library (scripts/build.sh sanitize: clang, ASan and UBSan, -O1, line
# tables), which the tests' sanitizer run builds too; the corpus and findings are kept apart in
# build/fuzz/.
bash scripts/build.sh sanitize tumble_scenario_fuzz
corpus=build/fuzz/corpus
mkdir -p "$corpus"
cp examples/*.yaml tests/data/fuzz/*.yaml "$corpus"/ 2>/dev/null || true
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
  build/sanitize/fuzz/tumble_scenario_fuzz "$corpus" -max_total_time="$seconds" -timeout=1 \
  -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix=build/fuzz/ \
  -seed="$seed"
