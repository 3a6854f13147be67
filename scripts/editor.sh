#!/usr/bin/env bash
# Installs what is missing, builds the stripe editor, and serves it for the bundled Stanford bunny
# (8k faces) on port 8080: open the address it prints (with its token) in a browser; Ctrl+C stops it.
#   bash scripts/editor.sh                       the bunny on port 8080
#   bash scripts/editor.sh MESH [--port P] ...   another mesh or port (options: run the program
#                                                build/examples/surface_design_editor alone)
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

install_packages "${BUILD_PACKAGES[@]}" "${EDITOR_PACKAGES[@]}"

BUILD="$ROOT/build"
configure_and_build "$BUILD" -DCMAKE_BUILD_TYPE=Release -DCGAL_SURFACE_DESIGN_REQUIRE_EDITOR=ON -- surface_design_editor

if [ "$#" -eq 0 ]; then
  set -- "$ROOT/data/bunny_8k.off"
fi
exec "$BUILD/examples/surface_design_editor" "$@"
