#!/usr/bin/env bash
# Runs every example in examples/ and examples/planar/ and `tumble modes` on every example in
# examples/modes/, and checks that each CSV they write (trajectories, events, modes) has the
# SHA-256 recorded in tests/golden/examples.sha256: a refactor of the engine must not change one
# byte of any answer.
# The digests were made by the commit named in that file's first line; to see what changed,
# run that commit's tumble on the example and diff the two CSVs.
#   scripts/check_examples_csv.sh TUMBLE_EXE           check (exit 1 on any difference)
#   scripts/check_examples_csv.sh TUMBLE_EXE --update  rewrite the digests (only for a change
#                                                      that is meant to alter answers; say so)
set -euo pipefail
exe=${1:?usage: scripts/check_examples_csv.sh TUMBLE_EXE [--update]}
mode=${2:-check}
root="$(cd "$(dirname "$0")/.." && pwd)"
digests="$root/tests/golden/examples.sha256"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

for scenario in "$root"/examples/*.yaml; do
  name=$(basename "$scenario" .yaml)
  mkdir -p "$out/$name"
  "$exe" run "$scenario" --out "$out/$name" >/dev/null
done
for scenario in "$root"/examples/planar/*.yaml; do
  name=planar/$(basename "$scenario" .yaml)
  mkdir -p "$out/$name"
  "$exe" run "$scenario" --out "$out/$name" >/dev/null
done
for scenario in "$root"/examples/modes/*.yaml; do
  name=modes/$(basename "$scenario" .yaml)
  mkdir -p "$out/$name"
  "$exe" modes "$scenario" --out "$out/$name" >/dev/null
done
(cd "$out" && find . -name '*.csv' | LC_ALL=C sort | xargs sha256sum) >"$out/now.sha256"

if [ "$mode" = "--update" ]; then
  { echo "# made by: $(git -C "$root" rev-parse --short HEAD)"; cat "$out/now.sha256"; } >"$digests"
  echo "wrote $digests"
  exit 0
fi
if diff <(grep -v '^#' "$digests") "$out/now.sha256" >"$out/diff"; then
  echo "every example's CSV is byte-identical ($(grep -vc '^#' "$digests") files)"
else
  echo "example CSVs that differ from tests/golden/examples.sha256 ($(head -1 "$digests")):" >&2
  grep '^[<>]' "$out/diff" | awk '{print $3}' | sort -u >&2
  exit 1
fi
