#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite.
#   bash scripts/test.sh              every test, the programs (command lines, editor server) and the
#                                     install check under AddressSanitizer + UBSan (-O0, the
#                                     long-running programs at -Og, see CMakeLists.txt; line tables
#                                     only (-g1); assertions on). This is what CI runs: one build.
#   bash scripts/test.sh --release    the same tests in a Release build (the test programs at -O1, see
#                                     test/CMakeLists.txt; the examples and programs at -O3), and the
#                                     benchmark harness's smoke run (at -O1 there: benchmark/CMakeLists.txt)
# Warnings are errors in both.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# poppler-utils: pdfinfo reads the PDF patterns back in the command-line checks; f3d, xvfb and
# xauth: the programs' --picture, which those checks run (as scripts/demo.sh installs them)
install_packages "${BUILD_PACKAGES[@]}" "${EDITOR_PACKAGES[@]}" python3 chromium poppler-utils f3d xvfb xauth

# every optional dependency is installed above, so none may be missing: the tests that compare
# CHOLMOD, METIS orderings and TBB loops with the rest must not pass by being skipped
REQUIRED=(-DCGAL_SURFACE_DESIGN_REQUIRE_CHOLMOD=ON -DCGAL_SURFACE_DESIGN_REQUIRE_METIS=ON
          -DCGAL_SURFACE_DESIGN_REQUIRE_TBB=ON -DCGAL_SURFACE_DESIGN_REQUIRE_EDITOR=ON)

case "${1:-}" in
  "" | --sanitize) # --sanitize: the former name of the default
    BUILD="$ROOT/build-sanitize"
    configure_and_build "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O0 -g1" \
      -DCGAL_SURFACE_DESIGN_SANITIZE=ON -DCGAL_SURFACE_DESIGN_WERROR=ON "${REQUIRED[@]}" \
      -DCGAL_SURFACE_DESIGN_BUILD_EXAMPLES=ON -DCGAL_SURFACE_DESIGN_BUILD_BENCHMARKS=OFF
    export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
    export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
    ;;
  --release)
    BUILD="$ROOT/build"
    # the benchmark harness is built for its smoke test only, at the test programs' -O1 (benchmark/CMakeLists.txt)
    configure_and_build "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCGAL_SURFACE_DESIGN_WERROR=ON "${REQUIRED[@]}" \
      -DCGAL_SURFACE_DESIGN_BENCHMARK_SMOKE_BUILD=ON
    ;;
  *)
    echo "usage: bash scripts/test.sh [--release]" >&2
    exit 1
    ;;
esac

echo "== Running the tests in $BUILD"
cd "$BUILD"
ctest --output-on-failure -j "$JOBS"
