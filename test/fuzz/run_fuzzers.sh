#!/usr/bin/env bash
# Fuzzes the programs' mesh reader, their option parsing and the stripe editor's edit API with
# libFuzzer under AddressSanitizer + UBSan (clang from Debian). Not part of CI: run it by hand.
#   bash test/fuzz/run_fuzzers.sh [SECONDS] [TARGET...]   (default: 600 s for each target)
# Targets: mesh_reader, option_parsing, editor_edit. The seeds are test/fuzz/corpus/TARGET; the
# growing corpora and any crash files go to build-fuzz/. Prints executions and crashes per target
# and exits 1 if any target found a crash.
source "$(dirname "${BASH_SOURCE[0]}")/../../scripts/common.sh"

install_packages "${BUILD_PACKAGES[@]}" nlohmann-json3-dev clang libclang-rt-dev

SECONDS_EACH="${1:-600}"
shift || true
TARGETS=("$@")
[ "${#TARGETS[@]}" -gt 0 ] || TARGETS=(mesh_reader option_parsing editor_edit)
OUT="$ROOT/build-fuzz"
mkdir -p "$OUT"
HERE="$ROOT/test/fuzz"

declare -A MAX_LEN=([mesh_reader]=65536 [option_parsing]=300000 [editor_edit]=4096)
declare -A EXTRA=([editor_edit]="-dict=$HERE/editor.dict")

status=0
summary=()
for target in "${TARGETS[@]}"; do
  [ -f "$HERE/fuzz_$target.cpp" ] || { echo "unknown target $target"; exit 2; }
  echo "== Building fuzz_$target"
  clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
    -I"$ROOT/include" -I/usr/include/eigen3 -DCGAL_EIGEN3_ENABLED \
    "$HERE/fuzz_$target.cpp" -o "$OUT/fuzz_$target" -lgmp -lmpfr -lpthread
  mkdir -p "$OUT/corpus_$target" "$OUT/crashes_$target"
  echo "== Fuzzing $target for $SECONDS_EACH s"
  log="$OUT/fuzz_$target.log"
  # shellcheck disable=SC2086
  ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    "$OUT/fuzz_$target" -max_total_time="$SECONDS_EACH" -max_len="${MAX_LEN[$target]}" -timeout=60 \
    -rss_limit_mb=4096 -print_final_stats=1 -artifact_prefix="$OUT/crashes_$target/" ${EXTRA[$target]:-} \
    "$OUT/corpus_$target" "$HERE/corpus/$target" > "$log" 2>&1
  rc=$?
  runs=$(grep -oE "stat::number_of_executed_units: *[0-9]+" "$log" | grep -oE "[0-9]+$" | tail -1)
  crashes=$(find "$OUT/crashes_$target" -type f ! -name 'slow-unit-*' | wc -l)
  slow=$(find "$OUT/crashes_$target" -type f -name 'slow-unit-*' | wc -l)
  summary+=("$target: ${runs:-?} executions in $SECONDS_EACH s, $crashes crash/timeout/out-of-memory file(s), $slow slow input(s), exit $rc")
  if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
    status=1
    echo "FINDING in $target (see $log and $OUT/crashes_$target):"
    grep -E "ERROR|SUMMARY|runtime error|changed the state" "$log" | head -5
  fi
done
echo "== Summary"
printf '%s\n' "${summary[@]}"
exit "$status"
