// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: the option parsing shared by every command-line program
// (examples/common/example_support.h). The input is split at NUL bytes into an argument vector;
// each argument goes through the parsers the programs use (numbers, integers in a range, pairs
// F:K, choices, repeated options, output paths). A parser either returns a value that honours
// its promise (finite, within the range, a listed word) or throws Usage_error; anything else is a
// finding.

#include "../../examples/common/example_support.h"

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

  example::Once once;
  for(int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[std::size_t(i)];
    try
    {
      once.check(arg);
      const double x = example::parse_double(arg, "--x", -10., 1e6);
      expect(std::isfinite(x) && x >= -10. && x <= 1e6);
    }
    catch(const example::Usage_error&)
    {
    }
    try
    {
      const double x = example::parse_positive(arg, "--scale");
      expect(std::isfinite(x) && x > 0.);
    }
    catch(const example::Usage_error&)
    {
    }
    try
    {
      const long n = example::parse_integer(arg, "--n", -5, 1000);
      expect(n >= -5 && n <= 1000);
    }
    catch(const example::Usage_error&)
    {
    }
    try
    {
      const auto [f, k] = example::parse_pair(arg, "FACE:INDEX");
      expect(std::abs(f) <= 2147483647L && std::abs(k) <= 2147483647L);
    }
    catch(const example::Usage_error&)
    {
    }
    try
    {
      const std::string word = example::parse_choice(arg, "--solver", example::solver_names());
      expect(!word.empty());
    }
    catch(const example::Usage_error&)
    {
    }
    try
    {
      example::check_output_path(arg, "--output", {".off", ".ply"});
      expect(arg.size() > 4);
    }
    catch(const example::Usage_error&)
    {
    }
    try
    {
      int at = i;
      const std::string value = example::option_value(argc, argv.data(), at);
      expect(at == i + 1 && value == arguments[std::size_t(i + 1)]);
    }
    catch(const example::Usage_error&)
    {
    }
  }
  return 0;
}
