#pragma once

#include <Eigen/SparseCholesky>

#include <cstddef>

namespace cscd {

// A sparse symmetric positive definite matrix A factored as Eigen's SimplicialLDLT does (AMD ordering,
// P A Pᵀ = L D Lᵀ), solved in the factor's own order: the caller writes the right-hand side at
// position(row) and reads the solution there. Eigen's solve permutes the whole vector on the way in
// and out; for the heat method's sparse sources and per-face gathers that was a tenth of a distance's
// time on a 20,000-vertex mesh. The arithmetic is Eigen's, so the solutions are the same numbers.
class OrderedLDLT {
public:
  // Throws if the matrix is not square, finite and symmetric (std::logic_error, as geometry-central's
  // solvers) or if the factorization fails (std::invalid_argument).
  explicit OrderedLDLT(Eigen::SparseMatrix<double>& matrix);

  // Where a row of the matrix is in the factor's order.
  size_t position(size_t row) const { return size_t(ldlt.permutationP().indices()[Eigen::Index(row)]); }

  // x: a right-hand side in the factor's order, replaced by the solution (in that order). Throws
  // std::logic_error on a non-finite entry (as geometry-central's solvers).
  void solveInPlace(Eigen::VectorXd& x) const;

private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
};

} // namespace cscd
