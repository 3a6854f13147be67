// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quad remeshing with the isolines and gradient lines of a harmonic function.

#ifndef CGAL_SURFACE_DESIGN_HARMONIC_QUAD_REMESHER_H
#define CGAL_SURFACE_DESIGN_HARMONIC_QUAD_REMESHER_H

// (the refined mesh of the spectacles is a Surface_mesh: its graph functions come first)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/intrinsic_delaunay.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/harmonic_function.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/net_cells.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/odd_faces.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/pipeline.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/quad_net.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/snap.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/spectacles.h>
#include <CGAL/Surface_design/internal/Harmonic_quad_remeshing/trace_mesh.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgHarmonicQuadRemeshingRef
/// Weights of the Laplacian whose harmonic function drives the remeshing.
enum class Harmonic_weights
{
  cotangent,         ///< the cotangent weights of the mesh (negative across non-Delaunay edges)
  intrinsic_delaunay ///< the cotangent weights of the intrinsic Delaunay triangulation (>= 0 on
                     ///< interior edges up to rounding, -1e-12 at worst: the discrete maximum
                     ///< principle holds on its edges; extrema
                     ///< are classified on the mesh's own edges, where they are then rare)
};

/// \ingroup PkgHarmonicQuadRemeshingRef
/// The critical vertices of a piecewise-linear function (Edelsbrunner, Harer & Zomorodian 2003:
/// ties broken by vertex index). Vertex indices are those of the mesh's index maps.
struct Harmonic_critical_points
{
  std::vector<std::size_t> minima, maxima;
  std::vector<std::pair<std::size_t, int>> saddles; ///< (vertex, multiplicity: k - 1 for k lower wedges)
  std::size_t on_boundary = 0;      ///< critical vertices on the boundary
  std::size_t spurious_extrema = 0; ///< extrema that are not constrained vertices
  /// sum over all vertices of 1 - chi(lower link); equal to `euler_characteristic` for any
  /// function (a theorem: a check of the classification). On a closed mesh it is #minima +
  /// #maxima - sum of saddle multiplicities; on the boundary a maximum has index 0.
  long index_sum = 0;
  long euler_characteristic = 0; ///< V - E + F of the mesh

  int saddle_multiplicity() const
  {
    int m = 0;
    for(const auto& s : saddles)
      m += s.second;
    return m;
  }
};

/// \ingroup PkgHarmonicQuadRemeshingRef
/// What `Harmonic_quad_remesher::remesh()` did.
struct Harmonic_quad_remeshing_result
{
  double target_edge_length = 0.;
  /// the spacing h of the net that was used: `target_edge_length`, or finer after a fall-back
  /// (see `fallbacks`)
  double spacing = 0.;
  std::size_t levels = 0;          ///< isovalues
  std::size_t isolines = 0;        ///< connected isolines in the net (loops and paths)
  std::size_t gradient_lines = 0;  ///< traced gradient-line pieces (isoline to isoline)
  std::size_t stopped_lines = 0;   ///< lines ended because a neighbour came closer than h / sqrt 2
  std::size_t started_lines = 0;   ///< lines started in gaps wider than h sqrt 2 (or on first isolines)
  std::size_t merged_lines = 0;    ///< lines ended because they met another one
  std::size_t saddle_levels = 0;   ///< isolines added between two saddles of one band
  std::size_t saddles = 0;         ///< saddle vertices of the harmonic function
  std::size_t spectacles = 0;      ///< saddles given spectacles
  std::size_t spectacles_lines = 0; ///< lines from bridges and junctions
  /// net vertices added at the input's boundary vertices where the boundary leaves the chord
  /// between two net vertices by more than h / 4 (serrated or sharply bent boundaries)
  std::size_t boundary_detail_vertices = 0;
  /// saddles left without spectacles (input vertex index, reason), with `spectacles(true)`
  std::vector<std::pair<std::size_t, std::string>> skipped_saddles;
  /// cells of the net whose boundary ran through a node twice (a band crossed by a single
  /// gradient line leaves a slit; two loops of the net touching pinch a cell), each cut by a
  /// chord between the two parts of its boundary
  std::size_t repaired_cells = 0;
  /// the attempts that failed before the one that made the output ("what: why"), then "used:
  /// what"; empty when the net came out right at once. A net is accepted only as a valid
  /// polygon mesh with the input's topology; the attempts, in turn: as asked, without
  /// spectacles, the intrinsic Delaunay Laplacian (when the cotangent one has negative
  /// weights), then finer spacings, the one that adds the fewest faces first: h / 2 within 2 h
  /// of the saddles, h / sqrt 2, h / 2.
  std::vector<std::string> fallbacks;
  std::size_t odd_faces = 0;        ///< faces of the net with an odd number of sides
  std::size_t odd_face_paths = 0;   ///< with `all_quads(true)`: paths that paired them (or led to the boundary)
  std::size_t split_edges = 0;      ///< with `all_quads(true)`: edges of the net given a vertex
  /// interior input vertices and points along its creases farther than h / 4 from the remeshed
  /// surface before feature snapping
  std::size_t far_input_vertices = 0;
  std::size_t snapped_vertices = 0; ///< with `feature_snapping(true)`: output vertices moved onto them
  double largest_input_distance = 0.; ///< the largest of those distances, before snapping (0 without it)
  std::size_t vertices = 0, faces = 0; ///< of the output
  /// of the output, always the input's (checked on the net: a net with another topology is
  /// never returned)
  long euler_characteristic = 0;
  std::size_t boundary_loops = 0, components = 0;
  double harmonic_seconds = 0.;    ///< Laplacian, factorization, solve (when they were done)
  double spectacles_seconds = 0.;  ///< spectacles: curves, insertion into the mesh, re-solve
  double curves_seconds = 0.;      ///< isolines and gradient lines
  double meshing_seconds = 0.;     ///< faces of the net, quads only (`all_quads`), the output mesh
  double all_quads_seconds = 0.;   ///< of which quads only: pairing the odd faces, splitting
  double snapping_seconds = 0.;    ///< of which feature snapping (distances through an AABB tree)
};

/// \ingroup PkgHarmonicQuadRemeshingRef
///
/// Quad remeshing of a triangle mesh by the net of isolines and gradient lines of a harmonic
/// function (Dong, Kircher & Garland 2005), with Nagano & Imai's spectacles at saddles.
///
/// **The function.** Given constraints u(c) = value at a few vertices C (at least one minimum
/// and one maximum per connected component), u is the solution of L_FF u_F = -L_FC u_C, L the
/// cotangent Laplacian (of the intrinsic Delaunay triangulation with
/// `Harmonic_weights::intrinsic_delaunay`), with zero flux across the boundary. It has no
/// extremum outside C when the weights are positive; its saddles make up the difference in the
/// Euler characteristic: #max + #min - sum of saddle multiplicities = chi.
///
/// **The net.** Isolines at levels c_1 < c_2 < ... spaced so that the next level lies h further
/// (h times the median of |grad u| on the level), and gradient lines from each isoline to the
/// next, started evenly on first isolines and kept between h / sqrt 2 and h sqrt 2 apart along
/// every isoline (a line stops, or a new one starts, otherwise). Lines run straight through
/// faces and along edges where both faces' gradients meet; they end at extrema (poles: every
/// other line is kept, a fan of quads), at the boundary (kept as it is), or one isoline early
/// where they meet another line. Between two saddles that fall between the same two levels an
/// extra isoline separates them, so that every cell is a disk. The faces of the net are found
/// from its rotation system (up, along, down, back at every crossing).
///
/// **Spectacles** (Nagano & Imai, on by default): at every simple interior saddle, two gradient
/// lines from the saddle to the next level of the net (the bridge) and the isolines where they end
/// (the frames) are inserted into a copy of the mesh and held at one value while the function is
/// solved again, so that the saddle's octagon-like cell gives way to one isoline graph with quads
/// around it; saddles where this cannot be done are listed in the report with the reason.
///
/// **Quads only** (on by default). The net is quad-dominant: where a line stops on an isoline
/// the cell beyond is a pentagon with a flat corner (a T-junction). Faces with an odd number of
/// sides are paired by shortest paths across the net that run straight (a turn costs extra) and
/// leave a pentagon opposite its flat corner, i.e. they continue the line that stopped until it
/// meets another such cell (or the boundary); every edge crossed gets a vertex at its middle, and
/// every face, now with an even number of sides, is split into quads by diagonals or,
/// where a path turns, by a centre vertex.
///
/// The class factors the Laplacian once: new constraints on the same vertex set, or new edge
/// lengths, reuse it (with spectacles, the refined copy of the mesh is factored for each remesh).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`, triangles only
/// \tparam VertexPointMap a readable vertex -> `Point_3` property map
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d`
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class SolverTraits = Default_solver_traits>
class Harmonic_quad_remesher
{
  using GT = boost::graph_traits<TriangleMesh>;
  using Indices = internal::Mesh_indices<TriangleMesh>;
  using Clock = std::chrono::steady_clock;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;

  /// Validates the mesh and builds the Laplacian.
  ///
  /// \param tm the mesh; it must not change while the object is used
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as
  ///                    value type, convertible to `VertexPointMap`}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{sparse_linear_solver}
  ///     \cgalParamDescription{the sparse solver that factors the Laplacian (of `harmonic_weights`) restricted
  ///                           to the unconstrained vertices (the Laplacians of the mesh refined along
  ///                           spectacles and of the intrinsic Delaunay fall-back of `remesh()` are factored by
  ///                           new objects of the same type)}
  ///     \cgalParamType{`SolverTraits`, a model of `SparseLinearAlgebraWithFactorTraits_d` (class template
  ///                    argument deduction takes the class's `SolverTraits` from this parameter)}
  ///     \cgalParamDefault{`SolverTraits()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{harmonic_weights}
  ///     \cgalParamDescription{the weights of the Laplacian whose harmonic function drives the remeshing}
  ///     \cgalParamType{`Harmonic_weights`}
  ///     \cgalParamDefault{`Harmonic_weights::cotangent`}
  ///     \cgalParamExtra{throws `Invalid_parameter` for a value other than the two enumerators}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{harmonic_constraints}
  ///     \cgalParamDescription{the constrained vertices and their values, u(c) = value (see
  ///                           `set_constraints()`)}
  ///     \cgalParamType{a range of (`vertex_descriptor`, value convertible to `double`) pairs}
  ///     \cgalParamDefault{the default constraints (`set_default_constraints()`)}
  ///     \cgalParamExtra{throws `Invalid_constraints` if a vertex is not a vertex of `tm` or is constrained
  ///                     twice, if a value is not finite, or if a connected component does not get at least two
  ///                     different values}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{protrusion_maxima}
  ///     \cgalParamDescription{with the default constraints, whether there is also a maximum at every tip of
  ///                           the shape (see `set_default_constraints()`)}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///     \cgalParamExtra{ignored when `harmonic_constraints` is given}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
  ///                           `[0, num_vertices(tm))`: the numbering of the elements (vertex indices in the
  ///                           results and in error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_vertices(tm))`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{halfedge_index_map}
  ///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
  ///                           `[0, num_halfedges(tm))`: the numbering of the elements (vertex indices in the
  ///                           results and in error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_halfedges(tm))`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{edge_index_map}
  ///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
  ///                           `[0, num_edges(tm))`: the numbering of the elements (vertex indices in the
  ///                           results and in error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the order of `edges(tm)`}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_edges(tm))`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{face_index_map}
  ///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
  ///                           `[0, num_faces(tm))`: the numbering of the elements (vertex indices in the
  ///                           results and in error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_faces(tm))`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Invalid_mesh the mesh is empty, not triangles, not manifold, has degenerate faces or
  ///         non-finite coordinates
  /// \throws Invalid_constraints the constraints are invalid (see `set_constraints()`)
  /// \throws Invalid_parameter `harmonic_weights` is not a `Harmonic_weights` enumerator
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Harmonic_quad_remesher(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_idx(tm, np),
      m_vpm(internal::class_vertex_point_map<VertexPointMap, false>(tm, np))
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    internal::validate_mesh(m_idx, m_vpm);
    m_mesh = internal::harmonic_quad::make_trace_mesh(m_idx, m_vpm);
    m_topology = internal::harmonic_quad::soup_topology(m_mesh.tri, m_mesh.number_of_vertices());
    m_weights_kind = choose_parameter(get_parameter(np, internal_np::harmonic_weights), Harmonic_weights::cotangent);
    if(m_weights_kind != Harmonic_weights::cotangent && m_weights_kind != Harmonic_weights::intrinsic_delaunay)
      throw Invalid_parameter("harmonic_weights", "not a Harmonic_weights enumerator");
    const auto start = Clock::now();
    internal::Intrinsic_triangulation intrinsic(m_idx, m_vpm);
    if(m_weights_kind == Harmonic_weights::intrinsic_delaunay)
      m_flips = intrinsic.make_delaunay();
    m_solver = std::make_unique<Solver>(m_mesh.number_of_vertices(), intrinsic.cotangent_weights(),
                                        internal::class_solver_traits<SolverTraits>(np));
    m_setup_seconds = seconds_since(start);
    const auto constraints = get_parameter(np, internal_np::harmonic_constraints);
    if constexpr(std::is_same<std::decay_t<decltype(constraints)>, CGAL::internal_np::Param_not_found>::value)
      set_default_constraints(choose_parameter(get_parameter(np, internal_np::protrusion_maxima), true));
    else
      set_constraints(constraints);
  }

  /// Sets the constraints: a range of (vertex_descriptor, value) pairs with finite values, each
  /// vertex at most once, and on every connected component at least two different values.
  /// \throws Invalid_constraints otherwise (the previous constraints stay)
  template <class ConstraintRange>
  void set_constraints(const ConstraintRange& constraints)
  {
    std::vector<std::pair<std::size_t, double>> c;
    for(const auto& [v, value] : constraints)
    {
      const std::size_t i = m_idx.find(v);
      if(i == internal::npos)
        throw Invalid_constraints("a constrained vertex is not a vertex of the mesh");
      c.emplace_back(i, double(value));
    }
    internal::harmonic_quad::check_constraints(m_mesh, c);
    m_constraints = std::move(c);
    m_solved = false;
  }

  /// The default constraints: per connected component a minimum (0) and a maximum (1) at the ends
  /// of an approximate geodesic diameter (two Dijkstra sweeps), and with `protrusions` a maximum at
  /// every tip t (a vertex farthest from the minimum within a geodesic ball of a quarter of the
  /// diameter), valued d(min, t) / diameter.
  void set_default_constraints(bool protrusions = true)
  {
    m_constraints = internal::harmonic_quad::default_constraints(m_mesh, protrusions);
    m_solved = false;
  }

  /// The constraints as (vertex_descriptor, value) pairs, as `set_constraints()` takes them.
  std::vector<std::pair<vertex_descriptor, double>> constraints() const
  {
    std::vector<std::pair<vertex_descriptor, double>> c;
    c.reserve(m_constraints.size());
    for(const auto& [i, value] : m_constraints)
      c.emplace_back(m_idx.vertex(i), value);
    return c;
  }

  /// Number of intrinsic edge flips made (`Harmonic_weights::intrinsic_delaunay`).
  std::size_t number_of_flips() const { return m_flips; }

  /// Number of edges (of the intrinsic triangulation, boundary edges included) with a negative
  /// Laplacian weight.
  std::size_t number_of_negative_weights() const
  {
    std::size_t n = 0;
    for(const auto& e : m_solver->weights())
      n += e.w < 0.;
    return n;
  }

  /// The harmonic function, one value per vertex index (solved on first use).
  /// \throws Linear_solver_failure if the factorization fails
  const std::vector<double>& harmonic_function()
  {
    solve();
    return m_u;
  }

  /// Writes the harmonic function to a writable vertex -> double map.
  template <class VertexValueMap>
  void harmonic_function(VertexValueMap values)
  {
    solve();
    for(std::size_t v = 0; v < m_u.size(); ++v)
      put(values, m_idx.vertex(v), m_u[v]);
  }

  /// max over unconstrained vertices of |(L u)_i| / (L_ii (max u - min u)): 0 up to rounding.
  double harmonic_residual()
  {
    solve();
    std::vector<double> lu(m_u.size(), 0.), diagonal(m_u.size(), 0.);
    for(const auto& e : m_solver->weights())
    {
      lu[e.i] += e.w * (m_u[e.i] - m_u[e.j]);
      lu[e.j] += e.w * (m_u[e.j] - m_u[e.i]);
      diagonal[e.i] += std::abs(e.w);
      diagonal[e.j] += std::abs(e.w);
    }
    const auto [lo, hi] = std::minmax_element(m_u.begin(), m_u.end());
    const double range = (std::max)(*hi - *lo, 1e-300);
    double worst = 0.;
    for(std::size_t v = 0; v < m_u.size(); ++v)
      if(!m_constrained[v] && diagonal[v] > 0.)
        worst = (std::max)(worst, std::abs(lu[v]) / (diagonal[v] * range));
    return worst;
  }

  /// The critical vertices of the harmonic function.
  Harmonic_critical_points critical_points()
  {
    solve();
    Harmonic_critical_points out;
    const auto [list, index_sum] = internal::harmonic_quad::critical_points(m_mesh, m_u);
    out.index_sum = index_sum;
    out.euler_characteristic = long(m_idx.number_of_vertices()) - long(m_idx.number_of_edges()) +
                               long(m_idx.number_of_faces());
    using internal::harmonic_quad::Critical_kind;
    for(const auto& c : list)
    {
      out.on_boundary += c.on_boundary;
      if(c.kind == Critical_kind::saddle)
        out.saddles.emplace_back(c.vertex, c.multiplicity);
      else
      {
        (c.kind == Critical_kind::minimum ? out.minima : out.maxima).push_back(c.vertex);
        out.spurious_extrema += !m_constrained[c.vertex];
      }
    }
    return out;
  }

  /// Remeshes into `out` (the new vertices and faces are added to it): a quad mesh (with
  /// `all_quads(false)`: the quad-dominant net) with the input's topology (Euler characteristic,
  /// boundary loops and connected components, checked), consistently oriented like the input.
  /// When the net of the requested settings comes out wrong, the method falls back to what the
  /// package has (see `Harmonic_quad_remeshing_result::fallbacks`) and otherwise throws.
  ///
  /// \tparam PolygonMesh a model of `MutableFaceGraph`, with an internal point property map or a
  ///         `vertex_point_map` for it in `np`
  /// \param np an optional sequence of named parameters among the ones listed below
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{target_edge_length}
  ///     \cgalParamDescription{the spacing h of both families of curves}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{sqrt(area / 3000), with the surface area of the mesh given to the constructor: about
  ///                       3000 faces}
  ///     \cgalParamExtra{throws `Invalid_parameter` if it is not finite and positive, or if area / h^2 > 1e7
  ///                     (about 10 million faces)}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{quad_poles}
  ///     \cgalParamDescription{fans of quads at the extrema (every other line ends there); `false`: fans of
  ///                           triangles}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{spectacles}
  ///     \cgalParamDescription{Nagano & Imai's spectacles around every simple interior saddle (two gradient
  ///                           lines from the saddle down, or up, to the next level of the net and the isolines
  ///                           where they end), inserted into a copy of the mesh, held at one value while the
  ///                           function is re-solved, and built into the net as one isoline graph (lines leave
  ///                           the bridge on both sides and each junction along the bisectors of its two
  ///                           corners). Saddles whose spectacles cannot be built (on the boundary, of
  ///                           multiplicity > 1, both wedges reaching one isoline, crossing other spectacles)
  ///                           are listed in `skipped_saddles` with the reason; when the net with spectacles is
  ///                           not a valid polygon mesh with the input's topology, the net is built without
  ///                           them and all are listed there}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{all_quads}
  ///     \cgalParamDescription{quads only. The net's faces with an odd number of sides (the pentagons where a
  ///                           line ends on an isoline, triangles) are paired by short, straight paths across
  ///                           the net (or led to the boundary); every edge a path crosses gets a vertex at its
  ///                           middle and every face is split into quads by the diagonals that keep its corners
  ///                           closest to 90 degrees. A path continues the line that ended at a T-junction
  ///                           until it meets another one, so T-junctions become regular vertices. `false`: the
  ///                           quad-dominant net as it is}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{curvature_adaptation}
  ///     \cgalParamDescription{curvature-adapted spacing a: the spacing of both families of curves becomes h /
  ///                           (1 + a h kappa), at least h / 4, with kappa the (smoothed) normal curvature
  ///                           across the input's edges: finer where the surface bends. 0: uniform spacing h}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{`0`}
  ///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{feature_snapping}
  ///     \cgalParamDescription{the curves pass over features narrower than their spacing (a pit, a spike, the
  ///                           apex of a cone, a sharp crease). Interior input vertices, and points at most h / 2
  ///                           apart along the input's creases (edges whose faces' normals differ by more than 30
  ///                           degrees), farther than h / 4 from the result, farthest first, pull the nearest
  ///                           corner of the face closest to them
  ///                           onto them (a corner not on the boundary, at most 2h away, no face around it
  ///                           turned over or moved before). The boundary needs no snapping: where the input's
  ///                           boundary leaves the chord between two vertices of the net by more than h / 4 (a
  ///                           serrated or sharply bent boundary), its vertices become vertices of the net (an
  ///                           even number per edge, see `boundary_detail_vertices`)}
  ///     \cgalParamType{`bool`}
  ///     \cgalParamDefault{`true`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_point_map}
  ///     \cgalParamDescription{a property map through which the points of the new vertices of `out` are
  ///                           written}
  ///     \cgalParamType{a class model of `WritablePropertyMap` with
  ///                    `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and `%Point_3` as
  ///                    value type}
  ///     \cgalParamDefault{`boost::get(CGAL::vertex_point, out)`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Invalid_parameter `target_edge_length` is not finite and positive, or so small that
  ///         area / h^2 exceeds 10^7 (about that many faces); `curvature_adaptation` negative or not finite
  /// \throws Remeshing_failure when no attempt (see `Harmonic_quad_remeshing_result::fallbacks`)
  ///         makes a net that is a valid polygon mesh with the input's topology; `out` is
  ///         then unchanged. A result with another topology is never returned.
  /// \throws Linear_solver_failure if a factorization fails
  template <class PolygonMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
  Harmonic_quad_remeshing_result remesh(PolygonMesh& out, const NamedParameters& np = CGAL::parameters::default_values())
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    Harmonic_quad_remeshing_result report;
    double area = 0.;
    for(double a : m_mesh.area)
      area += a;
    const double h = choose_parameter(get_parameter(np, internal_np::target_edge_length), std::sqrt(area / 3000.));
    if(!std::isfinite(h) || !(h > 0.))
      throw Invalid_parameter("target_edge_length", "must be finite and positive (got " + internal::to_text(h) + ")");
    if(area / (h * h) > 1e7)
      throw Invalid_parameter("target_edge_length", internal::to_text(h) + " would make about " +
                                                      internal::to_text(area / (h * h)) +
                                                      " faces (the surface area is " + internal::to_text(area) +
                                                      "); at most 1e7");
    const double adaptation = choose_parameter(get_parameter(np, internal_np::curvature_adaptation), 0.);
    if(!std::isfinite(adaptation) || adaptation < 0.)
      throw Invalid_parameter("curvature_adaptation",
                              "must be finite and non-negative (got " + internal::to_text(adaptation) + ")");
    report.target_edge_length = h;
    solve();
    report.harmonic_seconds = m_setup_seconds + m_solve_seconds;

    namespace hq = internal::harmonic_quad;
    hq::Pipeline_options options;
    options.h = h;
    options.adaptation = adaptation;
    options.spectacles = choose_parameter(get_parameter(np, internal_np::spectacles), true);
    options.quad_poles = choose_parameter(get_parameter(np, internal_np::quad_poles), true);
    options.all_quads = choose_parameter(get_parameter(np, internal_np::all_quads), true);
    const hq::Pipeline_input<SolverTraits> input{
      m_mesh, m_u, m_constraints, m_topology, m_weights_kind == Harmonic_weights::intrinsic_delaunay,
      m_weights_kind == Harmonic_weights::cotangent ? number_of_negative_weights() : 0, m_solver->traits(),
      [this]() -> const std::vector<double>& { return intrinsic_function(); }};
    hq::Polygon_soup soup = hq::make_quad_net(input, options, report);
    const auto start = Clock::now();
    if(choose_parameter(get_parameter(np, internal_np::feature_snapping), true))
    {
      const auto snap_start = Clock::now();
      const double spacing = report.spacing;
      const internal::Snap_statistics snap = hq::snap_to_far_vertices(soup, m_mesh, spacing / 4., 2. * spacing, true);
      report.far_input_vertices = snap.far_vertices;
      report.snapped_vertices = snap.snapped;
      report.largest_input_distance = snap.largest_distance;
      report.snapping_seconds = seconds_since(snap_start);
    }
    using Out_vpm = internal::Vertex_point_map_t<PolygonMesh, NamedParameters>;
    using Out_point = typename boost::property_traits<Out_vpm>::value_type;
    std::vector<Out_point> points;
    points.reserve(soup.points.size());
    for(const auto& p : soup.points)
      points.emplace_back(p.x(), p.y(), p.z());
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.faces, out,
                                                                CGAL::parameters::default_values(), np);
    report.vertices = soup.points.size();
    report.faces = soup.faces.size();
    report.euler_characteristic = m_topology.euler_characteristic;
    report.boundary_loops = m_topology.boundary_loops;
    report.components = m_topology.components;
    report.meshing_seconds += seconds_since(start);
    return report;
  }

private:
  using Solver = internal::harmonic_quad::Harmonic_solver<SolverTraits>;

  // the function of the intrinsic Delaunay Laplacian with the same constraints (a fall-back of
  // remesh() when the cotangent Laplacian has negative weights), solved once
  const std::vector<double>& intrinsic_function()
  {
    if(m_intrinsic_u.empty())
    {
      internal::Intrinsic_triangulation intrinsic(m_idx, m_vpm);
      intrinsic.make_delaunay();
      Solver solver(m_mesh.number_of_vertices(), intrinsic.cotangent_weights(),
                    internal::new_solver_like(m_solver->traits()));
      std::vector<double> u(m_mesh.number_of_vertices(), 0.);
      for(const auto& [v, value] : m_constraints)
        u[v] = value;
      solver.factor(m_constrained);
      solver.solve(u);
      m_intrinsic_u = std::move(u); // kept only once solved
    }
    return m_intrinsic_u;
  }

  static double seconds_since(Clock::time_point t)
  {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }

  void solve()
  {
    if(m_solved)
      return;
    const auto start = Clock::now();
    m_constrained.assign(m_mesh.number_of_vertices(), 0);
    m_u.assign(m_mesh.number_of_vertices(), 0.);
    for(const auto& [v, value] : m_constraints)
    {
      m_constrained[v] = 1;
      m_u[v] = value;
    }
    m_solver->factor(m_constrained);
    m_solver->solve(m_u);
    m_intrinsic_u.clear();
    m_solve_seconds = seconds_since(start);
    m_solved = true;
  }

  Indices m_idx;
  VertexPointMap m_vpm;
  internal::harmonic_quad::Trace_mesh m_mesh;
  Harmonic_weights m_weights_kind = Harmonic_weights::cotangent;
  std::size_t m_flips = 0;
  std::unique_ptr<Solver> m_solver;
  std::vector<std::pair<std::size_t, double>> m_constraints;
  std::vector<char> m_constrained;
  std::vector<double> m_u;
  std::vector<double> m_intrinsic_u; // the intrinsic Delaunay function, when a fall-back needed it
  internal::harmonic_quad::Soup_topology m_topology; // of the input
  bool m_solved = false;
  double m_setup_seconds = 0., m_solve_seconds = 0.;
};

/// Deduces the point map and solver types from the named parameters.
template <class TriangleMesh, class NamedParameters>
Harmonic_quad_remesher(const TriangleMesh&, const NamedParameters&)
  -> Harmonic_quad_remesher<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                            internal::Solver_traits_t<NamedParameters>>;
template <class TriangleMesh>
Harmonic_quad_remesher(const TriangleMesh&) -> Harmonic_quad_remesher<TriangleMesh>;

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_HARMONIC_QUAD_REMESHER_H
