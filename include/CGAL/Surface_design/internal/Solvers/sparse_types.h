// Copyright (c) 2026 The CGAL Surface Design authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sparse matrix types of the library's systems (Eigen, column-major), and the assembly of
// matrices of one pattern from triplets again and again.

#ifndef CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SPARSE_TYPES_H
#define CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SPARSE_TYPES_H

#include <Eigen/SparseCore>

#include <algorithm>
#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_design {
namespace internal {

using Sparse_matrix = Eigen::SparseMatrix<double>;
using Complex_sparse_matrix = Eigen::SparseMatrix<std::complex<double>>;

/// Assembles a compressed sparse matrix from triplets (duplicates summed). The first call sorts
/// them (`setFromTriplets()`) and remembers where each lands; a later call with the same sequence
/// of positions (a system whose weights changed) only adds the values into those slots.
class Triplet_assembler
{
public:
  Sparse_matrix assemble(const std::vector<Eigen::Triplet<double>>& triplets, Eigen::Index rows, Eigen::Index cols)
  {
    if(!same_positions(triplets, rows, cols))
      analyse(triplets, rows, cols);
    Sparse_matrix a = m_pattern;
    double* value = a.valuePtr();
    std::fill(value, value + a.nonZeros(), 0.);
    for(std::size_t t = 0; t < triplets.size(); ++t)
      value[m_slot[t]] += triplets[t].value();
    return a;
  }

private:
  bool same_positions(const std::vector<Eigen::Triplet<double>>& triplets, Eigen::Index rows, Eigen::Index cols) const
  {
    if(m_slot.size() != triplets.size() || m_pattern.rows() != rows || m_pattern.cols() != cols)
      return false;
    for(std::size_t t = 0; t < triplets.size(); ++t)
      if(m_position[t].first != int(triplets[t].row()) || m_position[t].second != int(triplets[t].col()))
        return false;
    return true;
  }

  void analyse(const std::vector<Eigen::Triplet<double>>& triplets, Eigen::Index rows, Eigen::Index cols)
  {
    m_pattern = Sparse_matrix(rows, cols);
    m_pattern.setFromTriplets(triplets.begin(), triplets.end());
    m_pattern.makeCompressed(); // the rows of every column sorted
    m_slot.resize(triplets.size());
    m_position.resize(triplets.size());
    const int* outer = m_pattern.outerIndexPtr();
    const int* inner = m_pattern.innerIndexPtr();
    for(std::size_t t = 0; t < triplets.size(); ++t)
    {
      const int r = int(triplets[t].row()), c = int(triplets[t].col());
      m_slot[t] = std::size_t(std::lower_bound(inner + outer[c], inner + outer[c + 1], r) - inner);
      m_position[t] = {r, c};
    }
  }

  Sparse_matrix m_pattern;
  std::vector<std::size_t> m_slot;
  std::vector<std::pair<int, int>> m_position;
};

} // namespace internal
} // namespace Surface_design
} // namespace CGAL

#endif // CGAL_SURFACE_DESIGN_INTERNAL_SOLVERS_SPARSE_TYPES_H
