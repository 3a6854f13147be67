// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the option parsing shared by every command-line program
// (examples/Programs/common/program_support.h). The input is split at NUL bytes into an argument vector;
// each argument goes through the parsers the programs use (numbers, integers in a range, pairs
// F:K, choices, output paths), and the whole vector through an Option_parser declaring every
// kind of option (values, repeated values, flags, an input file, outputs, a solver, a picture). A parser either returns a value that honours
// its promise (finite, within the range, a listed word) or throws Usage_error; anything else is a
// finding.

#include "../../examples/Programs/common/option_parser.h"
#include "../../examples/Programs/common/program_support.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

void expect(bool promise)
{
  if(!promise)
    std::abort(); // a parser returned a value that breaks its own promise
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::string> arguments(1, "fuzzed_program");
  std::string current;
  for(std::size_t i = 0; i < size; ++i)
  {
    if(data[i] == 0)
    {
      arguments.push_back(current);
      current.clear();
    }
    else
      current += char(data[i]);
  }
  arguments.push_back(current);
  std::vector<char*> argv;
  for(std::string& a : arguments)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  const int argc = int(arguments.size());

  try
  {
    std::string input, output, picture, up, solver;
    std::size_t repeats = 0, flags = 0;
    double x = 0.;
    program::Option_parser p;
    p.input(input)
      .value("--x", [&](const std::string& v) { x = program::parse_double(v, "--x", -10., 1e6); })
      .repeated("--again", [&](const std::string&) { ++repeats; })
      .flag("--flag", [&] { ++flags; })
      .output("--output", output, {".off", ".ply"})
      .solver(solver)
      .picture(picture, up)
      .parse(argc, argv.data());
    expect(!input.empty() && flags <= 1 && std::isfinite(x) && x >= -10. && x <= 1e6);
    expect(!p.given("--output") || output.size() > 4);
    expect(!p.given("--solver") || !solver.empty());
  }
  catch(const program::Usage_error&)
  {
  }
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[std::size_t(i)];
    try
    {
      const double x = program::parse_double(arg, "--x", -10., 1e6);
      expect(std::isfinite(x) && x >= -10. && x <= 1e6);
    }
    catch(const program::Usage_error&)
    {
    }
    try
    {
      const double x = program::parse_positive(arg, "--scale");
      expect(std::isfinite(x) && x > 0.);
    }
    catch(const program::Usage_error&)
    {
    }
    try
    {
      const long n = program::parse_integer(arg, "--n", -5, 1000);
      expect(n >= -5 && n <= 1000);
    }
    catch(const program::Usage_error&)
    {
    }
    try
    {
      const auto [f, k] = program::parse_pair(arg, "FACE:INDEX");
      expect(std::abs(f) <= 2147483647L && std::abs(k) <= 2147483647L);
    }
    catch(const program::Usage_error&)
    {
    }
    try
    {
      const std::string word = program::parse_choice(arg, "--solver", program::solver_names());
      expect(!word.empty());
    }
    catch(const program::Usage_error&)
    {
    }
    try
    {
      program::check_output_path(arg, "--output", {".off", ".ply"});
      expect(arg.size() > 4);
    }
    catch(const program::Usage_error&)
    {
    }
    try
    {
      int at = i;
      const std::string value = program::option_value(argc, argv.data(), at);
      expect(at == i + 1 && value == arguments[std::size_t(i + 1)]);
    }
    catch(const program::Usage_error&)
    {
    }
  }
  return 0;
}
