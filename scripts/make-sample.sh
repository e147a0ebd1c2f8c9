#!/usr/bin/env bash
# Rebuilds the bundled sample project from the shared data (CGAL elephant, CC0, with the Tux Paint
# side-view elephant drawing, GPL-2+, and the openclipart contour elephant, public domain).
# Usage: scripts/make-sample.sh [path/to/celform]   (default: build/release/app/celform)
set -euo pipefail
cd "$(dirname "$0")/.."
celform=${1:-build/release/app/celform}
data=../shared/data
"$celform" new "$data/meshes/cgal_elephant.off" \
  --drawing "$data/drawings/tuxpaint_elephant.png" \
  --drawing "$data/drawings/openclipart_contour_elephant.svg" \
  --out resources/samples/elephant.celform
rm -f resources/samples/elephant.celform.bak
echo "wrote resources/samples/elephant.celform"
