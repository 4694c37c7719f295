#!/usr/bin/env bash
# Runs glint's libFuzzer targets (docs/reliability.md, "Fuzzing") side by side, each in libFuzzer's
# fork mode with its own workers, and writes what they did:
#   OUT/stats.tsv                target, seconds, executions, coverage, corpus size, crash files
#   OUT/logs/<target>.log        libFuzzer's output
#   OUT/crashes/<target>/        inputs that crashed, broke a sanitizer check, ran out of memory or time
#                                (crash-*, oom-*, timeout-*, leak-*): each becomes a fix and a copy in
#                                fuzz/regressions/<target>/
#   OUT/corpus/<target>/         the inputs that found new coverage (seeded from fuzz/corpus/<target>/)
#
# usage: fuzz/run_fuzzers.sh [-b BUILD_DIR] [-t SECONDS] [-w WORKERS] [-o OUT] [TARGET...]
#   BUILD_DIR  where the fuzz_<target> programs are (default build-fuzz: cmake --preset fuzz && cmake --build --preset fuzz)
#   SECONDS    time per target (default 300), WORKERS processes per target (default 1), OUT (default $TMPDIR/glint-fuzz)
#   TARGET     obj_mtl gltf scene_json texture (default all four)
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-fuzz seconds=300 workers=1 out=${TMPDIR:-/tmp}/glint-fuzz
while getopts "b:t:w:o:" option; do
  case $option in
    b) build=$OPTARG ;; t) seconds=$OPTARG ;; w) workers=$OPTARG ;; o) out=$OPTARG ;;
    *) sed -n '2,14p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(obj_mtl gltf scene_json texture)

# A sanitizer report must stop the process (and keep the input); leaks are reported too.
export ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
mkdir -p "$out/logs"
for target in "${targets[@]}"; do
  program=$build/fuzz_$target
  [ -x "$program" ] || { echo "run_fuzzers: $program not built (cmake --build --preset fuzz)" >&2; exit 1; }
  mkdir -p "$out/corpus/$target" "$out/crashes/$target"
  seeds=(fuzz/corpus/$target)
  [ -d fuzz/regressions/$target ] && seeds+=(fuzz/regressions/$target)
  # fork mode: the parent hands out corpus slices to `workers` children and keeps going after a crash,
  # an out-of-memory (over 2 GB) or a timeout (an input taking over 10 s), saving each input.
  "$program" -fork="$workers" -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -dict=fuzz/dict/$target.dict -artifact_prefix="$out/crashes/$target/" -print_final_stats=1 \
    "$out/corpus/$target" "${seeds[@]}" >"$out/logs/$target.log" 2>&1 &
done
wait || true

printf 'target\tseconds\texecutions\tcoverage\tcorpus\tcrash_files\n' >"$out/stats.tsv"
for target in "${targets[@]}"; do
  # fork mode's status lines: "#<executions>: cov: <edges> ft: <features> corp: <inputs> ... time: <s>s ..."
  last=$(grep -E '^#[0-9]+: cov: ' "$out/logs/$target.log" | tail -1 || true)
  executions=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")
  coverage=$(sed -E 's/.* cov: ([0-9]+) .*/\1/' <<<"$last")
  time=$(sed -E 's/.* time: ([0-9]+)s.*/\1/' <<<"$last")
  crashes=$(find "$out/crashes/$target" -type f | wc -l)
  corpus=$(find "$out/corpus/$target" -type f | wc -l)
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$target" "${time:-?}" "${executions:-?}" "${coverage:-?}" "$corpus" "$crashes" >>"$out/stats.tsv"
done
column -t "$out/stats.tsv" 2>/dev/null || cat "$out/stats.tsv"
