// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the programs' mesh reader (examples/Programs/common/program_support.h, read_mesh) and
// the library's validation on whatever it accepts. The first byte picks the format (OFF, OBJ,
// PLY), the rest is the file. A refusal is an exception of the documented kinds; anything else
// (a crash, a sanitizer report, another exception type) is a finding.

#include "../../examples/Programs/common/program_support.h"

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/validation.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  static const char* const extensions[] = {".off", ".obj", ".ply"};
  static const std::string path =
    "/tmp/surface_design_fuzz_mesh_" + std::to_string(::getpid()) + extensions[0];
  const std::string file = path.substr(0, path.size() - 4) + extensions[data[0] % 3];
  {
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  try
  {
    namespace SDI = CGAL::Surface_design::internal;
    const program::Mesh mesh = program::read_mesh(file);
    const SDI::Mesh_indices<program::Mesh> idx(mesh);
    SDI::validate_mesh(idx, get(CGAL::vertex_point, mesh));
  }
  catch(const std::runtime_error&) // unreadable or not a polygon mesh
  {
  }
  catch(const CGAL::Surface_design::Invalid_mesh&) // not a valid triangle mesh for the library
  {
  }
  std::remove(file.c_str());
  return 0;
}
