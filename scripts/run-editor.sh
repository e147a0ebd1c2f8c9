#!/usr/bin/env bash
# Quick start 1: set up, build, and open the editor on the bundled sample project.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec build/release/app/celform resources/samples/elephant.celform "$@"
