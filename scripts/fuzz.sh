#!/usr/bin/env bash
# Runs every libFuzzer target of a fuzz build (cmake --preset asan) for a fixed time, on seeds from
# the repository's own files and the inputs of past finds. A crash, leak, hang or huge allocation
# fails the run and leaves the input in BUILD/fuzz/artifacts/.
# Usage: scripts/fuzz.sh [BUILD_DIR (build-asan)] [SECONDS per target (20)] [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-asan}
seconds=${2:-20}
shift $(($# < 2 ? $# : 2))
# Seeds: folders (libFuzzer reads them recursively; a file of another format is just one more
# input the parser must refuse cleanly).
declare -A seeds=(
  [off]="tests/data/io tests/proximity/data tests/interact/data"
  [vect]="tests/data/io"
  [curve_text]="tests/data/io tests/knots/data"
  [scene]="scenes tests/data/io/bad tests/proximity/data"
  [scenario]="scenarios scenes"
  [session]="tests/data/io/sessions"
  [trajectory]="fuzz/seeds/trajectory"
  [knot_stroke]="tests/knots/data"
  [ribbon_stroke]="tests/interact/data"
)
targets=("$@")
((${#targets[@]})) || targets=(off vect curve_text scene scenario session trajectory knot_stroke ribbon_stroke)
mkdir -p "$build/fuzz/artifacts"
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
failed=()
# One target: its summary line goes to BUILD/fuzz/T.result, its status is the run's.
fuzz_one() {
  local t=$1 corpus="$build/fuzz/corpus/$1" log="$build/fuzz/$1.log"
  mkdir -p "$corpus"
  local dirs=(${seeds[$t]})
  [[ -d tests/data/fuzz_regressions/$t ]] && dirs+=("tests/data/fuzz_regressions/$t")
  # -timeout: one input may take this long (s); -rss_limit_mb / -malloc_limit_mb: a parser must
  # refuse a file that asks for more memory than this rather than allocate it.
  if "$build/fuzz/${t}_fuzz" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
      -print_final_stats=1 -artifact_prefix="$build/fuzz/artifacts/$t-" "$corpus" "${dirs[@]}" > "$log" 2>&1; then
    echo "fuzz.sh: $t: $(grep -m1 -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') runs in ${seconds} s, no crash; corpus $(ls "$corpus" | wc -l) inputs" > "$build/fuzz/$t.result"
  else
    { echo "fuzz.sh: $t FAILED (log: $log):"
      grep -m1 -A40 -E 'ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|libFuzzer)|runtime error|terminate called|==ERROR' "$log" || tail -40 "$log"
    } > "$build/fuzz/$t.result"
    return 1
  fi
}
for t in "${targets[@]}"; do
  [[ -n "${seeds[$t]:-}" ]] || { echo "fuzz.sh: unknown target '$t'" >&2; exit 1; }
done
# As many targets at once as there are cores (S4D_FUZZ_JOBS): each is one process, so two cores
# fuzz two targets in the time of one, each for its full time.
parallel=${S4D_FUZZ_JOBS:-$(nproc)}
declare -A pid_of=()
for t in "${targets[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  rm -f "$build/fuzz/$t.result"
  fuzz_one "$t" &
  pid_of[$t]=$!
done
for t in "${targets[@]}"; do
  wait "${pid_of[$t]}" || failed+=("$t")
  cat "$build/fuzz/$t.result" 2>/dev/null || echo "fuzz.sh: $t left no result"
done
if ((${#failed[@]})); then
  echo "fuzz.sh: ${#failed[@]} target(s) found a problem: ${failed[*]} (inputs in $build/fuzz/artifacts/)"
  exit 1
fi
echo "fuzz.sh: ${#targets[@]} target(s), ${seconds} s each: no crash, leak, hang or huge allocation"
