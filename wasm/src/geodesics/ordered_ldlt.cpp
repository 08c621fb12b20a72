#include "geodesics/ordered_ldlt.h"

#include "geometrycentral/numerical/linear_algebra_utilities.h"

#include <cmath>
#include <stdexcept>

namespace cscd {

OrderedLDLT::OrderedLDLT(Eigen::SparseMatrix<double>& matrix) {
  if (matrix.rows() != matrix.cols()) throw std::logic_error("OrderedLDLT: the matrix is not square");
  // geometry-central's PositiveDefiniteSolver checks, with its tolerance.
  geometrycentral::checkFinite(matrix);
  geometrycentral::checkHermitian(matrix);
  matrix.makeCompressed();
  ldlt.compute(matrix);
  if (ldlt.info() != Eigen::Success) throw std::invalid_argument("OrderedLDLT: the factorization failed");
}

void OrderedLDLT::solveInPlace(Eigen::VectorXd& x) const {
  for (Eigen::Index i = 0; i < x.size(); i++)
    if (!std::isfinite(x[i])) throw std::logic_error("OrderedLDLT: a non-finite right-hand side");
  // SimplicialLDLT::_solve_impl's steps between its two permutations, in its order.
  ldlt.matrixL().solveInPlace(x);
  x = ldlt.vectorD().asDiagonal().inverse() * x;
  ldlt.matrixU().solveInPlace(x);
}

} // namespace cscd
