// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a timing depends on besides the code: the BLAS actually loaded (CHOLMOD's supernodal
// kernels run on it), compiler, library versions, cores, build type.

#ifndef CGAL_SURFACE_DESIGN_BENCHMARK_MACHINE_INFO_H
#define CGAL_SURFACE_DESIGN_BENCHMARK_MACHINE_INFO_H

#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/version_macros.h>

#include <Eigen/Core>

#include <link.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#ifndef SURFACE_DESIGN_BENCHMARK_BUILD_TYPE
#define SURFACE_DESIGN_BENCHMARK_BUILD_TYPE "unknown"
#endif

namespace benchmark {

struct Machine_info
{
  std::string blas;     ///< real paths of the loaded BLAS libraries, or "none loaded"
  std::string cpu;      ///< model name from /proc/cpuinfo
  unsigned cores = 0;   ///< std::thread::hardware_concurrency()
  std::string compiler;
  std::string build_type; ///< CMake configuration, plus whether assertions are on
  std::string cgal_version, eigen_version;
  bool cholmod = false;
  std::string cholmod_version; ///< empty without CHOLMOD
  std::string date;            ///< UTC, ISO 8601
  /// the environment's GLIBC_TUNABLES, or "" (`stripe_peer_comparison.py --warm-heap` sets the
  /// allocator's thresholds there: pages kept between calls, README "Stripes on line fields")
  std::string allocator_tunables;
};

namespace machine_info_detail {

inline int collect_blas(dl_phdr_info* info, std::size_t, void* data)
{
  auto& found = *static_cast<std::vector<std::string>*>(data);
  if(!info->dlpi_name || !*info->dlpi_name)
    return 0;
  std::string name = info->dlpi_name;
  std::string base = name.substr(name.find_last_of('/') + 1);
  std::transform(base.begin(), base.end(), base.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if(base.find("blas") == std::string::npos) // also matches openblas, flexiblas, cblas
    return 0;
  if(char* real = realpath(name.c_str(), nullptr))
  {
    name = real;
    std::free(real);
  }
  if(std::find(found.begin(), found.end(), name) == found.end())
    found.push_back(name);
  return 0;
}

} // namespace machine_info_detail

/// Real paths of the shared objects loaded in this process whose name contains "blas" (the
/// Debian `libblas.so.3` alternative resolves to the implementation behind it), comma-separated;
/// "none loaded" if there is none. Call it after the solvers ran, in case one is loaded lazily.
inline std::string loaded_blas_libraries()
{
  std::vector<std::string> found;
  dl_iterate_phdr(&machine_info_detail::collect_blas, &found);
  std::string list;
  for(const std::string& f : found)
    list += (list.empty() ? "" : ", ") + f;
  return list.empty() ? "none loaded" : list;
}

inline std::string cpu_model()
{
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while(std::getline(in, line))
    if(line.compare(0, 10, "model name") == 0 && line.find(':') != std::string::npos)
      return line.substr(line.find(':') + 2);
  return "unknown";
}

inline Machine_info machine_info()
{
  Machine_info m;
  m.blas = loaded_blas_libraries();
  m.cpu = cpu_model();
  m.cores = std::thread::hardware_concurrency();
#if defined(__clang__)
  m.compiler = "Clang " __clang_version__;
#elif defined(__GNUC__)
  m.compiler = "GCC " __VERSION__;
#else
  m.compiler = __VERSION__;
#endif
#if defined(NDEBUG)
  m.build_type = SURFACE_DESIGN_BENCHMARK_BUILD_TYPE " (NDEBUG)";
#else
  m.build_type = SURFACE_DESIGN_BENCHMARK_BUILD_TYPE " (assertions on)";
#endif
  m.cgal_version = CGAL_VERSION_STR;
  m.eigen_version = std::to_string(EIGEN_WORLD_VERSION) + "." +
                    std::to_string(EIGEN_MAJOR_VERSION) + "." + std::to_string(EIGEN_MINOR_VERSION);
#if defined(CGAL_SURFACE_DESIGN_HAS_CHOLMOD)
  m.cholmod = true;
  m.cholmod_version = std::to_string(CHOLMOD_MAIN_VERSION) + "." +
                      std::to_string(CHOLMOD_SUB_VERSION) + "." +
                      std::to_string(CHOLMOD_SUBSUB_VERSION);
#endif
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  char date[32] = "unknown";
  if(gmtime_r(&now, &utc))
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", &utc);
  m.date = date;
  if(const char* tunables = std::getenv("GLIBC_TUNABLES"))
    m.allocator_tunables = tunables;
  return m;
}

} // namespace benchmark

#endif // CGAL_SURFACE_DESIGN_BENCHMARK_MACHINE_INFO_H
