// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// surface_design_editor: an interactive stripe editor in the browser. A small HTTP server on the
// loopback address keeps one mesh and its Field_aligned_parameterizer (factored once); the page
// (web/, three.js from Debian's libjs-three) sends edits as JSON and draws the stripes from the
// per-corner coordinates it gets back. Run without arguments for the usage.
//
// A local server is reachable from every page the user's browser opens, so it trusts nothing but
// its own address: a request whose Host is not the editor's address (DNS rebinding) or whose
// Origin is another site is refused with 403; every /api/ request must carry the token printed at
// start (header X-Editor-Token, or ?token= for the PLY download link), as local notebook servers
// do; an edit must be sent as application/json (a cross-site form or text/plain POST needs no
// preflight, a JSON one does, and the server answers no preflight).

#include "editor_session.h"
#include "../common/configured_paths.h"
#include "../common/option_parser.h"

#include <httplib.h>

#include <cctype>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <sstream>


namespace {

const char* const usage =
  "usage: surface_design_editor MESH [options]\n"
  "Serves an interactive stripe editor for the triangle mesh MESH (OFF, OBJ, PLY) and prints its URL,\n"
  "which carries a token made at each start: the server answers only requests that present it, that\n"
  "address it by its own address, and that come from its own page (not from other sites).\n"
  "Open it in a browser: click faces to add singularities, drag them, annihilate pairs, change the\n"
  "field and the frequency; the stripes are re-solved without refactoring.\n"
  "options:\n"
  "  --port P            TCP port, 0 to 65535 (default 8080; 0: any free port)\n"
  "  --host ADDRESS      address to listen on (default 127.0.0.1, this machine only)\n"
  "  --data DIR          folder of meshes the page can load (default: the project's data/)\n"
  "  --web DIR           folder of the page (default: the sources' examples/Programs/Editor/web; both\n"
  "                      defaults come from configured_paths.txt beside the program)\n"
  "  --three DIR         three.js r111 or later as Debian's libjs-three installs it\n"
  "                      (default /usr/share/javascript/three)\n"
  "  --save-frames DIR   accept PNG frames from the page (POST /api/frame?name=N, for the tests and\n"
  "                      the manual's pictures) and write them to DIR\n";

struct Options
{
  std::string mesh, host = "127.0.0.1", data = program::configured_path("CGAL_SURFACE_DESIGN_DATA_DIR"),
                    web = program::configured_path("CGAL_SURFACE_DESIGN_EDITOR_WEB_DIR"),
                    three = "/usr/share/javascript/three", frames;
  int port = 8080;
};

Options parse(int argc, char** argv)
{
  Options o;
  auto text = [](std::string& into) { return [&into](const std::string& v) { into = v; }; };
  program::Option_parser()
    .input(o.mesh, "no mesh given")
    .value("--port", [&](const std::string& v) { o.port = int(program::parse_integer(v, "--port", 0, 65535)); })
    .value("--host", text(o.host))
    .value("--data", text(o.data))
    .value("--web", text(o.web))
    .value("--three", text(o.three))
    .value("--save-frames", text(o.frames))
    .parse(argc, argv);
  if(o.host.empty())
    throw program::Usage_error("--host needs an address");
  if(!o.frames.empty() && !std::filesystem::is_directory(o.frames))
    throw program::Usage_error("--save-frames " + o.frames + ": not a folder");
  if(!o.data.empty() && !std::filesystem::is_directory(o.data))
    throw program::Usage_error("--data " + o.data + ": not a folder");
  return o;
}

std::string read_file(const std::string& path, const std::string& what)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw program::Usage_error("cannot read " + path + " (" + what + ")");
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

void json_error(httplib::Response& res, int status, const std::string& message)
{
  res.status = status;
  res.set_content(editor::Json{{"error", message}}.dump(), "application/json");
}

constexpr std::size_t max_edit_bytes = 64 * 1024; // an edit is a few dozen bytes

/// 128 random bits in hex: the token of one start of the server.
std::string new_token()
{
  std::random_device device;
  std::string token;
  for(int i = 0; i < 4; ++i)
  {
    char word[9];
    std::snprintf(word, sizeof(word), "%08x", unsigned(device()) & 0xFFFFFFFFu);
    token += word;
  }
  return token;
}

/// Compares in a time that does not depend on where the strings differ.
bool same_secret(const std::string& given, const std::string& token)
{
  if(given.size() != token.size())
    return false;
  unsigned char difference = 0;
  for(std::size_t i = 0; i < token.size(); ++i)
    difference |= static_cast<unsigned char>(given[i] ^ token[i]);
  return difference == 0;
}

bool has_media_type(const httplib::Request& req, const std::string& type)
{
  const std::string value = req.get_header_value("Content-Type");
  const std::string media = value.substr(0, value.find(';'));
  return media.size() == type.size() && std::equal(media.begin(), media.end(), type.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

/// The address to print and the Host values under which this server may be addressed: the
/// loopback names and the address it listens on, each with the port.
struct Own_address
{
  std::string printed;
  std::set<std::string> hosts;

  Own_address(const std::string& host, int port)
  {
    const std::string p = ":" + std::to_string(port);
    hosts = {"127.0.0.1" + p, "localhost" + p, "[::1]" + p};
    printed = "127.0.0.1" + p;
    if(host != "0.0.0.0" && host != "::")
    {
      printed = (host.find(':') != std::string::npos ? "[" + host + "]" : host) + p;
      hosts.insert(printed);
    }
  }

  bool is_origin(const std::string& origin) const
  {
    return origin.rfind("http://", 0) == 0 && hosts.count(origin.substr(7)) > 0;
  }
};

} // namespace

int main(int argc, char** argv)
{
  return program::run_main("surface_design_editor", usage, argc, [&] {
    const Options o = parse(argc, argv);
    // the page and three.js, read once (a missing file is an error now, not a blank page later)
    const std::map<std::string, std::pair<std::string, const char*>> files{
      {"/", {read_file(o.web + "/index.html", "the editor's page; see --web"), "text/html"}},
      {"/editor.js", {read_file(o.web + "/editor.js", "the editor's script; see --web"), "text/javascript"}},
      {"/editor.css", {read_file(o.web + "/editor.css", "the editor's style; see --web"), "text/css"}},
      {"/three.min.js",
       {read_file(o.three + "/build/three.min.js", "three.js: apt-get install libjs-three, or see --three"),
        "text/javascript"}},
      {"/OrbitControls.js",
       {read_file(o.three + "/examples/js/controls/OrbitControls.js", "three.js' OrbitControls; see --three"),
        "text/javascript"}}};

    editor::Mesh_catalog catalog;
    if(!o.data.empty())
      catalog.add_folder(o.data);
    const std::string first = catalog.add_file(o.mesh);
    program::Stopwatch clock;
    std::mutex mutex; // one edit at a time
    long mesh_version = 0;
    auto session = std::make_unique<editor::Session>(o.mesh, first, mesh_version);
    std::cout << "loaded " << o.mesh << ": " << num_vertices(session->mesh()) << " vertices, "
              << session->number_of_faces() << " faces, factored and solved in " << clock.lap() << " ms" << std::endl;

    httplib::Server server;
    server.set_payload_max_length(o.frames.empty() ? max_edit_bytes : 32u << 20);
    const std::string token = new_token();
    std::optional<Own_address> own; // set once the port is known, before the first request
    server.set_pre_routing_handler([&](const httplib::Request& req, httplib::Response& res) {
      const std::string host = req.get_header_value("Host");
      if(!own->hosts.count(host))
      {
        json_error(res, 403, "Host '" + host + "' is not this editor's address (" + own->printed + ")");
        return httplib::Server::HandlerResponse::Handled;
      }
      if(req.has_header("Origin") && !own->is_origin(req.get_header_value("Origin")))
      {
        json_error(res, 403, "requests from the page of another site (Origin '" + req.get_header_value("Origin") +
                               "') are refused");
        return httplib::Server::HandlerResponse::Handled;
      }
      if(req.path.rfind("/api/", 0) == 0)
      {
        const std::string given =
          req.has_header("X-Editor-Token") ? req.get_header_value("X-Editor-Token") : req.get_param_value("token");
        if(!same_secret(given, token))
        {
          json_error(res, 403, std::string(given.empty() ? "no" : "a wrong") +
                                 " token: open the address with ?token= that surface_design_editor printed");
          return httplib::Server::HandlerResponse::Handled;
        }
      }
      return httplib::Server::HandlerResponse::Unhandled;
    });
    for(const auto& [path, file] : files)
      server.Get(path, [&file = file](const httplib::Request&, httplib::Response& res) {
        res.set_content(file.first, file.second);
      });
    server.Get("/api/meshes", [&](const httplib::Request&, httplib::Response& res) {
      std::lock_guard<std::mutex> lock(mutex);
      res.set_content(editor::Json{{"meshes", catalog.names()}, {"current", session->name()}}.dump(),
                      "application/json");
    });
    server.Get("/api/mesh", [&](const httplib::Request&, httplib::Response& res) {
      std::lock_guard<std::mutex> lock(mutex);
      res.set_content(session->mesh_json().dump(), "application/json");
    });
    server.Get("/api/state", [&](const httplib::Request&, httplib::Response& res) {
      std::lock_guard<std::mutex> lock(mutex);
      res.set_content(session->state(), "application/octet-stream");
    });
    server.Post("/api/edit", [&](const httplib::Request& req, httplib::Response& res) {
      const auto received = editor::Clock::now();
      if(!has_media_type(req, "application/json"))
        return json_error(res, 415, "an edit must be sent as Content-Type: application/json, not '" +
                                      req.get_header_value("Content-Type") + "'");
      if(req.body.size() > max_edit_bytes)
        return json_error(res, 413, "the request has " + std::to_string(req.body.size()) + " bytes; an edit has at most " +
                                      std::to_string(max_edit_bytes));
      editor::Json request;
      try
      {
        request = editor::Json::parse(req.body);
      }
      catch(const editor::Json::exception& e)
      {
        return json_error(res, 400, std::string("malformed JSON: ") + e.what());
      }
      std::lock_guard<std::mutex> lock(mutex);
      try
      {
        if(request.is_object() && request.contains("op") && request["op"] == "load")
        {
          if(!request.contains("name") || !request["name"].is_string())
            throw editor::Request_error("load: \"name\" must be a string (GET /api/meshes lists the meshes)");
          const std::string name = request["name"].get<std::string>();
          const std::string& path = catalog.path(name);
          std::unique_ptr<editor::Session> next;
          try
          {
            next = std::make_unique<editor::Session>(path, name, mesh_version + 1);
          }
          catch(const std::exception& e)
          {
            throw editor::Request_error("cannot edit " + name + ": " + e.what());
          }
          session = std::move(next);
          ++mesh_version;
          std::cout << "loaded " << name << " (" << session->number_of_faces() << " faces)" << std::endl;
          res.set_content(session->state(received), "application/octet-stream");
          return;
        }
        res.set_content(session->edit(request, received), "application/octet-stream");
      }
      catch(const editor::Request_error& e)
      {
        json_error(res, 400, e.what());
      }
      catch(const editor::Json::exception& e) // a member of the wrong JSON type
      {
        json_error(res, 400, std::string("invalid request: ") + e.what());
      }
    });
    server.Get("/api/export.ply", [&](const httplib::Request&, httplib::Response& res) {
      std::lock_guard<std::mutex> lock(mutex);
      res.set_header("Content-Disposition", "attachment; filename=\"stripes.ply\"");
      res.set_content(session->export_ply(), "application/octet-stream");
    });
    for(const std::string format : {"off", "obj"})
      server.Get("/api/export_quads." + format, [&, format](const httplib::Request&, httplib::Response& res) {
        std::lock_guard<std::mutex> lock(mutex);
        try
        {
          const std::string content = session->export_quads(format);
          res.set_header("Content-Disposition", "attachment; filename=\"quads." + format + "\"");
          res.set_content(content, "application/octet-stream");
        }
        catch(const editor::Request_error& e)
        {
          json_error(res, 409, e.what());
        }
      });
    server.Post("/api/frame", [&](const httplib::Request& req, httplib::Response& res) {
      if(o.frames.empty())
        return json_error(res, 404, "frames are accepted only when the server runs with --save-frames DIR");
      const std::string name = req.get_param_value("name");
      const bool valid = !name.empty() && name.size() <= 64 && std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
      });
      if(!valid)
        return json_error(res, 400, "frame name '" + name + "': use 1 to 64 letters, digits, '_' or '-'");
      if(!has_media_type(req, "image/png"))
        return json_error(res, 415, "a frame must be sent as Content-Type: image/png");
      if(req.body.size() < 8 || req.body.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        return json_error(res, 400, "a frame must be a PNG file");
      std::ofstream out(o.frames + "/" + name + ".png", std::ios::binary);
      out << req.body;
      if(!out)
        return json_error(res, 500, "cannot write " + o.frames + "/" + name + ".png");
      res.set_content("{}", "application/json");
    });
    server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
      if(res.body.empty())
        json_error(res, res.status, "HTTP " + std::to_string(res.status) + " for " + req.method + " " + req.path);
    });
    server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
      std::string message = "internal error";
      try
      {
        std::rethrow_exception(ep);
      }
      catch(const std::exception& e)
      {
        message += std::string(": ") + e.what();
      }
      catch(...)
      {
      }
      json_error(res, 500, message);
    });

    int port = o.port;
    if(port == 0)
      port = server.bind_to_any_port(o.host);
    else if(!server.bind_to_port(o.host, port))
      port = -1;
    if(port <= 0)
      throw std::runtime_error("cannot listen on " + o.host + ":" + std::to_string(o.port) +
                               " (in use, or not an address of this machine): try another --port");
    own.emplace(o.host, port);
    if(o.host != "127.0.0.1" && o.host != "localhost" && o.host != "::1")
      std::cout << "warning: listening on " << o.host << ", not only on this machine's loopback address" << std::endl;
    std::cout << "open http://" << own->printed << "/?token=" << token << " in a browser (Ctrl+C stops the server)"
              << std::endl;
    return server.listen_after_bind() ? 0 : 1;
  });
}
