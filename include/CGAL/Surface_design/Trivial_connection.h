// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Vertex-based direction fields with prescribed singularities from a trivial connection
// (Crane, Desbrun & Schröder 2010), adapted to fields that live on vertices with singularities in
// faces, and solved with the machinery of the stripe parameterization.

#ifndef CGAL_SURFACE_DESIGN_TRIVIAL_CONNECTION_H
#define CGAL_SURFACE_DESIGN_TRIVIAL_CONNECTION_H

#include <CGAL/Surface_design/direction_fields.h>
#include <CGAL/Surface_design/exceptions.h>
#include <CGAL/Surface_design/internal/Core/angles.h>
#include <CGAL/Surface_design/internal/Core/boundary_smoothing.h>
#include <CGAL/Surface_design/internal/Core/discrete_connection.h>
#include <CGAL/Surface_design/internal/Core/geometry.h>
#include <CGAL/Surface_design/internal/Core/Mesh_indices.h>
#include <CGAL/Surface_design/internal/Core/named_parameters.h>
#include <CGAL/Surface_design/internal/Core/Periodic_one_form_solver.h>
#include <CGAL/Surface_design/internal/Core/validation.h>
#include <CGAL/Surface_design/internal/Direction_fields/boundary_alignment.h>
#include <CGAL/Surface_design/internal/Direction_fields/direction_field_operators.h>
#include <CGAL/Surface_design/internal/Direction_fields/edge_rotation_bound.h>
#include <CGAL/Surface_design/internal/Direction_fields/singularity_separation.h>
#include <CGAL/Surface_design/parameters.h>
#include <CGAL/Surface_design/solver_traits.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {

/// \ingroup PkgDirectionFieldsRef
///
/// A vertex-based n-direction field whose singularities are exactly at prescribed faces, with
/// prescribed indices (multiples of 1/n), and that is parallel everywhere else for a connection
/// as close as possible to the Levi-Civita connection (Crane et al. 2010, "Trivial connections on
/// discrete surfaces").
///
/// **The problem.** The Levi-Civita transport rotates an n-direction by n rho_e along edge e
/// (angles in the rescaled vertex frames, see `smoothest_direction_field()`). Find per-edge
/// adjustments x_e of least l2 norm such that the adjusted transport n rho_e + x_e has holonomy
/// 2 pi k_f around every face f (k_f / n its prescribed index), a multiple of 2 pi around every
/// homology generator and every boundary loop; then transporting one direction from a root
/// vertex along a spanning tree gives a field that is parallel for the adjusted connection,
/// whose index in every face is exactly k_f / n (as long as every |x_e| < pi: see
/// `largest_adjustment()`).
///
/// **How it is solved.** With omega_e = n rho_e (wrapped into [-pi, pi)) and y = omega + x, the
/// constraints read (d1 y)_f = 2 pi (k_f + m_f) with the integers m_f = ((d1 omega)_f - n K_f) / 2 pi,
/// and integer windings of y along the loops: the periodic 1-form problem that the stripes of
/// `Field_aligned_parameterizer` solve too (`internal::Periodic_one_form_solver`), here with
/// target omega, face integers k + m and uniform edge weights.
/// The pinned graph Laplacian is factored once; changing the singularities and solving again
/// costs O(|E|) plus one back-substitution. The loop holonomies are chosen like the stripe
/// windings: the integers of least adjustment norm (relaxed optimum, then best rounding).
///
/// **Exactness of the field.** The index that `direction_field_singularities()` finds in a face
/// sums, over its edges, the field's turn relative to the transport taken in [-pi, pi): that is
/// x_e only while |x_e| < pi. An edge with |x_e| >= pi (least-norm adjustments reach that next to
/// singularities where the rescaled curvature is large, mostly for n = 4, and on the boundary
/// edge of a singular boundary face) would show as a +1/-1 pair in its two faces, or lose the
/// singularity of its one face: no field on the vertices can turn by pi or more along one edge.
/// So when the least-norm adjustment has an |x_e| above pi - 10^-3, `solve()` adds to x a local
/// correction that keeps every face holonomy and loop winding, the differential u_j - u_i of
/// vertex shifts u, which rotates the field only at vertices near those edges (see
/// `internal::bound_edge_rotations()`; x is then no longer least-norm there); `adjustment()`,
/// `largest_adjustment()` (then at most pi - 10^-3) and `adjustment_norm2()` describe the
/// corrected connection. Such shifts exist unless some closed path of L edges encloses a prescribed
/// rotation (2 pi times the indices inside, minus n times the enclosed curvature) of L pi or more
/// in magnitude, e.g. a single face f with |2 pi k_f - n K_f| >= 3 pi: then no vertex-based field
/// with these singularities exists on this mesh, and `solve()` throws `Invalid_constraints`
/// naming the path.
///
/// **Along the boundary.** With `field_boundary_condition(Direction_field_boundary::tangent)` (or
/// `normal`), the field follows the boundary: at every boundary vertex one of its n directions is
/// the boundary's direction there (that of the boundary edge leaving it, the surface on its left),
/// or the inward normal. The field's rescaled angle is then the same constant at every boundary
/// vertex, so its one-form y is 0 on the boundary edges (x_e = -omega_e there: the field turns
/// with the boundary) and every boundary loop's winding is 0; the rest of the adjustment is of
/// least norm (`internal::Boundary_aligned_one_form`: a Dirichlet problem, its Laplacian factored
/// once more). The windings around handles are still chosen for the problem without the boundary
/// condition.
///
/// With `boundary_smoothing_length(L)` the field follows the boundary's direction smoothed at L
/// instead (`smoothest_direction_field()` takes the same parameter): a boundary that zigzags at a
/// scale below L (a cut through a triangulation, a staircase) is straightened, and its corners are
/// kept where it turns by 67.5 degrees or more within L. The field's rescaled angle at a boundary
/// vertex is then the constant plus n times the smoothed direction's angle from the boundary edge
/// leaving it, y on a boundary edge the transport's omega plus n times the smoothed direction's
/// turn along it (the multiple of 2 pi that turns the field least: a quarter turn at a corner is
/// none for a cross field), and each loop's winding the sum of those, no longer 0. The indices
/// then sum to the corners that the smoothed direction keeps.
///
/// **Consistency.** On a closed component the indices must sum to its Euler characteristic
/// (Poincaré-Hopf); on a component with boundary any sum is allowed (the boundary holonomies
/// absorb it), except with the field along the boundary: then they must sum to the Euler
/// characteristic less 1/n for every convex corner of the boundary that the field turns with in
/// one step, plus 1/n for every concave one (where the boundary turns by 2 pi / n, the n-fold
/// turning 2 pi is read as 0 edge by edge; `required_index_sum()`): 1 on a disk with a smooth
/// boundary, 0 for a cross field on a square (four right-angle corners) or an L (five convex and
/// one concave). By Gauss-Bonnet the sum is n times the total curvature plus the boundary's n-fold
/// turning counted edge by edge, in units of 2 pi. A face holds an
/// index of at most 1/n in magnitude: along each of its three edges a vertex-based field turns by
/// less than pi relative to the transport.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPointMap a readable property map from vertices to `Point_3` (default: the mesh's)
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d` (default
///         `Default_solver_traits`; own object per instance)
///
/// With class template argument deduction, `Trivial_connection tc(mesh, np)` takes both types
/// from the named parameters.
template <class TriangleMesh,
          class VertexPointMap = typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type,
          class SolverTraits = Default_solver_traits>
class Trivial_connection
{
  using Solver = internal::Periodic_one_form_solver<TriangleMesh, SolverTraits>;
  using Indices = internal::Mesh_indices<TriangleMesh>;
  using GT = boost::graph_traits<TriangleMesh>;

public:
  using vertex_descriptor = typename GT::vertex_descriptor;
  using face_descriptor = typename GT::face_descriptor;

  /// Validates the mesh, computes the connection and factors the graph Laplacian. The mesh must
  /// not change while this object is used.
  ///
  /// \param tm a triangle mesh
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
  ///     \cgalParamDescription{the sparse solver that factors the graph Laplacian with one vertex pinned per
  ///                           connected component}
  ///     \cgalParamType{`SolverTraits`, a model of `SparseLinearAlgebraWithFactorTraits_d` (class template
  ///                    argument deduction takes the class's `SolverTraits` from this parameter)}
  ///     \cgalParamDefault{`SolverTraits()`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{symmetry_order}
  ///     \cgalParamDescription{the symmetry order n of the field: 1 vector field, 2 line field, 4 cross field,
  ///                           ...}
  ///     \cgalParamType{`int`}
  ///     \cgalParamDefault{`1` (vector field)}
  ///     \cgalParamExtra{throws `Invalid_parameter` if n < 1}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{field_boundary_condition}
  ///     \cgalParamDescription{`Direction_field_boundary::free` (the loops' holonomies are free),
  ///                           `tangent` or `normal` (the field follows the boundary, see "Along the
  ///                           boundary")}
  ///     \cgalParamType{`Direction_field_boundary`}
  ///     \cgalParamDefault{`Direction_field_boundary::free`}
  ///     \cgalParamExtra{throws `Invalid_parameter` for another value}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{boundary_smoothing_length}
  ///     \cgalParamDescription{with `tangent` or `normal`: the length L at which the boundary's direction is
  ///                           smoothed before the field follows it (see "Along the boundary"; 0: every edge)}
  ///     \cgalParamType{`double`}
  ///     \cgalParamDefault{`0`}
  ///     \cgalParamExtra{throws `Invalid_parameter` if it is negative or not finite}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{vertex_index_map}
  ///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in
  ///                           `[0, num_vertices(tm))`: the numbering of the elements (faces addressed by
  ///                           index, error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_vertex_index_map(tm)`)}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_vertices(tm))`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{halfedge_index_map}
  ///     \cgalParamDescription{a property map associating to each halfedge of `tm` a unique index in
  ///                           `[0, num_halfedges(tm))`: the numbering of the elements (faces addressed by
  ///                           index, error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%halfedge_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_halfedge_index_map(tm)`)}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_halfedges(tm))`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{edge_index_map}
  ///     \cgalParamDescription{a property map associating to each edge of `tm` a unique index in
  ///                           `[0, num_edges(tm))`: the numbering of the elements (faces addressed by index,
  ///                           error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the order of `edges(tm)`}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_edges(tm))`}
  ///   \cgalParamNEnd
  ///   \cgalParamNBegin{face_index_map}
  ///     \cgalParamDescription{a property map associating to each face of `tm` a unique index in
  ///                           `[0, num_faces(tm))`: the numbering of the elements (faces addressed by index,
  ///                           error messages)}
  ///     \cgalParamType{a class model of `ReadablePropertyMap` with
  ///                    `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an integer as
  ///                    value type}
  ///     \cgalParamDefault{the mesh's own (`CGAL::get_initialized_face_index_map(tm)`)}
  ///     \cgalParamExtra{throws `Invalid_mesh` (`Mesh_defect::invalid_index_map`) if it is not a bijection onto
  ///                     `[0, num_faces(tm))`}
  ///   \cgalParamNEnd
  /// \cgalNamedParamsEnd
  ///
  /// \throws Invalid_mesh on bad input, Invalid_parameter if n < 1 or the boundary condition is
  ///         not an enumerator, Linear_solver_failure
  ///
  /// Complexity: O(|E|) plus one sparse factorization of size |V| (two with the field along a
  /// boundary).
  template <class NamedParameters = CGAL::parameters::Default_named_parameters>
  explicit Trivial_connection(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_n(checked_symmetry_order(np)), m_solver(make_solver(tm, np)),
      m_connection(internal::levi_civita_connection(m_solver.indices(),
                                                    internal::class_vertex_point_map<VertexPointMap>(tm, np)))
  {
    const auto& idx = m_solver.indices();
    m_omega.resize(idx.number_of_edges());
    for(std::size_t e = 0; e < m_omega.size(); ++e)
      m_omega[e] = internal::wrap_angle(m_n * m_connection.rho[e]);
    // m_f = ((d1 omega)_f - n K_f) / 2 pi: an integer, since the transport angles sum to K_f mod 2 pi
    m_offset.resize(idx.number_of_faces());
    for(std::size_t f = 0; f < m_offset.size(); ++f)
    {
      double curl = -m_n * m_connection.curvature[f];
      for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
        curl += idx.orientation_sign(h) * m_omega[idx.edge_index(h)];
      m_offset[f] = int(std::lround(curl / internal::two_pi));
    }
    m_index.assign(idx.number_of_faces(), 0);
    m_boundary = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::field_boundary_condition), Direction_field_boundary::free);
    if(m_boundary != Direction_field_boundary::free && m_boundary != Direction_field_boundary::tangent &&
       m_boundary != Direction_field_boundary::normal)
      throw Invalid_parameter("field_boundary_condition", "not a Direction_field_boundary enumerator");
    const double smoothing = internal::require_nonnegative(
      "boundary_smoothing_length",
      CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::boundary_smoothing_length), 0.));
    if(m_boundary != Direction_field_boundary::free && m_solver.number_of_boundary_loops() > 0)
    {
      SolverTraits traits = internal::class_solver_traits<SolverTraits>(np);
      m_aligned.emplace(idx, m_solver.topology(), m_solver.weights(), internal::new_solver_like(traits));
      if(smoothing > 0.)
        follow_smoothed_boundary(tm, np, smoothing);
    }
    m_boundary_winding.assign(m_solver.number_of_boundary_loops(), 0);
    if(m_aligned)
      for(std::size_t b = 0; b < m_boundary_winding.size(); ++b)
      {
        const std::size_t l = m_solver.number_of_generator_loops() + b;
        double sum = 0.;
        for(std::size_t h : m_solver.oriented_loop(l))
          sum += idx.orientation_sign(idx.halfedge(h)) * m_aligned->boundary_y(idx.edge_index(idx.halfedge(h)));
        m_boundary_winding[b] = int(std::lround(sum / internal::two_pi));
      }
    const auto vpm = internal::class_vertex_point_map<VertexPointMap>(tm, np);
    m_centre.resize(idx.number_of_faces());
    for(std::size_t f = 0; f < m_centre.size(); ++f)
    {
      m_centre[f].setZero();
      for(auto v : vertices_around_face(halfedge(idx.face(f), tm), tm))
        m_centre[f] += internal::position(vpm, v) / 3.;
    }
    const std::vector<double> corner = internal::corner_angles(idx, vpm);
    m_largest_angle.assign(idx.number_of_faces(), 0.);
    for(std::size_t h = 0; h < corner.size(); ++h)
      if(!idx.is_border(idx.halfedge(h)))
      {
        double& largest = m_largest_angle[idx.index(face(idx.halfedge(h), tm))];
        largest = (std::max)(largest, corner[h]);
      }
  }

  int symmetry_order() const { return m_n; }

  /// \name Singularities (indices in units of 1/n)
  /// @{
  /// Index numerator k of face `f`: its index is k / n.
  int index(face_descriptor f) const { return m_index[checked_face(f)]; }
  /// Prescribes the index k / n in face `f`. \throws Invalid_constraints if `f` is not a face of the mesh
  void set_index(face_descriptor f, int k) { m_index[checked_face(f)] = k; }
  /// Same, with the face given by its index (the face index map's; for meshes read from a file,
  /// the input order).
  void set_index(std::size_t face_index, int k)
  {
    if(face_index >= m_index.size())
      throw Invalid_constraints("face " + std::to_string(face_index) + " does not exist (the mesh has " +
                                std::to_string(m_index.size()) + " faces)");
    m_index[face_index] = k;
  }
  /// Reads all indices (in units of 1/n) from a face -> integer map.
  template <class FaceIndexMap>
  void set_indices(const FaceIndexMap& k)
  {
    for(std::size_t f = 0; f < m_index.size(); ++f)
      m_index[f] = int(get(k, m_solver.indices().face(f)));
  }
  void clear_indices() { std::fill(m_index.begin(), m_index.end(), 0); }
  /// Moves the singularity of face `from` to face `to` (adding its index to that of `to`).
  void move_singularity(face_descriptor from, face_descriptor to)
  {
    const std::size_t a = checked_face(from), b = checked_face(to);
    const int k = m_index[a];
    m_index[a] = 0;
    m_index[b] += k;
  }
  /// @}

  /// Makes the singularities at least `distance` apart (between the centroids of their faces),
  /// as a quad mesh needs its cones (two cones of a quad mesh with edge length h are at least about
  /// h apart): while two are closer, the closest pair is removed if its indices cancel, and
  /// otherwise (or if no field exists without them) one of them moves to the face within 2 `distance` that is farthest from all other
  /// singularities. A change after which no field exists (see `solve()`: a small region of large
  /// curvature needs its singularity) is undone, and a pair that can neither go nor move is kept.
  /// Then solves.
  /// \throws Invalid_parameter if `distance` is not finite and positive; Invalid_constraints from
  ///         `solve()` if the singularities before the separation admit no field
  ///
  /// Complexity: one `solve()` per change, plus O(singularities² + faces) per change.
  Singularity_separation separate_singularities(double distance)
  {
    if(!std::isfinite(distance) || !(distance > 0.))
      throw Invalid_parameter("distance", "must be finite and positive, got " + std::to_string(distance));
    solve();
    const Singularity_separation result = internal::separate_singularities(m_index, m_centre, distance, [&] {
      try
      {
        solve();
        return true;
      }
      catch(const Invalid_constraints&)
      {
        return false;
      }
    });
    solve();
    return result;
  }

  /// Moves every singularity of negative index out of a face with an angle of `angle` or more
  /// (radians) into the adjacent face without a singularity whose largest angle is the smallest,
  /// if it is smaller, then solves. Field-aligned quads need it: the quads' map around a cone of
  /// index -k/n widens the angles at its branch point by 1 + k/n, and from inside a face the edge
  /// opposite an angle A is seen under more than A, so a -1/4 cone in a face with an angle past
  /// 144 degrees folds the map for good (stiffening cannot undo it). Where the moved singularities
  /// admit no field, they go back where they were.
  /// \returns the number of singularities moved (0 if they went back)
  /// \throws Invalid_parameter if `angle` is not in (0, pi]; Invalid_constraints from `solve()` if
  ///         the singularities before the move admit no field
  ///
  /// Complexity: O(|F|) plus one or two `solve()`.
  std::size_t move_singularities_from_wide_faces(double angle = 2. * internal::pi / 3.)
  {
    if(!std::isfinite(angle) || !(angle > 0.) || angle > internal::pi)
      throw Invalid_parameter("angle", "must lie in (0, pi], got " + std::to_string(angle));
    solve();
    const auto& idx = m_solver.indices();
    const TriangleMesh& tm = idx.mesh();
    std::vector<std::pair<std::size_t, std::size_t>> moves; // from, to
    for(std::size_t f = 0; f < m_index.size(); ++f)
    {
      if(m_index[f] >= 0 || m_largest_angle[f] < angle)
        continue;
      std::size_t best = f;
      for(auto h : halfedges_around_face(halfedge(idx.face(f), tm), tm))
      {
        const auto g = face(opposite(h, tm), tm);
        if(g == boost::graph_traits<TriangleMesh>::null_face())
          continue;
        const std::size_t gi = idx.index(g);
        if(m_index[gi] == 0 && m_largest_angle[gi] < m_largest_angle[best])
          best = gi;
      }
      if(best != f)
      {
        m_index[best] = m_index[f];
        m_index[f] = 0;
        moves.emplace_back(f, best);
      }
    }
    if(moves.empty())
      return 0;
    try
    {
      solve();
      return moves.size();
    }
    catch(const Invalid_constraints&)
    {
      for(auto m = moves.rbegin(); m != moves.rend(); ++m) // last first: a singularity may have moved twice
      {
        m_index[m->first] = m_index[m->second];
        m_index[m->second] = 0;
      }
      solve();
      return 0;
    }
  }

  /// Rotates the whole field by `angle` (radians, in the rescaled angles of the frames); the
  /// field is otherwise determined up to this rotation per connected component. With the field
  /// along the boundary, the components with a boundary are not rotated.
  /// \throws Invalid_parameter if `angle` is not finite
  void set_rotation(double angle) { m_rotation = internal::require_finite("rotation", angle); }

  /// Computes the connection and the field. O(|E|) plus one back-substitution (plus a local
  /// correction where an adjustment would reach pi, see "Exactness of the field"); with the field
  /// along the boundary two more, and O(|E|) per boundary loop beyond the first of a component.
  /// \throws Invalid_constraints if the indices of a closed component do not sum to its Euler
  /// characteristic (or, with the field along the boundary, those of a component with boundary
  /// to `required_index_sum()`), or if no vertex-based field has these singularities on this mesh
  /// (with the field along the boundary: also where the boundary turns half-way between two of
  /// the field's directions along one edge, e.g. a right angle for n = 2, which no such field
  /// follows; and the search for shifts that keep the boundary still is local, not exhaustive)
  void solve()
  {
    for(std::size_t f = 0; f < m_index.size(); ++f)
      if(std::abs(m_index[f]) > 1)
        throw Invalid_constraints(
          "face " + std::to_string(f) + " has index " + index_text(m_index[f]) + ", but a triangle can hold at most " +
          index_text(1) + " in magnitude: the field turns by less than pi along each of its three edges; "
          "spread a larger index over several faces");
    // (before the sums: at such a corner the sum the boundary asks is not defined)
    if(m_aligned)
      if(const std::size_t e = m_aligned->sharp_turn(m_omega, internal::pi - rotation_margin); e != internal::npos)
      {
        const auto [a, b] = m_solver.indices().edge_vertices(e);
        throw Invalid_constraints("the boundary turns by about " + std::to_string(int(std::lround(180. / m_n))) +
                                  " degrees at its edge " + std::to_string(e) + " (vertices " + std::to_string(a) +
                                  " and " + std::to_string(b) + "), half-way between two directions of the field: a "
                                  "field of symmetry order " + std::to_string(m_n) + " cannot follow the boundary there");
      }
    const auto& topo = m_solver.topology();
    std::vector<long> sum(topo.components.size(), 0);
    for(std::size_t f = 0; f < m_index.size(); ++f)
      sum[topo.components.face_component[f]] += m_index[f];
    for(std::size_t c = 0; c < sum.size(); ++c)
    {
      const auto& info = topo.components.info[c];
      const long chi = info.euler_characteristic();
      if(info.is_closed() && sum[c] != m_n * chi)
      {
        std::ostringstream s;
        s << "on connected component " << c << " (" << info.faces << " faces, closed, Euler characteristic "
          << chi << ") the singularity indices sum to " << index_text(sum[c])
          << " but must sum to " << chi << " (Poincaré-Hopf)";
        throw Invalid_constraints(s.str());
      }
      const std::optional<long> required = required_index_sum(c);
      if(!info.is_closed() && required && sum[c] != *required)
      {
        std::ostringstream s;
        s << "on connected component " << c << " (" << info.faces << " faces, " << info.boundary_loops
          << " boundary loops, Euler characteristic " << chi << ") the singularity indices sum to " << index_text(sum[c])
          << " but must sum to " << index_text(*required) << " for a field along the boundary (Poincaré-Hopf: the "
          << "Euler characteristic, less the boundary's corners that the field turns with in one step)";
        throw Invalid_constraints(s.str());
      }
    }
    std::vector<int> k(m_index.size());
    for(std::size_t f = 0; f < k.size(); ++f)
      k[f] = m_index[f] + m_offset[f];
    // along the boundary: every boundary loop's winding is 0 (see "Along the boundary")
    std::vector<std::optional<int>> windings(m_solver.number_of_loops());
    if(m_aligned)
      for(std::size_t l = m_solver.number_of_generator_loops(); l < windings.size(); ++l)
        windings[l] = m_boundary_winding[l - m_solver.number_of_generator_loops()];
    typename Solver::Solution s = m_solver.solve(m_omega, k, windings);
    if(m_aligned)
    {
      m_aligned->correct(m_solver.indices(), topo, s.y, m_omega, m_solver.integrate(s.y));
      s.energy = m_solver.energy(s.y, m_omega);
    }
    bound_adjustment(s);
    std::vector<double> alpha = m_solver.integrate(s.y);
    if(m_aligned) // the constant of the boundary condition at the first boundary vertex of each component
    {
      const double value = m_boundary == Direction_field_boundary::normal ? m_n * internal::pi / 2. : 0.;
      std::vector<double> shift(topo.components.size(), 0.);
      std::vector<bool> done(topo.components.size(), false);
      for(const auto& loop : topo.boundary.loops)
      {
        const std::size_t v = m_solver.indices().source_index(m_solver.indices().halfedge(loop.front()));
        const std::size_t c = topo.components.vertex_component[v];
        if(!done[c])
          shift[c] = value + m_aligned->alpha_offset(v) - alpha[v];
        done[c] = true;
      }
      for(std::size_t v = 0; v < alpha.size(); ++v)
        alpha[v] += shift[topo.components.vertex_component[v]];
    }
    for(double& a : alpha)
      a = internal::wrap_angle(a);
    m_solution = std::move(s);
    m_alpha = std::move(alpha);
    m_solved = true;
  }

  bool is_solved() const { return m_solved; }

  /// The sum of the index numerators (units of 1/n) that component `c` must have: n times its
  /// Euler characteristic if it is closed; with the field along the boundary,
  /// -sum_f (d1 omega - n K)_f / 2 pi over its faces (see "Consistency"); `std::nullopt` on a
  /// component with boundary otherwise (any sum).
  /// \throws Invalid_parameter if `c` is not a component index
  std::optional<long> required_index_sum(std::size_t c) const
  {
    const auto& topo = m_solver.topology();
    if(c >= topo.components.size())
      throw Invalid_parameter("component", std::to_string(c) + " is not a component index (the mesh has " +
                                             std::to_string(topo.components.size()) + ")");
    if(!topo.components.info[c].is_closed() && !m_aligned)
      return std::nullopt;
    long sum = 0;
    for(std::size_t f = 0; f < m_offset.size(); ++f)
      if(topo.components.face_component[f] == c)
        sum -= m_offset[f];
    // (Stokes: the boundary windings, 0 unless the boundary is smoothed)
    for(std::size_t b = 0; b < m_boundary_winding.size(); ++b)
      if(m_solver.loop_component(m_solver.number_of_generator_loops() + b) == c)
        sum += m_boundary_winding[b];
    return sum;
  }

  /// The boundary condition given to the constructor.
  Direction_field_boundary boundary_condition() const { return m_boundary; }

  /// Angle of the field at vertex `v` (one of its n directions) in the rescaled vertex frame.
  double angle(vertex_descriptor v) const
  {
    require_solved();
    const std::size_t i = m_solver.indices().index(v);
    const bool fixed = m_aligned && !m_solver.topology().components.info[m_solver.topology().components.vertex_component[i]].is_closed();
    return (m_alpha[i] + (fixed ? 0. : m_rotation)) / m_n;
  }

  /// Writes one of the field's n directions per vertex, as a unit tangent vector.
  template <class VertexVectorMap>
  void field(VertexVectorMap out) const
  {
    require_solved();
    const auto& idx = m_solver.indices();
    std::vector<double> a(idx.number_of_vertices());
    for(std::size_t v = 0; v < a.size(); ++v)
      a[v] = angle(idx.vertex(v));
    internal::write_field(idx, m_connection.frames, a, {}, out);
  }

  /// The adjustment x_e of the n-fold transport per edge index (edge orientation: smaller to larger
  /// vertex index); the rotation of a single direction is adjusted by x_e / n.
  std::vector<double> adjustment() const
  {
    require_solved();
    std::vector<double> x = m_solution.y;
    for(std::size_t e = 0; e < x.size(); ++e)
      x[e] -= m_omega[e];
    return x;
  }
  /// max_e |x_e|: at most pi - 10^-3 after a successful `solve()`, so that every face has exactly
  /// its prescribed index (see "Exactness of the field").
  double largest_adjustment() const
  {
    double m = 0.;
    for(double x : adjustment())
      m = (std::max)(m, std::abs(x));
    return m;
  }
  /// sum_e x_e^2: the least-squares norm that the solve minimized, or that of the corrected
  /// adjustment when an |x_e| had to be brought below pi.
  double adjustment_norm2() const
  {
    require_solved();
    return m_solution.energy;
  }

  /// \name Internal data, for tests (unstable: may change without notice)
  /// @{
  const internal::Mesh_indices<TriangleMesh>& indices() const { return m_solver.indices(); }
  const internal::Discrete_connection& connection() const { return m_connection; }
  const internal::Topology& topology() const { return m_solver.topology(); }
  /// @}

private:
  // The field along the boundary smoothed at `length` (`internal::smoothed_boundary()`): at a
  // boundary vertex alpha = c + n times the smoothed direction's offset, and y on a boundary edge
  // (from vertex i to j, the surface on the left) the transport's omega plus n times the smoothed
  // direction's turn, the multiple of 2 pi taken that turns the field least (a corner's quarter
  // turn is no turn of a cross field)
  template <class NamedParameters>
  void follow_smoothed_boundary(const TriangleMesh& tm, const NamedParameters& np, double length)
  {
    const auto& idx = m_solver.indices();
    const internal::Smoothed_boundary sb = internal::smoothed_boundary(
      idx, internal::class_vertex_point_map<VertexPointMap>(tm, np), m_solver.topology().boundary, length);
    std::vector<double> y(idx.number_of_edges(), 0.), alpha(idx.number_of_vertices(), 0.);
    for(std::size_t v = 0; v < alpha.size(); ++v)
      alpha[v] = m_n * sb.offset[v];
    for(const auto& loop : m_solver.topology().boundary.loops)
      for(std::size_t h : loop)
      {
        const auto inner = opposite(idx.halfedge(h), tm); // from vertex i to j, the surface on its left
        const std::size_t e = idx.edge_index(inner);
        y[e] = m_omega[e] + idx.orientation_sign(inner) * internal::wrap_angle(m_n * sb.turning[e]);
      }
    m_aligned->set_boundary_values(std::move(y), std::move(alpha));
  }

  template <class NamedParameters>
  static int checked_symmetry_order(const NamedParameters& np)
  {
    const int n = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::symmetry_order), 1);
    internal::check_symmetry_order(n);
    return n;
  }

  template <class NamedParameters>
  static Solver make_solver(const TriangleMesh& tm, const NamedParameters& np)
  {
    Indices idx(tm, np);
    internal::validate_mesh(idx, internal::class_vertex_point_map<VertexPointMap>(tm, np));
    const std::size_t ne = idx.number_of_edges();
    return Solver(std::move(idx), std::vector<double>(ne, 1.), internal::class_solver_traits<SolverTraits>(np),
                  "pinned graph Laplacian of the trivial connection");
  }

  // Largest |x_e| of the written field; some margin below pi, so that the field's rotation along
  // every edge is still read as x_e (not x_e -+ 2 pi) after the round trip through 3D vectors.
  static constexpr double rotation_margin = 1e-3;

  // Brings every |x_e| = |y_e - omega_e| to at most pi - rotation_margin by adding the differential
  // of vertex shifts (same face holonomies and loop windings, so the same singularities; see
  // "Exactness of the field"), or throws. Leaves s untouched when the bound already holds.
  void bound_adjustment(typename Solver::Solution& s) const
  {
    const auto& idx = m_solver.indices();
    const double bound = internal::pi - rotation_margin;
    std::vector<double> x(s.y.size());
    bool within = true;
    for(std::size_t e = 0; e < x.size(); ++e)
    {
      x[e] = s.y[e] - m_omega[e];
      within = within && std::abs(x[e]) <= bound;
    }
    if(within)
      return;
    internal::Edge_rotation_bound r = internal::bound_edge_rotations(idx, x, bound);
    if(!r.cycle.empty())
      throw Invalid_constraints(obstruction(r.cycle, x, bound));
    if(m_aligned && moves_boundary(r.u))
      r.u = boundary_keeping_shifts(x, bound, std::move(r.u));
    const std::vector<double>& w = m_solver.weights();
    s.energy = 0.;
    for(std::size_t e = 0; e < x.size(); ++e)
    {
      const auto ij = idx.edge_vertices(e);
      s.y[e] += r.u[ij.second] - r.u[ij.first];
      s.energy += w[e] * (s.y[e] - m_omega[e]) * (s.y[e] - m_omega[e]);
    }
  }

  // The message for a closed path of the mesh (vertex indices `cycle`) along which the edges would
  // have to turn by more than `bound` each: the faces it encloses (the smaller side), their index
  // sum and curvature, and the index sums that would fit.
  std::string obstruction(const std::vector<std::size_t>& cycle, const std::vector<double>& x, double bound) const
  {
    const auto& idx = m_solver.indices();
    const auto& tm = idx.mesh();
    const std::size_t L = cycle.size();
    std::vector<bool> on_path(idx.number_of_edges(), false);
    std::size_t first = internal::npos; // a halfedge of the path
    double turn = 0.;
    for(std::size_t i = 0; i < L; ++i)
      for(auto h : halfedges_around_source(idx.vertex(cycle[i]), tm))
        if(idx.target_index(h) == cycle[(i + 1) % L])
        {
          on_path[idx.edge_index(h)] = true;
          turn += idx.orientation_sign(h) * x[idx.edge_index(h)];
          first = first == internal::npos ? idx.index(h) : first;
          break;
        }
    // the faces on either side of the first path edge, reached without crossing the path; the
    // smaller side is the region the path encloses if its boundary is the path alone
    auto side = [&](auto h) {
      std::vector<std::size_t> faces;
      if(idx.is_border(h))
        return faces;
      std::vector<bool> seen(idx.number_of_faces(), false);
      faces.push_back(idx.index(face(h, tm)));
      seen[faces.back()] = true;
      for(std::size_t i = 0; i < faces.size(); ++i)
        for(auto g : halfedges_around_face(halfedge(idx.face(faces[i]), tm), tm))
        {
          const auto o = opposite(g, tm);
          if(!on_path[idx.edge_index(g)] && !idx.is_border(o) && !seen[idx.index(face(o, tm))])
          {
            seen[idx.index(face(o, tm))] = true;
            faces.push_back(idx.index(face(o, tm)));
          }
        }
      return faces;
    };
    const auto h0 = idx.halfedge(first);
    std::vector<std::size_t> inside = side(h0), outside = side(opposite(h0, tm));
    if(inside.empty() || (!outside.empty() && outside.size() < inside.size()))
      std::swap(inside, outside);
    bool enclosed = outside.empty() || std::find(inside.begin(), inside.end(), outside.front()) == inside.end();
    for(std::size_t i = 0; enclosed && i < inside.size(); ++i)
      for(auto g : halfedges_around_face(halfedge(idx.face(inside[i]), tm), tm))
        enclosed = enclosed && (!idx.is_border(opposite(g, tm)) || on_path[idx.edge_index(g)]);
    std::ostringstream m;
    m << "no vertex-based field has these singularities on this mesh: along every edge a field on the vertices "
         "turns by less than pi relative to the transport, but along the closed path of "
      << L << " edges through vertices";
    for(std::size_t i = 0; i < L && i < 12; ++i)
      m << ' ' << cycle[i];
    m << (L > 12 ? " ..." : "") << " it would have to turn by " << std::abs(turn) << " rad (" << std::abs(turn) / internal::pi
      << " pi)";
    if(!enclosed)
    {
      m << "; choose other singularities or refine the mesh";
      return m.str();
    }
    // Stokes: that turn is 2 pi (indices inside) - n (curvature inside)
    long k = 0;
    double curvature = 0.;
    for(std::size_t f : inside)
    {
      k += m_index[f];
      curvature += m_connection.curvature[f];
    }
    m << ": the " << inside.size() << " faces it encloses (";
    for(std::size_t i = 0; i < inside.size() && i < 12; ++i)
      m << (i ? " " : "") << inside[i];
    m << (inside.size() > 12 ? " ..." : "") << ") have indices summing to " << index_text(k) << " and curvature "
      << curvature << " rad; indices summing to";
    const long lo = long(std::floor((m_n * curvature - L * bound) / internal::two_pi)) + 1;
    const long hi = long(std::ceil((m_n * curvature + L * bound) / internal::two_pi)) - 1;
    for(long j = lo; j <= hi; ++j) // at least one: the interval is 3 (pi - margin) / pi > 2 wide
      m << (j > lo ? (j < hi ? "," : " or") : "") << ' ' << index_text(j);
    m << " there would fit (balanced elsewhere); or refine the mesh there";
    return m.str();
  }

  std::size_t checked_face(face_descriptor f) const
  {
    const std::size_t i = m_solver.indices().find(f);
    if(i == internal::npos)
      throw Invalid_constraints("the face is not a face of this mesh");
    return i;
  }
  void require_solved() const
  {
    if(!m_solved)
      throw Invalid_constraints("solve() has not been called");
  }
  // Shifts that bound the rotations and keep the boundary vertices in place, from `down` (the
  // largest shifts <= 0, which move some boundary vertex) and the smallest >= 0 (of -x, negated):
  // both are 0 but around the edges past the bound, so on each connected piece of the vertices
  // that either moves, the one that keeps the piece's boundary vertices still is taken, and the
  // combination checked edge by edge. \throws Invalid_constraints where none is found
  std::vector<double> boundary_keeping_shifts(const std::vector<double>& x, double bound, std::vector<double> down) const
  {
    const auto& idx = m_solver.indices();
    const std::size_t nv = idx.number_of_vertices(), ne = x.size();
    std::vector<double> minus_x(ne);
    for(std::size_t e = 0; e < ne; ++e)
      minus_x[e] = -x[e];
    internal::Edge_rotation_bound up = internal::bound_edge_rotations(idx, minus_x, bound);
    for(double& u : up.u)
      u = -u;
    std::size_t blocked = internal::npos; // a boundary vertex that no choice keeps still
    std::vector<double> u(nv, 0.);
    if(up.cycle.empty())
    {
      // the pieces: vertices that move in either, joined along edges
      internal::Union_find pieces(nv);
      for(std::size_t e = 0; e < ne; ++e)
      {
        const auto [i, j] = idx.edge_vertices(e);
        const bool mi = down[i] != 0. || up.u[i] != 0., mj = down[j] != 0. || up.u[j] != 0.;
        if(mi && mj)
          pieces.unite(i, j);
      }
      std::vector<bool> down_moves(nv, false), up_moves(nv, false);
      for(std::size_t v = 0; v < nv; ++v)
        if(m_aligned->on_boundary(v))
        {
          down_moves[pieces.find(v)] = down_moves[pieces.find(v)] || down[v] != 0.;
          up_moves[pieces.find(v)] = up_moves[pieces.find(v)] || up.u[v] != 0.;
        }
      for(std::size_t v = 0; v < nv && blocked == internal::npos; ++v)
      {
        const std::size_t p = pieces.find(v);
        if(!down_moves[p])
          u[v] = down[v];
        else if(!up_moves[p])
          u[v] = up.u[v];
        else if(m_aligned->on_boundary(v))
          blocked = v;
      }
    }
    for(std::size_t e = 0; e < ne && blocked == internal::npos; ++e)
    {
      const auto [i, j] = idx.edge_vertices(e);
      if(!(std::abs(x[e] + u[j] - u[i]) <= bound))
        blocked = i;
    }
    if(blocked == internal::npos)
      return u;
    throw Invalid_constraints(
      "no vertex-based field along the boundary has these singularities on this mesh: along every edge a field "
      "on the vertices turns by less than pi relative to the transport, and next to the boundary (near vertex " +
      std::to_string(blocked == internal::npos ? 0 : blocked) + ") no field that keeps to the boundary does; choose "
      "other singularities (farther from the boundary) or refine the mesh there");
  }

  bool moves_boundary(const std::vector<double>& u) const
  {
    for(std::size_t v = 0; v < u.size(); ++v)
      if(u[v] != 0. && m_aligned->on_boundary(v))
        return true;
    return false;
  }

  std::string index_text(long k) const
  {
    return m_n == 1 ? std::to_string(k) : std::to_string(k) + "/" + std::to_string(m_n);
  }

  int m_n;
  Solver m_solver;
  internal::Discrete_connection m_connection;
  std::vector<double> m_omega; // n rho wrapped into [-pi, pi)
  std::vector<int> m_offset, m_index;
  std::vector<Eigen::Vector3d> m_centre; // of every face
  std::vector<double> m_largest_angle;   // of every face, radians
  double m_rotation = 0.;
  Direction_field_boundary m_boundary = Direction_field_boundary::free;
  std::vector<int> m_boundary_winding; // per boundary loop: y's winding along it (field along the boundary)
  // with the field along the boundary, on a mesh with one
  std::optional<internal::Boundary_aligned_one_form<Indices, SolverTraits>> m_aligned;
  bool m_solved = false;
  typename Solver::Solution m_solution;
  std::vector<double> m_alpha; // n times the field angle, in [-pi, pi)
};

/// Deduces the point map and solver types from the named parameters.
template <class TriangleMesh, class NamedParameters>
Trivial_connection(const TriangleMesh&, const NamedParameters&)
  -> Trivial_connection<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                        internal::Solver_traits_t<NamedParameters>>;
template <class TriangleMesh>
Trivial_connection(const TriangleMesh&) -> Trivial_connection<TriangleMesh>;

/// \ingroup PkgDirectionFieldsRef
///
/// One-call trivial connection: writes to `field` a unit vertex-based n-direction field (one of
/// its n directions per vertex) whose singularities are exactly the faces f with
/// `get(face_indices, f) != 0`, of index `get(face_indices, f) / n`. See `Trivial_connection`.
///
/// \param tm a triangle mesh
/// \param face_indices a readable face -> integer map: the indices in units of 1/n
/// \param field a writable vertex -> `Vector_3` map (output), written only on success
/// \param np an optional sequence of named parameters: exactly those of the `Trivial_connection`
///        constructor (`vertex_point_map`, `sparse_linear_solver`, `symmetry_order` and the four
///        index maps), with the same types, defaults and checks
///
/// \returns the largest adjustment (see `Trivial_connection::largest_adjustment()`)
/// \throws Invalid_mesh, Invalid_parameter, Invalid_constraints, Linear_solver_failure as
///         `Trivial_connection` and its `solve()`
///
/// Complexity: one sparse factorization of size |V| and O(|E|) work.
template <class TriangleMesh, class FaceIndexMap, class VertexVectorMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
double trivial_connection_field(const TriangleMesh& tm, const FaceIndexMap& face_indices, VertexVectorMap field,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  Trivial_connection<TriangleMesh, internal::Const_vertex_point_map_t<TriangleMesh, NamedParameters>,
                     internal::Solver_traits_t<NamedParameters>>
    tc(tm, np);
  tc.set_indices(face_indices);
  tc.solve();
  tc.field(field);
  return tc.largest_adjustment();
}

} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_TRIVIAL_CONNECTION_H
