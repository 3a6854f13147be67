// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the stripe editor's edit API (examples/Programs/Editor/editor_session.h), as the
// server calls it for POST /api/edit: the body is parsed as JSON and handed to Session::edit on a
// small mesh with boundary and a closed one. An edit either succeeds or throws Request_error /
// a JSON type error, and then the state (version, singularities, field, frequency and every corner
// value) must be exactly as before. A crash, a sanitizer report, another exception type (the
// server would answer 500) or a refused edit that changed the state is a finding.

#include "../../examples/Programs/Editor/editor_session.h"

#include <CGAL/Surface_design/mesh_generators.h>

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

namespace {

editor::Session& session(std::uint8_t which)
{
  static std::unique_ptr<editor::Session> sessions[2];
  auto& s = sessions[which % 2];
  if(!s)
  {
    editor::Mesh mesh;
    if(which % 2 == 0)
      CGAL::Surface_design::make_grid(mesh, 6, 6, 0.2, [](std::size_t i, std::size_t j) { return i == 2 && j == 3; });
    else
      CGAL::Surface_design::make_torus(mesh, 10, 6);
    s = std::make_unique<editor::Session>(std::move(mesh), which % 2 == 0 ? "holed grid" : "torus");
  }
  return *s;
}

/// The state without its timings.
std::string comparable(const std::string& state)
{
  const std::uint32_t length = std::uint32_t(std::uint8_t(state[0])) | std::uint32_t(std::uint8_t(state[1])) << 8 |
                               std::uint32_t(std::uint8_t(state[2])) << 16 | std::uint32_t(std::uint8_t(state[3])) << 24;
  editor::Json header = editor::Json::parse(state.substr(4, length));
  header.erase("timing");
  return header.dump() + state.substr(4 + length);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  editor::Session& s = session(data[0]);
  const std::string body(reinterpret_cast<const char*>(data + 1), size - 1);
  editor::Json request;
  try
  {
    request = editor::Json::parse(body);
  }
  catch(const editor::Json::exception&)
  {
    return 0; // the server answers 400 "malformed JSON"
  }
  if(request.is_object() && request.contains("op") && request["op"] == "load")
    return 0; // loading is the server's, not the session's
  const std::string before = comparable(s.state());
  try
  {
    s.edit(request);
  }
  catch(const editor::Request_error&)
  {
    if(comparable(s.state()) != before)
    {
      std::cerr << "a refused edit changed the state: " << body << std::endl;
      std::abort();
    }
  }
  catch(const editor::Json::exception&)
  {
    if(comparable(s.state()) != before)
    {
      std::cerr << "a refused edit (JSON type) changed the state: " << body << std::endl;
      std::abort();
    }
  }
  return 0;
}
