// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Output of the benchmark harness: aligned text tables for people, a JSON file for scripts.
// The JSON is written by hand (no dependency); its layout is described in benchmark/README.md.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_REPORT_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_REPORT_H

#include "harness.h"
#include "machine_info.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace benchmark {

/// A text table whose columns are as wide as their widest cell; numeric columns right-aligned.
class Text_table
{
public:
  Text_table(std::vector<std::string> header, std::vector<bool> right_aligned)
    : m_header(std::move(header)), m_right(std::move(right_aligned))
  {}

  void add_row(std::vector<std::string> row) { m_rows.push_back(std::move(row)); }
  /// A blank line between groups of rows.
  void add_separator() { m_rows.emplace_back(); }

  void print(std::ostream& out) const
  {
    std::vector<std::size_t> width(m_header.size());
    for(std::size_t c = 0; c < m_header.size(); ++c)
      width[c] = m_header[c].size();
    for(const auto& row : m_rows)
      for(std::size_t c = 0; c < row.size() && c < width.size(); ++c)
        width[c] = (std::max)(width[c], row[c].size());
    print_row(out, m_header, width);
    std::size_t rule = 0;
    for(std::size_t w : width)
      rule += w + 2;
    out << std::string(rule > 2 ? rule - 2 : 0, '-') << '\n';
    for(const auto& row : m_rows)
    {
      if(row.empty())
        out << '\n';
      else
        print_row(out, row, width);
    }
  }

private:
  void print_row(std::ostream& out, const std::vector<std::string>& row,
                 const std::vector<std::size_t>& width) const
  {
    std::string line;
    for(std::size_t c = 0; c < row.size() && c < width.size(); ++c)
    {
      const std::string pad(width[c] - row[c].size(), ' ');
      line += (c > 0 ? "  " : "") + (m_right[c] ? pad + row[c] : row[c] + pad);
    }
    line.erase(line.find_last_not_of(' ') + 1);
    out << line << '\n';
  }

  std::vector<std::string> m_header;
  std::vector<bool> m_right;
  std::vector<std::vector<std::string>> m_rows;
};

/// Milliseconds with three decimals below one second, one above (enough for run-to-run noise).
inline std::string format_ms(double ms)
{
  return format_number(ms < 1000. ? "%.3f" : "%.1f", ms);
}

inline void print_results(std::ostream& out, const std::vector<Phase_result>& results)
{
  if(results.empty())
  {
    out << "no results\n";
    return;
  }
  Text_table table({"workload", "mesh", "|V|", "|F|", "solver", "phase", "median ms", "min ms",
                    "max ms"},
                   {false, false, true, true, false, false, true, true, true});
  for(std::size_t i = 0; i < results.size(); ++i)
  {
    const Phase_result& r = results[i];
    if(i > 0 && (results[i - 1].workload != r.workload || results[i - 1].mesh != r.mesh))
      table.add_separator();
    table.add_row({r.workload, r.mesh, std::to_string(r.vertices), std::to_string(r.faces),
                   r.solver, r.phase, format_ms(r.time.median_ms), format_ms(r.time.min_ms),
                   format_ms(r.time.max_ms)});
  }
  table.print(out);
}

/// The comparisons of kind `solver`: each solver against the baseline solver, per workload.
inline void print_solver_comparisons(std::ostream& out, const std::vector<Comparison>& comparisons)
{
  Text_table table({"workload", "mesh", "phase", "baseline", "contender", "baseline ms",
                    "contender ms", "ratio"},
                   {false, false, false, false, false, true, true, true});
  const Comparison* previous = nullptr;
  for(const Comparison& c : comparisons)
  {
    if(c.kind != Comparison::Kind::solver)
      continue;
    if(previous && (previous->contender_workload != c.contender_workload || previous->mesh != c.mesh))
      table.add_separator();
    table.add_row({c.contender_workload, c.mesh, c.phase, c.baseline_solver, c.contender_solver,
                   format_ms(c.baseline_ms), format_ms(c.contender_ms),
                   format_number("%.2fx", c.ratio)});
    previous = &c;
  }
  table.print(out);
}

/// The comparisons of kind `reference`: each workload against its reference workload, per mesh
/// and solver.
inline void print_reference_comparisons(std::ostream& out,
                                        const std::vector<Comparison>& comparisons)
{
  Text_table table({"workload", "reference", "mesh", "solver", "phase", "reference ms",
                    "workload ms", "ratio"},
                   {false, false, false, false, false, true, true, true});
  const Comparison* previous = nullptr;
  for(const Comparison& c : comparisons)
  {
    if(c.kind != Comparison::Kind::reference)
      continue;
    if(previous && (previous->contender_workload != c.contender_workload ||
                    previous->mesh != c.mesh || previous->contender_solver != c.contender_solver))
      table.add_separator();
    table.add_row({c.contender_workload, c.baseline_workload, c.mesh, c.contender_solver, c.phase,
                   format_ms(c.baseline_ms), format_ms(c.contender_ms),
                   format_number("%.2fx", c.ratio)});
    previous = &c;
  }
  table.print(out);
}

/// One line per (workload, mesh) that did not apply, with the solvers it was tried with.
inline void print_not_applicable(std::ostream& out, const std::vector<Not_applicable_result>& rows)
{
  Text_table table({"workload", "mesh", "solvers", "reason"}, {false, false, false, false});
  for(std::size_t i = 0; i < rows.size();)
  {
    std::string solvers = rows[i].solver;
    std::size_t j = i + 1;
    for(; j < rows.size() && rows[j].workload == rows[i].workload && rows[j].mesh == rows[i].mesh &&
          rows[j].reason == rows[i].reason;
        ++j)
      solvers += "," + rows[j].solver;
    table.add_row({rows[i].workload, rows[i].mesh, solvers, rows[i].reason});
    i = j;
  }
  table.print(out);
}

inline void print_machine(std::ostream& out, const Machine_info& m)
{
  out << "machine: " << m.cpu << ", " << m.cores << " cores; " << m.compiler << ", "
      << m.build_type << "; CGAL " << m.cgal_version << ", Eigen " << m.eigen_version
      << ", CHOLMOD " << (m.cholmod ? m.cholmod_version : "not available") << "\nBLAS loaded: "
      << m.blas << '\n';
}

// --- JSON

/// A JSON string literal: quotes, backslashes and control characters escaped (RFC 8259).
inline std::string json_string(const std::string& s)
{
  std::string out = "\"";
  for(char ch : s)
  {
    const unsigned char c = static_cast<unsigned char>(ch);
    switch(c)
    {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      default:
        if(c < 0x20)
        {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", unsigned(c));
          out += escaped;
        }
        else
          out += ch; // UTF-8 bytes pass through unchanged
    }
  }
  return out + "\"";
}

/// A JSON number; `null` for NaN and infinities, which JSON cannot represent.
inline std::string json_number(double x)
{
  return std::isfinite(x) ? format_number("%.9g", x) : std::string("null");
}

/// Writes every result to `path`; returns false if the file cannot be written.
inline bool write_json(const std::string& path, const Machine_info& machine,
                       const Timing_settings& settings, const std::string& command_line,
                       const std::vector<Phase_result>& results,
                       const std::vector<Comparison>& comparisons,
                       const std::vector<Check_result>& checks,
                       const std::vector<Not_applicable_result>& not_applicable)
{
  std::ofstream out(path);
  if(!out)
    return false;
  auto str = [](const std::string& s) { return json_string(s); };
  out << "{\n  \"machine\": {\n"
      << "    \"blas\": " << str(machine.blas) << ",\n"
      << "    \"cpu\": " << str(machine.cpu) << ",\n"
      << "    \"cores\": " << machine.cores << ",\n"
      << "    \"compiler\": " << str(machine.compiler) << ",\n"
      << "    \"build_type\": " << str(machine.build_type) << ",\n"
      << "    \"cgal_version\": " << str(machine.cgal_version) << ",\n"
      << "    \"eigen_version\": " << str(machine.eigen_version) << ",\n"
      << "    \"cholmod_available\": " << (machine.cholmod ? "true" : "false") << ",\n"
      << "    \"cholmod_version\": "
      << (machine.cholmod ? str(machine.cholmod_version) : std::string("null")) << ",\n"
      << "    \"date\": " << str(machine.date) << ",\n"
      << "    \"glibc_tunables\": " << str(machine.allocator_tunables) << "\n  },\n";
  out << "  \"settings\": {\"warmup\": " << settings.warmup << ", \"runs\": " << settings.runs
      << ", \"command\": " << str(command_line) << "},\n";

  out << "  \"results\": [";
  for(std::size_t i = 0; i < results.size(); ++i)
  {
    const Phase_result& r = results[i];
    out << (i ? "," : "") << "\n    {\"workload\": " << str(r.workload)
        << ", \"mesh\": " << str(r.mesh) << ", \"vertices\": " << r.vertices
        << ", \"faces\": " << r.faces << ", \"phase\": " << str(r.phase)
        << ", \"median_ms\": " << json_number(r.time.median_ms)
        << ", \"min_ms\": " << json_number(r.time.min_ms)
        << ", \"max_ms\": " << json_number(r.time.max_ms) << ", \"runs\": " << r.runs
        << ", \"solver\": " << str(r.solver) << "}";
  }
  out << (results.empty() ? "],\n" : "\n  ],\n");

  out << "  \"comparisons\": [";
  for(std::size_t i = 0; i < comparisons.size(); ++i)
  {
    const Comparison& c = comparisons[i];
    out << (i ? "," : "") << "\n    {\"kind\": " << str(c.kind_name())
        << ", \"mesh\": " << str(c.mesh) << ", \"phase\": " << str(c.phase)
        << ", \"baseline_workload\": " << str(c.baseline_workload)
        << ", \"baseline_solver\": " << str(c.baseline_solver)
        << ", \"contender_workload\": " << str(c.contender_workload)
        << ", \"contender_solver\": " << str(c.contender_solver)
        << ", \"baseline_median_ms\": " << json_number(c.baseline_ms)
        << ", \"contender_median_ms\": " << json_number(c.contender_ms)
        << ", \"ratio\": " << json_number(c.ratio) << "}";
  }
  out << (comparisons.empty() ? "],\n" : "\n  ],\n");

  out << "  \"checks\": [";
  for(std::size_t i = 0; i < checks.size(); ++i)
  {
    const Check_result& k = checks[i];
    out << (i ? "," : "") << "\n    {\"workload\": " << str(k.workload)
        << ", \"mesh\": " << str(k.mesh) << ", \"solver\": " << str(k.solver)
        << ", \"check\": " << str(k.what) << ", \"value\": " << json_number(k.value)
        << ", \"bound\": " << json_number(k.bound)
        << ", \"passed\": " << (k.passed() ? "true" : "false") << "}";
  }
  out << (checks.empty() ? "],\n" : "\n  ],\n");

  out << "  \"not_applicable\": [";
  for(std::size_t i = 0; i < not_applicable.size(); ++i)
  {
    const Not_applicable_result& n = not_applicable[i];
    out << (i ? "," : "") << "\n    {\"workload\": " << str(n.workload)
        << ", \"mesh\": " << str(n.mesh) << ", \"solver\": " << str(n.solver)
        << ", \"reason\": " << str(n.reason) << "}";
  }
  out << (not_applicable.empty() ? "]\n" : "\n  ]\n") << "}\n";
  out.close();
  return bool(out);
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_REPORT_H
