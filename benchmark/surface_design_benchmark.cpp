// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// surface_design_benchmark: times the phases of named workloads on a list of meshes, with every
// available sparse solver side by side. See benchmark/README.md.

#include "harness.h"
#include "machine_info.h"
#include "mesh_sources.h"
#include "report.h"
#include "workload_laplacian.h"

#include <algorithm>
#include <cstddef>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace benchmark {

/// The workload table. A new algorithm plugs in with one function
/// `void f(const Mesh& mesh, const std::string& solver, Run& run)` (see workload_laplacian.h)
/// and one line here.
const std::vector<Workload>& workloads()
{
  static const std::vector<Workload> table{
    {"laplacian", "cotangent Laplacian L + eps M; phases assemble, factor, solve",
     &laplacian_workload},
  };
  return table;
}

const Workload* find_workload(const std::string& name)
{
  for(const Workload& w : workloads())
    if(name == w.name)
      return &w;
  return nullptr;
}

struct Options
{
  std::vector<const Workload*> workloads;
  std::vector<Mesh_source> meshes;
  std::vector<std::string> solvers;
  Timing_settings timing;
  std::string json = "benchmark_results.json";
  bool list = false;
};

const char* const usage =
  "usage: surface_design_benchmark [--workload NAME]... [--mesh SOURCE]... [--preset NAME]...\n"
  "                                [--solver S] [--warmup W] [--runs R] [--json FILE] [--list]\n"
  "\n"
  "  --workload NAME  workload to run (repeatable; default: all workloads)\n"
  "  --mesh SOURCE    bundled:NAME  file of the project's data/ folder\n"
  "                   shared:NAME   file of the shared mesh folder (.off.gz allowed; skipped when\n"
  "                                 absent; env CGAL_SURFACE_DESIGN_SHARED_MESH_DIR overrides it)\n"
  "                   sphere:F      generated sphere of about F faces (F may end in k or M)\n"
  "                   torus:F       generated torus of about F faces\n"
  "                   (repeatable; default: preset quick)\n"
  "  --preset NAME    a named list of meshes (repeatable; see --list)\n"
  "  --solver S       ldlt, cholmod, a comma-separated list, or all (default: all); the first\n"
  "                   is the baseline of the comparisons\n"
  "  --warmup W       unmeasured runs first (default 1)\n"
  "  --runs R         measured runs (default 5)\n"
  "  --json FILE      where to write the results (default benchmark_results.json)\n"
  "  --list           list the workloads, presets and solvers, and exit\n";

void print_list(std::ostream& out)
{
  out << "workloads:\n";
  for(const Workload& w : workloads())
    out << "  " << w.name << "  " << w.description << '\n';
  out << "presets:\n";
  for(const Preset& p : presets())
  {
    out << "  " << p.name << "  " << p.description << "\n     ";
    for(const char* s : p.sources)
      out << ' ' << s;
    out << '\n';
  }
  out << "solvers in this build:";
  for(const std::string& s : compiled_solvers())
    out << ' ' << s;
#if !defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  out << "  (cholmod unavailable: built without CHOLMOD)";
#endif
  out << '\n';
}

bool parse_count(const std::string& text, int lowest, int& value)
{
  if(text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoi(text);
  return value >= lowest;
}

/// Fills `solvers` from the value of --solver; cholmod without CHOLMOD is reported and dropped.
bool parse_solvers(const std::string& text, std::vector<std::string>& solvers, std::string& error)
{
  solvers.clear();
  std::vector<std::string> requested;
  if(text == "all")
    requested = {"ldlt", "cholmod"};
  else
    for(std::size_t start = 0; start <= text.size();)
    {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      requested.push_back(text.substr(start, comma - start));
      start = comma + 1;
    }
  for(const std::string& s : requested)
  {
    if(s != "ldlt" && s != "cholmod")
    {
      error = "unknown solver \"" + s + "\" (expected ldlt, cholmod or all)";
      return false;
    }
    const auto& compiled = compiled_solvers();
    if(std::find(compiled.begin(), compiled.end(), s) == compiled.end())
      std::cout << "solver " << s << ": unavailable (this build has no CHOLMOD: "
                << "CGAL_SURFACE_DESIGN_HAS_CHOLMOD is not defined)\n";
    else if(std::find(solvers.begin(), solvers.end(), s) == solvers.end())
      solvers.push_back(s);
  }
  if(solvers.empty())
  {
    error = "no available solver selected";
    return false;
  }
  return true;
}

/// Parses the command line; returns -1 to go on, otherwise the exit code.
int parse_options(int argc, char** argv, Options& options)
{
  auto fail = [](const std::string& message) {
    std::cerr << "surface_design_benchmark: " << message << "\n\n" << usage;
    return 2;
  };
  bool solver_given = false;
  for(int i = 1; i < argc; ++i)
  {
    static const std::vector<std::string> value_options{
      "--workload", "--mesh", "--preset", "--solver", "--warmup", "--runs", "--json"};
    std::string option = argv[i], value;
    const std::size_t equal =
      option.compare(0, 2, "--") == 0 ? option.find('=') : std::string::npos;
    const bool inline_value = equal != std::string::npos;
    if(inline_value)
    {
      value = option.substr(equal + 1);
      option.erase(equal);
    }
    const bool takes_value =
      std::find(value_options.begin(), value_options.end(), option) != value_options.end();
    if(!takes_value && option != "--list" && option != "--help" && option != "-h")
      return fail(std::string("unknown option ") + argv[i]);
    if(takes_value && !inline_value)
    {
      if(i + 1 >= argc)
        return fail("option " + option + " needs a value");
      value = argv[++i];
    }
    if(!takes_value && inline_value)
      return fail("option " + option + " takes no value");

    std::string error;
    if(option == "--help" || option == "-h")
    {
      std::cout << usage;
      return 0;
    }
    else if(option == "--list")
      options.list = true;
    else if(option == "--workload")
    {
      const Workload* w = find_workload(value);
      if(!w)
        return fail("unknown workload \"" + value + "\" (see --list)");
      auto& chosen = options.workloads;
      if(std::find(chosen.begin(), chosen.end(), w) == chosen.end())
        chosen.push_back(w);
    }
    else if(option == "--mesh")
    {
      Mesh_source source;
      if(!parse_mesh_source(value, source, error))
        return fail(error);
      options.meshes.push_back(source);
    }
    else if(option == "--preset")
    {
      const Preset* p = find_preset(value);
      if(!p)
        return fail("unknown preset \"" + value + "\" (see --list)");
      for(const char* spec : p->sources)
      {
        Mesh_source source;
        parse_mesh_source(spec, source, error);
        options.meshes.push_back(source);
      }
    }
    else if(option == "--solver")
    {
      if(!parse_solvers(value, options.solvers, error))
        return fail(error);
      solver_given = true;
    }
    else if(option == "--warmup")
    {
      if(!parse_count(value, 0, options.timing.warmup))
        return fail("--warmup needs an integer >= 0");
    }
    else if(option == "--runs")
    {
      if(!parse_count(value, 1, options.timing.runs))
        return fail("--runs needs an integer >= 1");
    }
    else if(option == "--json")
    {
      if(value.empty())
        return fail("--json needs a file name");
      options.json = value;
    }
  }

  if(options.workloads.empty())
    for(const Workload& w : workloads())
      options.workloads.push_back(&w);
  if(options.meshes.empty())
    for(const char* spec : find_preset("quick")->sources)
    {
      Mesh_source source;
      std::string error;
      parse_mesh_source(spec, source, error);
      options.meshes.push_back(source);
    }
  if(!solver_given)
  {
    std::string error;
    parse_solvers("all", options.solvers, error);
  }
  return -1;
}

int run_benchmark(int argc, char** argv)
{
  Options options;
  const int parsed = parse_options(argc, argv, options);
  if(parsed >= 0)
    return parsed;
  if(options.list)
  {
    print_list(std::cout);
    return 0;
  }
  std::string command_line = "surface_design_benchmark";
  for(int i = 1; i < argc; ++i)
    command_line += std::string(" ") + argv[i];

  int exit_code = 0;
  std::vector<Phase_result> results;
  std::vector<Check_result> checks;
  for(const Mesh_source& source : options.meshes)
  {
    Mesh mesh;
    std::string message;
    const Clock::time_point start = Clock::now();
    const Load_status status = load_mesh(source, mesh, message);
    if(status == Load_status::skipped)
    {
      std::cout << message << std::endl;
      continue;
    }
    if(status == Load_status::failed)
    {
      std::cerr << "ERROR: " << message << std::endl;
      exit_code = 1;
      continue;
    }
    std::cout << "mesh " << source.spec << ": " << num_vertices(mesh) << " vertices, "
              << num_faces(mesh) << " faces (loaded in "
              << format_number("%.2f", std::chrono::duration<double>(Clock::now() - start).count())
              << " s)" << std::endl;
    for(const Workload* w : options.workloads)
    {
      Measurement m = measure(*w, mesh, source.spec, options.solvers, options.timing, std::cout);
      results.insert(results.end(), m.results.begin(), m.results.end());
      checks.insert(checks.end(), m.checks.begin(), m.checks.end());
      if(m.failures > 0)
        exit_code = 1;
    }
  }

  const Machine_info machine = machine_info();
  const std::vector<Comparison> comparisons = compare_contenders(results);
  std::cout << '\n';
  print_machine(std::cout, machine);
  std::cout << '\n';
  print_results(std::cout, results);
  if(!comparisons.empty())
  {
    std::cout << "\nratio = baseline median / contender median"
              << " (above 1: the contender is faster)\n";
    print_comparisons(std::cout, comparisons);
  }
  const std::size_t failed_checks = std::size_t(
    std::count_if(checks.begin(), checks.end(), [](const Check_result& k) { return !k.passed(); }));
  if(failed_checks > 0)
    std::cout << "\nWARNING: " << failed_checks << " of " << checks.size()
              << " sanity checks failed (see above)\n";

  if(write_json(options.json, machine, options.timing, command_line, results, comparisons, checks))
    std::cout << "\nresults written to " << options.json << std::endl;
  else
  {
    std::cerr << "ERROR: cannot write " << options.json << std::endl;
    exit_code = 1;
  }
  return exit_code;
}

} // namespace benchmark

int main(int argc, char** argv)
{
  try
  {
    return benchmark::run_benchmark(argc, argv);
  }
  catch(const std::exception& e)
  {
    std::cerr << "surface_design_benchmark: " << e.what() << std::endl;
    return 1;
  }
}
