#!/usr/bin/env bash
# Makes the sample's model-sheet drawings from the CGAL elephant (CC0) in the model's own pose:
#   resources/samples/drawings/elephant-sheet-side.png   from +z (the key "side", --view 0,0,1)
#   resources/samples/drawings/elephant-sheet-front.png  from the way the elephant faces (+x)
# scripts/model_sheet/model_sheet.cpp renders the silhouette (30-degree perspective, the figure
# filling 80 % of the height), warps it smoothly in 2D as a model sheet exaggerates (ears about
# 20 % larger, the trunk 13 % longer), inks it with a varying line width and prints each drawing's
# camera (eye, target, up, field of view) and the IoU of the drawing's outline against the
# unwarped silhouette. scripts/make-sample.sh builds the samples from them.
# Usage: scripts/make-model-sheet.sh [build-dir] [shared-data-dir]
#   (defaults: build/release and ../shared/data, as scripts/make-sample.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
data=${2:-../shared/data}
cmake --build "$build" --target model_sheet -j2 >/dev/null
"$build/scripts/model_sheet/model_sheet" "$data/meshes/cgal_elephant.off" resources/samples/drawings --long-side 1024
