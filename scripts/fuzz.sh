#!/usr/bin/env bash
# Fuzzes with clang's libFuzzer (AddressSanitizer and UndefinedBehaviorSanitizer on) for SECONDS
# (default 60): the scenario reader, model builder, linearisation and a bounded run of each valid
# scenario (tumble_scenario_fuzz, from the examples and tests/data/fuzz/), the checkpoint reader
# and the run it resumes (tumble_checkpoint_fuzz, from tests/data/fuzz-checkpoint/), and a
# record's and the events' expressions on an example (tumble_expression_fuzz, from
# tests/data/fuzz-expressions/).
#   scripts/fuzz.sh                 a minute: half on the scenarios, a quarter each on the states
#                                   and the expressions (scripts/test.sh runs this)
#   TARGET=scenario scripts/fuzz.sh 36000     ten hours on one target; the corpus grows in
#                                   build/fuzz/corpus (build/fuzz/checkpoint-corpus,
#                                   build/fuzz/expression-corpus) across runs
# An input that crashes, hangs past 1 s, leaks or throws what the target does not take as a
# refusal is written to build/fuzz/ (crash-*, timeout-*, leak-*) and the script fails; copy it
# into tests/data/fuzz/ (tests/data/fuzz-checkpoint/) as a regression test (FuzzRegressions reads
# every file there).
# SEED (default 1) fixes the mutations' order, so that CI's minute explores the same inputs on
# every run of the same code; give SEED=0 for a random order on long runs.
set -euo pipefail
seconds=${1:-60}
seed=${SEED:-1}
target=${TARGET:-all}
cd "$(dirname "$0")/.."
# On the sanitizer build's library (scripts/build.sh sanitize: clang, ASan and UBSan, -O1, line
# tables), which the tests' sanitizer run builds too; the corpus and findings are kept apart in
# build/fuzz/.
bash scripts/build.sh sanitize tumble_scenario_fuzz tumble_checkpoint_fuzz tumble_expression_fuzz
mkdir -p build/fuzz/corpus build/fuzz/checkpoint-corpus build/fuzz/expression-corpus
cp examples/*.yaml tests/data/fuzz/*.yaml build/fuzz/corpus/
cp tests/data/fuzz-checkpoint/* build/fuzz/checkpoint-corpus/
cp tests/data/fuzz-expressions/* build/fuzz/expression-corpus/

fuzz() {  # TARGET CORPUS SECONDS
  ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 \
    "build/sanitize/fuzz/tumble_$1_fuzz" "$2" -max_total_time="$3" -timeout=1 \
    -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix=build/fuzz/ \
    -seed="$seed"
}
case "$target" in
  all)
    fuzz scenario build/fuzz/corpus $((seconds / 2))
    fuzz checkpoint build/fuzz/checkpoint-corpus $((seconds / 4))
    fuzz expression build/fuzz/expression-corpus $((seconds - seconds / 2 - seconds / 4)) ;;
  scenario) fuzz scenario build/fuzz/corpus "$seconds" ;;
  checkpoint) fuzz checkpoint build/fuzz/checkpoint-corpus "$seconds" ;;
  expression) fuzz expression build/fuzz/expression-corpus "$seconds" ;;
  *) echo "TARGET is all, scenario, checkpoint or expression" >&2; exit 2 ;;
esac
