#!/bin/sh
# The app with the museum solved at each size (make_large_scenes.py): display build, rotation frame time, pick,
# recolour and iteration step, memory (tests/app/scale_benchmark_test.cpp prints one Markdown row per size), and a
# screenshot of the window per size in OUTDIR. Needs Xvfb (xvfb-run) and the dev build (app_tests).
# Usage: scenes/tools/bench_app.sh OUTDIR "ELEMENTS ..."
# e.g.   scenes/tools/bench_app.sh out/app-bench "50000 250000 1000000"
set -eu
out=$1
sizes=$2
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
tests=${APP_TESTS:-$root/build/release/tests/app_tests}
mkdir -p "$out"
scenes=""
for n in $sizes; do
  scene=$out/museum-$n.obj
  [ -f "$scene" ] || python3 "$here/make_large_scenes.py" museum "$n" "$scene" >/dev/null
  scenes="$scenes $scene"
done
RT_APP_BENCH_SCENES="$scenes" RT_APP_BENCH_SCREENSHOTS="$out" \
  xvfb-run -a -s "-screen 0 1920x1080x24" "$tests" --gtest_also_run_disabled_tests \
  --gtest_filter='AppScaleBenchmark.*'
