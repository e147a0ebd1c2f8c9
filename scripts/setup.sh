#!/usr/bin/env bash
# Installs the Debian 12 packages Celform needs (only the missing ones), then configures and
# builds the RelWithDebInfo preset with ccache. Safe to run again: it skips what is done.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake ninja-build ccache pkg-config
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n
  libqt6opengl6-dev qt6-svg-dev libgl-dev
  libvtk9-dev libcgal-dev libeigen3-dev
  libopenimageio-dev openimageio-tools
  libassimp-dev libtinyobjloader-dev libtinygltf-dev zlib1g-dev libdeflate-dev libopenexr-dev
  libbenchmark-dev glslang-tools
  libopencv-imgproc-dev
  xvfb xauth libgl1-mesa-dri
  # Fonts for SVG drawings with text, drawn without a display (fontconfig finds them; issue 27).
  fontconfig fonts-dejavu-core
  # A window manager for the scripted editor run on a 1366x768 screen (tests/app/with-window-manager.sh).
  openbox x11-utils
  # The farm templates' checks (test_cli_farm): Debian's Python reads the Open Job Description
  # template (YAML) and the OpenCue job spec (XML); Node runs the Flamenco job compiler.
  python3-yaml
  # The celform Python module (app/python/, docs/python.md): pybind11 and Debian's Python 3.11 headers to
  # build it, numpy for its arrays, pytest for its tests (tests/python).
  pybind11-dev python3-dev python3-numpy python3-pytest
  # test_crash_safety and test_large_pages trace the command line's system calls.
  strace
  # The sanitize preset and the fuzz targets: Clang with its sanitizer and libFuzzer runtimes
  # (LeakSanitizer needs libclang-rt-14-dev), and llvm-symbolizer for readable stacks.
  clang libclang-rt-14-dev llvm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all ${#packages[@]} Debian packages are installed"
fi

# The Khronos glTF Validator for test_export (an npm package, pinned). Node.js and npm come from
# Debian when the machine has no npm of its own (a NodeSource nodejs carries npm and conflicts
# with Debian's npm package, so npm is not in the list above).
validator_version=2.0.0-dev.3.10
if ! command -v npm >/dev/null 2>&1; then
  echo "setup: installing Node.js and npm for the glTF Validator"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends nodejs npm
fi
if grep -qs "\"version\": \"$validator_version\"" build/tools/node_modules/gltf-validator/package.json; then
  echo "setup: gltf-validator $validator_version is installed"
else
  npm install --prefix build/tools "gltf-validator@$validator_version" --no-audit --no-fund
fi
# TinyUSDZ's WebAssembly reader for test_export's USD files (pinned; tests/tools/read_usd.mjs
# loads it under Node; it brings three.js, which the shim does not use).
tinyusdz_version=0.9.0-rc10
if grep -qs "\"version\": \"$tinyusdz_version\"" build/tools/node_modules/tinyusdz/package.json; then
  echo "setup: tinyusdz $tinyusdz_version is installed"
else
  npm install --prefix build/tools "tinyusdz@$tinyusdz_version" --no-audit --no-fund
fi

# Paths below the checkout hash as relative ones: checkouts share ccache's entries.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
cmake --preset release
cmake --build --preset release
