#!/usr/bin/env bash
# Instructions a physics step / stepping pairs query / stepping impact query (issues 4 and 5),
# counted by callgrind over the measured steps only: repeatable to the instruction, unlike the
# wall clock of this VM. Needs a build with benchmarks (scripts/test.sh makes build-test/).
# Usage: scripts/count-instructions.sh [physics|folded|pairs|impact ...] [-- --n 128 --steps 50]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${COUNT_BIN:-build-test/bench/count_instructions}
[[ -x $bin ]] || { echo "count-instructions: $bin not built (run scripts/test.sh)" >&2; exit 2; }
what=()
while (($#)) && [[ $1 != -- ]]; do what+=("$1"); shift; done
(($#)) && shift
((${#what[@]})) || what=(physics pairs impact)
steps=100
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do [[ ${args[i]} == --steps ]] && steps=${args[i + 1]}; done
dir=$(mktemp -d)
for w in "${what[@]}"; do
  out=$dir/$w
  valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$out.cg" \
    "$bin" "$w" "$@" 2>"$out.log" | grep -v 'wall clock' || true
  total=$(grep -o 'Collected : [0-9]*' "$out.log" | grep -o '[0-9]*$' || true)
  [[ -n $total ]] || { echo "count-instructions: no count for $w (see $out.log)" >&2; exit 1; }
  awk -v w="$w" -v t="$total" -v s="$steps" \
    'BEGIN { printf "%-8s %.3f M instructions a step (%d steps)\n", w, t / s / 1e6, s }'
  echo "  profile: callgrind_annotate $out.cg"
done
