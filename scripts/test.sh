#!/usr/bin/env bash
# Quick start 2: set up, build, and run the whole test suite under a virtual X server.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# UI tests need an X server with OpenGL (Mesa llvmpipe); xvfb-run gives one even on a display-less node.
xvfb-run -a -s "-screen 0 1600x1200x24" ctest --preset release
