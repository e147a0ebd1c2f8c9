#!/usr/bin/env bash
# Builds the libFuzzer targets (the sanitize preset: Clang, ASan + UBSan) and runs each for SECONDS
# (default 180), or only the KINDs given (ply, off, obj, stl, gltf, glb, fbx, animated-gltf,
# animated-glb, png, jpg, tif, exr, psd, svg, project, cli-options, cli-process, png-writer:
# tests/fuzz/README.md).
# A crash, sanitizer report, uncaught exception, broken promise, hang (-timeout) or huge
# allocation (-rss_limit_mb) is a finding: its input goes to FUZZ_OUT/crashes/KIND/ and every
# finding is listed at the end (exit 1 when there is one).
#
# Usage: scripts/fuzz.sh [SECONDS] [KIND...]
# Environment:
#   FUZZ_OUT=build/fuzz        corpora (kept between runs), crashes and logs
#   FUZZ_JOBS=$(nproc)         targets fuzzed at the same time
#   FUZZ_RSS_MB=4096           memory limit per process (a drawing may decode to 4096 x 4096
#                              pixels from any file: about 700 MB at once under ASan)
#   FUZZ_MALLOC_MB=2048        the largest single allocation
#   FUZZ_TIMEOUT=10            seconds one input may take
#   FUZZ_FORK=N                N worker processes that go on after a finding (-fork -ignore_*),
#                              for long runs with known defects; default: stop at the first finding
#   FUZZ_SEED=N                libFuzzer's random seed (CI fixes it; default: random)
#   FUZZ_NO_BUILD=1            use the targets already built
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

seconds=${1:-180}
[ $# -gt 0 ] && shift
out=${FUZZ_OUT:-build/fuzz}
rss=${FUZZ_RSS_MB:-4096}
malloc=${FUZZ_MALLOC_MB:-2048}
timeout=${FUZZ_TIMEOUT:-10}
fork=${FUZZ_FORK:-0}
list=build/sanitize/fuzzers.txt

if [ -z "${FUZZ_NO_BUILD:-}" ]; then
  [ -f build/sanitize/CMakeCache.txt ] || nice cmake --preset sanitize
  nice cmake --build --preset fuzz
fi
[ -f "$list" ] || { echo "fuzz: $list is missing: configure the sanitize preset first" >&2; exit 2; }

mkdir -p "$out"
out=$(cd "$out" && pwd)
# Findings of this run are the files newer than this mark (older ones stay in crashes/ until removed).
mark=$out/.run-start
touch "$mark"
newFindings() { find "$@" -type f -newer "$mark" \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \); }
shared=$(cd .. && pwd)/shared/data

# Leaks are findings too; the symbolizer names the lines of a stack.
# intercept_tls_get_addr=0: see tests/lsan-suppressions.txt (LeakSanitizer's tracer crash).
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:check_initialization_order=1:intercept_tls_get_addr=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
# Upstream leaks only, each named in the file.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/lsan-suppressions.txt:print_suppressions=0}
export QT_QPA_PLATFORM=offscreen

# Targets run side by side, one per core (FUZZ_JOBS): each is one process fuzzing for SECONDS.
jobs_max=${FUZZ_JOBS:-$(nproc)}
rm -rf "$out/summary"
mkdir -p "$out/summary"
fuzzOne() {
  local kind=$1 binary=$2
  local corpus=$out/corpus/$kind crashes=$out/crashes/$kind work=$out/work/$kind
  mkdir -p "$corpus" "$crashes" "$work" "$out/logs"
  # Seeds: the committed corpus and the fuzzers' regressions, and (copied into the corpus) the
  # handcrafted regressions and the shared data's files under 50 kB with the kind's suffix.
  local seeds=() dir suffix=$kind
  for dir in tests/data/fuzz-corpus/$kind tests/data/fuzz-regressions/fuzzed/$kind; do
    [ -d "$dir" ] && seeds+=("$root/$dir")
  done
  [ "$kind" = project ] && suffix=celform
  case $kind in animated-*) suffix=${kind#animated-} ;; esac
  for dir in tests/data/fuzz-regressions "$shared"; do
    [ -d "$dir" ] && find "$dir" -path '*/fuzzed' -prune -o -type f -iname "*.$suffix" -size -50k \
      -exec cp -n {} "$corpus/" \;
  done
  local dict=tests/fuzz/dict/$kind.dict
  case $kind in glb | animated-gltf | animated-glb) dict=tests/fuzz/dict/gltf.dict ;; esac
  local flags=(-max_total_time="$seconds" -rss_limit_mb="$rss" -malloc_limit_mb="$malloc" -timeout="$timeout"
    -print_final_stats=1
    -artifact_prefix="$crashes/")
  [ -f "$dict" ] && flags+=(-dict="$root/$dict")
  [ -n "${FUZZ_SEED:-}" ] && flags+=(-seed="$FUZZ_SEED")
  [ "$fork" -gt 0 ] && flags+=(-fork="$fork" -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
  local log=$out/logs/$kind.log
  echo "fuzz: $kind for ${seconds}s (log: $log)"
  local status=0 runs found
  # Run from a folder of its own: libFuzzer writes fuzz-N.log files there in fork mode.
  (cd "$work" && nice "$binary" "${flags[@]}" "$corpus" "${seeds[@]}") >"$log" 2>&1 || status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' | tail -1 || true)
  [ -n "$runs" ] || runs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#' || true)
  found=$(newFindings "$crashes" | wc -l)
  printf '%-12s %12s executions  %3d findings  exit %d\n' "$kind" "${runs:-?}" "$found" "$status" \
    >"$out/summary/$kind"
  if [ "$status" -ne 0 ] && [ "$found" -eq 0 ]; then
    echo "fuzz: $kind stopped with status $status and no input saved; the end of its log:" >&2
    tail -30 "$log" >&2
  fi
}

kinds=()
while read -r kind binary; do
  if [ $# -gt 0 ] && ! printf '%s\n' "$@" | grep -qx -- "$kind"; then
    continue
  fi
  kinds+=("$kind")
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do
    wait -n || true
  done
  fuzzOne "$kind" "$binary" &
done <"$list"
wait
summary=()
for kind in "${kinds[@]}"; do
  summary+=("$(cat "$out/summary/$kind" 2>/dev/null || printf '%-12s %12s executions  %3s findings  exit %s' "$kind" '?' '?' 'lost')")
done

echo
echo "fuzz: per target (corpora in $out/corpus):"
printf '  %s\n' "${summary[@]}"
# A finding in a format the product reads in a child process (Assimp's meshes, OpenImageIO's
# TIFF, EXR and PSD: celform/model/io/import_process.h) is contained when the product, given the same bytes,
# refuses them in one line (exit 3) or loads them (exit 0) without dying itself: the defect is in the
# third-party reader and cannot take an open document along. Such findings are listed and kept in
# FUZZ_OUT/contained/ for an upstream report, and do not fail the run; every other finding does.
contained() {
  local kind=$1 file=$2 suffix=$1 celform=$root/build/sanitize/app/celform tmp status
  case $kind in
    stl | gltf | glb | fbx | tif | exr | psd) ;;
    *) return 1 ;;
  esac
  [ -x "$celform" ] || return 1
  tmp=$(mktemp -d)
  cp "$file" "$tmp/input.$suffix"
  status=0
  case $kind in
    stl | gltf | glb | fbx)
      "$celform" new "$tmp/input.$suffix" --out "$tmp/p.celform" >/dev/null 2>"$tmp/err" || status=$? ;;
    *)
      "$celform" new "$root/tests/data/fuzz-regressions/cli/tetrahedron.off" --drawing "$tmp/input.$suffix" \
        --out "$tmp/p.celform" >/dev/null 2>"$tmp/err" || status=$? ;;
  esac
  local lines
  lines=$(grep -vc '^warning:' "$tmp/err" || true)
  rm -rf "$tmp"
  [ "$status" -eq 0 ] || { [ "$status" -eq 3 ] && [ "$lines" -le 1 ]; }
}

findings=$(newFindings "$out/crashes" | sort)
failing=()
for finding in $findings; do
  kind=$(basename "$(dirname "$finding")")
  if contained "$kind" "$finding"; then
    mkdir -p "$out/contained/$kind"
    cp "$finding" "$out/contained/$kind/"
    echo "fuzz: contained (a third-party reader's defect, read in a child process): $finding"
  else
    failing+=("$finding")
  fi
done
if [ ${#failing[@]} -gt 0 ]; then
  echo
  echo "fuzz: findings (replay one with: build/sanitize/tests/fuzz/fuzz_KIND FILE):"
  printf '  %s\n' "${failing[@]}"
  exit 1
fi
# A target that stopped with an error and saved nothing is a failure; one whose findings were all
# contained is not.
failed=$(printf '%s\n' "${summary[@]}" | grep -v 'exit 0$' | grep -vc '[1-9][0-9]* findings' || true)
[ "$failed" -eq 0 ] || { echo "fuzz: $failed target(s) stopped with an error" >&2; exit 1; }
echo "fuzz: no findings"
