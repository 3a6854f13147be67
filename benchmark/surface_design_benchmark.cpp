// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// surface_design_benchmark: times the phases of named workloads on a list of meshes, with every
// available sparse solver side by side. See benchmark/README.md.

#include "harness.h"
#include "machine_info.h"
#include "mesh_sources.h"
#include "report.h"
#include "workload_factorization.h"
#include "workload_laplacian.h"
#include "workload_stripes.h"
#include "workload_direction_fields.h"
#include "workload_embedding.h"
#include "workload_developability.h"
#include "workload_flattening.h"
#include "workload_harmonic_quad.h"
#ifdef SURFACE_DESIGN_BENCHMARK_HAS_EDITOR
#include "workload_editor.h"
#endif

#include <algorithm>
#include <cstddef>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace benchmark {

/// The workload table. A new algorithm plugs in with one function
/// `void f(const Mesh& mesh, const std::string& solver, Run& run)` (see workload_laplacian.h)
/// and one line here; a fifth field names a reference workload it is compared with.
const std::vector<Workload>& workloads()
{
  static const std::vector<Workload> table{
    {"laplacian", "cotangent Laplacian L + eps M; phases assemble, factor, solve",
     &laplacian_workload},
    {"factorization", "first solve of L + eps M in phases ordering, symbolic, numeric, solve; fill and flops "
     "(ldlt: AMD, ldlt-nd: nested dissection, supernodal: the library's supernodal Cholesky with it, default: the same "
     "with AMD below 20k unknowns, ldlt-metis: METIS, cholmod: supernodal with nested dissection)",
     &factorization_workload},
    {"stripes",
     "field-aligned stripes, vertex space (Field_aligned_parameterizer); phases factor, field, "
     "solve, resolve, full = factor + field + solve",
     &stripes_workload, Solver_use::compared, "stripes_face_space"},
    {"stripes_face_space",
     "the same stripes by the paper's face-space solver (positive cotangent weights only); "
     "phases factor, field, solve, resolve, full",
     &stripes_face_space_workload},
    {"line_field_stripes",
     "smoothest line field, then the branched stripes along it (Branched_stripe_parameterizer); phases "
     "field, stripes, full, automatic, edit",
     &line_field_stripes_workload},
    {"cross_field_stripes",
     "smoothest cross field, then the two coupled families of stripes; phases field, stripes, full, "
     "automatic, edit",
     &cross_field_stripes_workload},
    {"field_stripes",
     "smoothest vector field, then the stripes along it; phases field, stripes, full (one ordering and "
     "analysis shared by the two systems: default and supernodal), full, analyses not shared",
     &field_stripes_workload},
#ifdef SURFACE_DESIGN_BENCHMARK_HAS_EDITOR
    {"editor",
     "the stripe editor's server, edit by edit (JSON parse, edit, re-solve, per-corner state written); phases open, "
     "add pair, drag step (mean of 20 moves to an adjacent face), frequency, state (serialization alone)",
     &editor_workload, Solver_use::none},
#endif
    {"smoothest_field", "smoothest vector field (smoothest_direction_field, n = 1); phase full",
     &smoothest_field_workload},
    {"trivial_connection",
     "vector field with |chi| prescribed singularities per closed component (Trivial_connection); "
     "phases factor, solve, resolve (one singularity moved), full = factor + solve",
     &trivial_connection_workload},
    {"embedding",
     "barycentric embedding, uniform weights, boundary fixed (Barycentric_embedder); phases factor, "
     "update, full = factor + update",
     &embedding_workload, Solver_use::compared, "embedding_iterative"},
    {"embedding_iterative", "the paper's iterative method 2 (area change < 1e-6); phase full",
     &embedding_iterative_workload},
    {"deformation",
     "Table 2: factor once, then 10 steps moving the top and bottom fixed vertices + update(); "
     "phases factor, updates, full",
     &deformation_workload, Solver_use::compared, "deformation_iterative"},
    {"deformation_iterative", "the 10 deformation steps by the iterative method 2; phase full",
     &deformation_iterative_workload},
    {"deformation_vs_fair", "the same as deformation, compared with PMP::fair",
     &deformation_workload, Solver_use::compared, "deformation_fair"},
    {"deformation_fair",
     "the 10 deformation steps by PMP::fair (continuity 0, uniform weights, refactors each call); "
     "phase full",
     &deformation_fair_workload},
    {"developability_evaluation",
     "one energy + gradient evaluation per developability energy, sequential and with TBB (2 threads); "
     "a phase per energy",
     &developability_evaluation_workload, Solver_use::none},
    {"flatten",
     "developable cut (epsilon 1e-3) + Boundary First Flattening (u_B = 0); phases cut, factor, flatten, "
     "full = factor + flatten",
     &flatten_workload, Solver_use::compared, "flatten_arap"},
    {"flatten_split",
     "the CLI's loop: developable cut, BFF, then while a piece overlaps itself in the plane, split it "
     "(compute_overlap_splitting_cut) and flatten again; phases cut, flatten and split; up to 200k faces",
     &flatten_split_workload},
    {"flatten_arap",
     "the same pieces flattened by CGAL's ARAP parameterizer (Surface_mesh_parameterization defaults: lambda 1000, "
     "50 iterations; its own solver, whichever is selected); phases cut, arap, full = arap; up to 300k faces",
     &flatten_arap_workload},
    {"quad_remesh",
     "harmonic-function quad remeshing, default constraints, spectacles, quads only, ~3000 faces in the net (as the "
     "CLI); phases harmonic, re-solve, curves, meshing (of which quads only), full (Nagano & Imai's Table 2); checks: "
     "quality of the output",
     &harmonic_quad_workload},
    {"quad_remesh_net", "the same, the quad-dominant net as it is (no odd faces paired)", &harmonic_quad_net_workload},
    {"quad_remesh_no_spectacles", "the net without spectacles (Dong et al.'s net alone)",
     &harmonic_quad_no_spectacles_workload},
    {"quad_remesh_delaunay", "the same on the intrinsic Delaunay Laplacian", &harmonic_quad_delaunay_workload},
    {"quad_remesh_curvature", "quad_remesh with curvature-adapted spacing (curvature_adaptation 1)",
     &harmonic_quad_curvature_workload},
    {"developable_flow_intrinsic",
     "make_piecewise_developable, intrinsic energy, 2 subdivisions; phases flow, metrics",
     &developable_flow_workload<CGAL::Surface_design::Developability_energy::intrinsic>, Solver_use::none, nullptr, true},
    {"developable_flow_covariance", "the same with the covariance energy (E^lambda)",
     &developable_flow_workload<CGAL::Surface_design::Developability_energy::covariance>, Solver_use::none, nullptr, true},
    {"developable_flow_intrinsic_width", "the same with the intrinsic width energy (B.5.1; the CLI's default)",
     &developable_flow_workload<CGAL::Surface_design::Developability_energy::intrinsic_width>, Solver_use::none, nullptr, true},
    {"developable_flow_covariance_max", "the same with the max covariance energy (eq. 6)",
     &developable_flow_workload<CGAL::Surface_design::Developability_energy::covariance_max>, Solver_use::none, nullptr, true},
    {"developable_flow_combinatorial", "the same with the combinatorial energy (E^P)",
     &developable_flow_workload<CGAL::Surface_design::Developability_energy::combinatorial>, Solver_use::none, nullptr, true},
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
  "                   storus:F      generated all-acute (staggered) torus of about F faces\n"
  "                   octahedron:M  Imafuji & Ochiai's octahedron, M segments per hexagon side\n"
  "                   (repeatable; default: preset quick)\n"
  "  --preset NAME    a named list of meshes (repeatable; see --list); without --workload,\n"
  "                   runs the workloads the preset is meant for\n"
  "  --solver S       default, ldlt, ldlt-nd, supernodal, ldlt-metis, cholmod, a comma-separated list, or all\n"
  "                   (default: all);\n"
  "                   the first is the baseline of the comparisons\n"
  "  --warmup W       unmeasured runs first (default 1)\n"
  "  --runs R         measured runs (default 5)\n"
  "  --json FILE      where to write the results (default benchmark_results.json)\n"
  "  --list           list the workloads, presets and solvers, and exit\n";

void print_list(std::ostream& out)
{
  out << "workloads:\n";
  for(const Workload& w : workloads())
  {
    out << "  " << w.name << "  " << w.description;
    if(w.reference)
      out << "; compared with " << w.reference;
    out << '\n';
  }
  out << "presets:\n";
  for(const Preset& p : presets())
  {
    out << "  " << p.name << "  " << p.description << "\n     ";
    for(const char* s : p.sources)
      out << ' ' << s;
    if(!p.workloads.empty())
    {
      out << "\n      workloads:";
      for(const char* w : p.workloads)
        out << ' ' << w;
    }
    out << '\n';
  }
  out << "solvers:\n";
  for(const Solver_info& s : known_solvers())
    out << "  " << s.name << "  " << s.description
        << (s.available ? "" : std::string("  (unavailable: ") + s.missing + ")") << '\n';
}

bool parse_count(const std::string& text, int lowest, int& value)
{
  if(text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoi(text);
  return value >= lowest;
}

/// Fills `solvers` from the value of --solver; a known solver missing from this build is
/// reported and dropped.
bool parse_solvers(const std::string& text, std::vector<std::string>& solvers, std::string& error)
{
  solvers.clear();
  std::vector<std::string> requested;
  if(text == "all")
    for(const Solver_info& s : known_solvers())
      requested.push_back(s.name);
  else
    for(std::size_t start = 0; start <= text.size();)
    {
      const std::size_t comma = std::min(text.find(',', start), text.size());
      requested.push_back(text.substr(start, comma - start));
      start = comma + 1;
    }
  const std::vector<Solver_info>& known = known_solvers();
  for(const std::string& s : requested)
  {
    const auto info = std::find_if(known.begin(), known.end(),
                                   [&s](const Solver_info& k) { return s == k.name; });
    if(info == known.end())
    {
      error = "unknown solver \"" + s + "\" (expected";
      for(const Solver_info& k : known)
        error += std::string(" ") + k.name + ",";
      error += " a comma-separated list of them, or all)";
      return false;
    }
    if(!info->available)
      std::cout << "solver " << s << ": unavailable (" << info->missing << ")\n";
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
  bool preset_given = false, preset_wants_all = false; // workloads implied by the presets
  std::vector<const Workload*> preset_workloads;
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
      preset_given = true;
      preset_wants_all = preset_wants_all || p->workloads.empty();
      for(const char* name : p->workloads)
      {
        const Workload* w = find_workload(name);
        if(w && std::find(preset_workloads.begin(), preset_workloads.end(), w) ==
                  preset_workloads.end())
          preset_workloads.push_back(w);
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

  if(options.workloads.empty() && preset_given)
    options.workloads = preset_workloads;
  if(options.workloads.empty() || (preset_given && preset_wants_all))
    for(const Workload& w : workloads())
      if(!w.on_request_only && std::find(options.workloads.begin(), options.workloads.end(), &w) ==
                                  options.workloads.end())
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
  std::vector<Not_applicable_result> not_applicable;
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
      not_applicable.insert(not_applicable.end(), m.not_applicable.begin(), m.not_applicable.end());
      if(m.failures > 0)
        exit_code = 1;
    }
  }

  const Machine_info machine = machine_info();
  std::vector<Comparison> comparisons = compare_contenders(results);
  const std::vector<Comparison> with_references = compare_with_references(results, workloads());
  comparisons.insert(comparisons.end(), with_references.begin(), with_references.end());
  const bool solver_comparisons = with_references.size() < comparisons.size();
  std::cout << '\n';
  print_machine(std::cout, machine);
  std::cout << '\n';
  print_results(std::cout, results);
  if(!not_applicable.empty())
  {
    std::cout << "\nnot applicable:\n";
    print_not_applicable(std::cout, not_applicable);
  }
  if(solver_comparisons)
  {
    std::cout << "\nsolvers: ratio = baseline median / contender median"
              << " (above 1: the contender is faster)\n";
    print_solver_comparisons(std::cout, comparisons);
  }
  if(!with_references.empty())
  {
    std::cout << "\nreference workloads: ratio = reference median / workload median"
              << " (above 1: the workload is faster)\n";
    print_reference_comparisons(std::cout, comparisons);
  }
  const std::size_t failed_checks = std::size_t(
    std::count_if(checks.begin(), checks.end(), [](const Check_result& k) { return !k.passed(); }));
  if(failed_checks > 0)
  {
    // the figures of a run whose results are wrong are not figures: the run fails (after the JSON)
    std::cout << "\nERROR: " << failed_checks << " of " << checks.size() << " sanity checks failed (see above)\n";
    exit_code = 1;
  }

  if(write_json(options.json, machine, options.timing, command_line, results, comparisons, checks,
                not_applicable))
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
