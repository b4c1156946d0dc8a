#!/usr/bin/env bash
# Ten minutes of random reader input on the app (tests/app/random_input_test.cpp), under Xvfb. Prints the
# seed first and every action; a failure is replayed with the same seed:
#   tests/app/random_input.sh [SECONDS [SEED]]
set -euo pipefail
cd "$(dirname "$0")/../.."
export RT_RANDOM_INPUT_SECONDS=${1:-600}
[ $# -ge 2 ] && export RT_RANDOM_INPUT_SEED=$2
exec xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/release/tests/app_tests \
  --gtest_filter='RandomInput.NoCrashNoHang'
