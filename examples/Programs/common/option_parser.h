// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The command-line parser of the programs: each program declares its options with what each one
// does, and the parser reads the arguments strictly. Every refusal is a Usage_error (exit status
// 1, the message, no output file): an unknown option, an option given twice (unless declared
// repeatable), a missing value, a second input file, no input file. The values themselves are
// checked by the handlers, with the parse_* functions of program_support.h, before any
// computation.

#ifndef CGAL_SURFACE_DESIGN_PROGRAMS_OPTION_PARSER_H
#define CGAL_SURFACE_DESIGN_PROGRAMS_OPTION_PARSER_H

#include "program_support.h"

#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace program {

class Option_parser
{
public:
  using Value_handler = std::function<void(const std::string& value)>;
  using Flag_handler = std::function<void()>;

  /// `NAME VALUE`, at most once: `handle(VALUE)`.
  Option_parser& value(const std::string& name, Value_handler handle) { return add(name, std::move(handle), {}, false); }

  /// `NAME VALUE`, any number of times: `handle(VALUE)` for each, in order.
  Option_parser& repeated(const std::string& name, Value_handler handle)
  {
    return add(name, std::move(handle), {}, true);
  }

  /// `NAME` without a value, at most once.
  Option_parser& flag(const std::string& name, Flag_handler handle) { return add(name, {}, std::move(handle), false); }

  /// The one positional argument, the input file, into `path`; `missing` is the message when it is
  /// not given. Without this declaration every argument must be an option.
  Option_parser& input(std::string& path, std::string missing = "no input mesh")
  {
    m_input = &path;
    m_missing_input = std::move(missing);
    return *this;
  }

  /// `NAME FILE`, at most once: a file to write, with one of `extensions` (checked by
  /// check_output_path() before anything is computed).
  Option_parser& output(const std::string& name, std::string& path, std::vector<std::string> extensions)
  {
    return value(name, [&path, name, extensions](const std::string& v) { check_output_path(path = v, name, extensions); });
  }

  /// `--solver NAME`, one of solver_names().
  Option_parser& solver(std::string& name)
  {
    return value("--solver", [&name](const std::string& v) { name = parse_choice(v, "--solver", solver_names()); });
  }

  /// `--picture OUT.png` and `--up +X|-X|+Y|-Y|+Z|-Z` (the up direction of the picture).
  Option_parser& picture(std::string& path, std::string& up)
  {
    output("--picture", path, {".png"});
    return value("--up", [&up](const std::string& v) { up = parse_choice(v, "--up", {"+X", "-X", "+Y", "-Y", "+Z", "-Z"}); });
  }

  /// Reads argv[1], ..., argv[argc - 1], calling the handlers in order.
  void parse(int argc, char** argv)
  {
    for(int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      const auto option = m_options.find(a);
      if(option != m_options.end())
      {
        if(!option->second.repeatable && !m_given.insert(a).second)
          throw Usage_error(a + " is given more than once");
        m_given.insert(a);
        if(option->second.on_value)
          option->second.on_value(option_value(argc, argv, i));
        else
          option->second.on_flag();
      }
      else if(!a.empty() && a[0] == '-')
        throw Usage_error("unknown option " + a);
      else if(m_input == nullptr)
        throw Usage_error("unexpected argument " + a + " (this program reads no input file)");
      else if(!m_input->empty())
        throw Usage_error("more than one input file: " + *m_input + " and " + a);
      else if(a.empty())
        throw Usage_error("an empty input file name");
      else
        *m_input = a;
    }
    if(m_input != nullptr && m_input->empty())
      throw Usage_error(m_missing_input);
  }

  /// Whether the option `name` was given.
  bool given(const std::string& name) const { return m_given.count(name) > 0; }

private:
  struct Option
  {
    Value_handler on_value;
    Flag_handler on_flag;
    bool repeatable = false;
  };

  Option_parser& add(const std::string& name, Value_handler on_value, Flag_handler on_flag, bool repeatable)
  {
    if(!m_options.emplace(name, Option{std::move(on_value), std::move(on_flag), repeatable}).second)
      throw std::logic_error("option " + name + " is declared twice"); // a programming error
    return *this;
  }

  std::map<std::string, Option> m_options;
  std::set<std::string> m_given;
  std::string* m_input = nullptr;
  std::string m_missing_input;
};

} // namespace program

#endif // CGAL_SURFACE_DESIGN_PROGRAMS_OPTION_PARSER_H
