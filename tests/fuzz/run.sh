#!/usr/bin/env bash
# Builds the libFuzzer targets (the fuzz preset: clang, build/fuzz, RT_BUILD_FUZZERS) and runs each for
# SECONDS, one after another, starting from its corpus in tests/fuzz/corpus/<target>/.
#   tests/fuzz/run.sh SECONDS [TARGET...]
# New inputs go to build/fuzz/fuzz/work/<target>/ (the repository's corpus is only read); findings (crash-,
# leak-, timeout-, oom- files) to build/fuzz/fuzz/findings/. Prints one line per target with its executions;
# exits 1 when any target found something. Copy a finding into the target's corpus once it is fixed: `ctest --preset fuzz`
# replays every corpus file.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:?usage: tests/fuzz/run.sh SECONDS [TARGET...]}
shift
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(fuzz_scene_obj fuzz_mtl fuzz_scene_json fuzz_lesson fuzz_npy fuzz_matrix_market fuzz_homework)
export CCACHE_BASEDIR="$PWD"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target fuzzers -j "$(nproc)"
out=build/fuzz/fuzz
mkdir -p "$out/findings"
failed=0
for target in "${targets[@]}"; do
  mkdir -p "$out/work/$target"
  log="$out/$target.log"
  # -rss_limit_mb and -malloc_limit_mb: a huge allocation is a finding; -timeout: so is a hang (10 s).
  if ASAN_OPTIONS=detect_leaks=1 "$out/$target" -max_total_time="$seconds" -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -timeout=10 -print_final_stats=1 -artifact_prefix="$out/findings/$target-" \
    "$out/work/$target" "tests/fuzz/corpus/$target" >"$log" 2>&1; then
    status=ok
  else
    status=FOUND
    failed=1
  fi
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo "?")
  echo "$target: $status, $runs executions in ${seconds} s (log: $log)"
  # The log stays on the machine that ran it; the finding's cause goes where CI's output is read.
  [ "$status" = FOUND ] && grep -m 4 -E 'runtime error|ERROR:|SUMMARY|Test unit written' "$log" | sed 's/^/  /'
done
exit $failed
