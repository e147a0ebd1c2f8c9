#!/usr/bin/env bash
# Quick start 2: set up, build, and run the whole test suite under a virtual X server; then the
# hardening steps: the sanitize build (Clang, ASan + UBSan, no editor) and its tests, and every
# fuzz target for CELFORM_CI_FUZZ_SECONDS (default 6) each. Every step runs; the script fails if
# any did.
set -euo pipefail
cd "$(dirname "$0")/.."
# Paths below the checkout hash as relative ones, so two checkouts (a clone for CI beside a working
# copy) share ccache's entries.
export CCACHE_BASEDIR="$PWD"
setup_start=$SECONDS
scripts/setup.sh
echo "== setup and release build: $((SECONDS - setup_start)) s"

failed=()
step() {
  local name=$1
  shift
  local start=$SECONDS
  echo "== $name"
  "$@" || failed+=("$name")
  echo "== $name: $((SECONDS - start)) s"
}

# UI tests need an X server with OpenGL (Mesa llvmpipe); xvfb-run gives one even on a display-less node.
step "release tests" xvfb-run -a -s "-screen 0 1600x1200x24" ctest --preset release
step "sanitize build" bash -c 'nice cmake --preset sanitize && nice cmake --build --preset sanitize'
step "sanitize tests" ctest --preset sanitize
# A fixed seed and a fresh corpus: the same inputs on every run of the same code.
step "fuzz" env FUZZ_NO_BUILD=1 FUZZ_SEED=1 FUZZ_OUT=build/fuzz-ci FUZZ_FORK=0 \
  bash -c 'rm -rf build/fuzz-ci && exec scripts/fuzz.sh "${CELFORM_CI_FUZZ_SECONDS:-6}"'

if [ ${#failed[@]} -gt 0 ]; then
  echo "test: failed: ${failed[*]}" >&2
  exit 1
fi
echo "test: all steps passed"
