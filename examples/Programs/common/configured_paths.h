// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Folders that the build knows (the bundled meshes, the shared meshes, the editor's page) without
// compiling them into the programs: a path in a -D flag differs between two clones of the
// repository, so that no compiler cache could share their objects. CMake writes
// `configured_paths.txt` (lines NAME=PATH) beside the programs; an environment variable NAME
// overrides a line.

#ifndef CGAL_SURFACE_DESIGN_CONFIGURED_PATHS_H
#define CGAL_SURFACE_DESIGN_CONFIGURED_PATHS_H

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace program {

/// The value of NAME: the environment variable if set and not empty, else its line in
/// configured_paths.txt beside the running program, else "".
inline std::string configured_path(const std::string& name)
{
  if(const char* env = std::getenv(name.c_str()); env != nullptr && *env != '\0')
    return env;
  std::error_code ec;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", ec);
  if(ec)
    return {};
  std::ifstream in(program.parent_path() / "configured_paths.txt");
  for(std::string line; std::getline(in, line);)
    if(line.size() > name.size() && line.compare(0, name.size(), name) == 0 && line[name.size()] == '=')
      return line.substr(name.size() + 1);
  return {};
}

} // namespace program

#endif // CGAL_SURFACE_DESIGN_CONFIGURED_PATHS_H
