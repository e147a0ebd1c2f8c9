#!/usr/bin/env bash
# Re-renders the reference pictures of tests/app/test_render_baselines.cpp from the bundled sample.
# Look at every picture before committing new baselines (STYLE.md): a baseline is a promise.
# Usage: scripts/update-baselines.sh [path/to/celform]   (default: build/release/app/celform)
set -euo pipefail
cd "$(dirname "$0")/.."
celform=${1:-build/release/app/celform}
out=tests/data/baselines
for style in toon gooch comic lambert; do
  "$celform" render resources/samples/elephant-plain.celform --style "$style" --size 240x180 --out "$out/elephant_$style.png"
done
"$celform" render resources/samples/elephant-plain.celform --stereo anaglyph --size 240x180 --out "$out/elephant_anaglyph.png"
echo "wrote $out"
