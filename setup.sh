#!/usr/bin/env bash
# The two entry points of the README.
#   ./setup.sh app    install what is missing, build, open the app on the Cornell box lesson
#                     (no display: render the lesson's steps to out/ and say where they went)
#   ./setup.sh test   install what is missing, build with tests, run every test
set -euo pipefail
cd "$(dirname "$0")"
what=${1:-app}
./install-deps.sh
jobs=$(nproc)
# Paths relative to the checkout in ccache's keys, so that clones in other folders share the cache.
export CCACHE_BASEDIR="$PWD"
case "$what" in
  app)
    cmake --preset release >/dev/null
    cmake --build --preset release -j "$jobs"
    if [ -n "${DISPLAY:-}" ]; then
      exec build/release/bin/radiosity-textbook --lesson cornell-box
    fi
    mkdir -p out
    xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/release/bin/radiosity solve scenes/cornell-box.json \
      --max-edge 25 --smooth --image out/cornell-box.png --output out/cornell-box-B.csv
    xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/release/bin/radiosity lesson render cornell-box \
      --output out/lesson
    # The lesson's last step, where the light has bounced to convergence (its first step is, by design, a black
    # room around the light).
    xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" build/release/bin/radiosity-textbook --lesson cornell-box \
      --step 4 --screenshot out/app-cornell-box.png
    echo "No display: the solved Cornell box is out/cornell-box.png, the lesson's figures and page are in out/lesson/,"
    echo "and the app's window on the lesson's last step is out/app-cornell-box.png"
    ;;
  test)
    cmake --preset dev >/dev/null
    cmake --build --preset dev -j "$jobs"
    # The web edition: the core in WebAssembly and the browser tests' driver (puppeteer-core, which never
    # downloads a browser: the tests run Debian's chromium). RT_REQUIRE_WEB makes their absence a failure.
    cmake --preset wasm >/dev/null
    cmake --build --preset wasm -j "$jobs"
    (cd tests/browser && PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --silent)
    export RT_REQUIRE_WEB=1
    # Everything that renders needs an X server: run the whole suite under one Xvfb.
    xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" ctest --preset dev -j "$jobs"
    ;;
  *)
    echo "usage: ./setup.sh app|test" >&2
    exit 2
    ;;
esac
