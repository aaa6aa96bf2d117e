// SPDX-License-Identifier: GPL-3.0-or-later
#include "shifted_factor.hpp"

#include <Eigen/SparseCholesky>
#include <limits>

#if IMPULSELAB_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace impulse::detail {

using Eigen::Index;
using Eigen::VectorXd;
using SparseMatrix = Eigen::SparseMatrix<double>;

#if IMPULSELAB_HAVE_CHOLMOD

namespace {

// CHOLMOD's Cholesky through Eigen's CholmodSupport, which keeps the factor to itself: this
// subclass reads its pivots. Simplicial L D L^T always: CHOLMOD's own choice (supernodal, with
// dense blocks and the BLAS, where the factor does much work per nonzero) took the pyramid's
// G G^T of 100,000 contacts in 190 to 450 ms of CPU against 140 ms simplicial, and its A in
// 660 against 450 ms, on the 2-core machine with Debian's reference BLAS, where its OpenMP
// threads (four, fixed when CHOLMOD was built) cost more than they gain (bench/README.md). The
// ordering is CHOLMOD's default choice: AMD, and METIS' nested dissection as well when AMD leaves
// much fill (on the generated stacks, cradles and pyramids it does not: METIS' analysis alone
// took longer than the whole factorisation with AMD, for the same fill).
class Simplicial : public Eigen::CholmodBase<SparseMatrix, Eigen::Lower, Simplicial> {
  using Base = Eigen::CholmodBase<SparseMatrix, Eigen::Lower, Simplicial>;
  using Base::m_cholmod;
  using Base::m_cholmodFactor;

 public:
  Simplicial() {
    m_cholmod.final_asis = 1;
    m_cholmod.supernodal = CHOLMOD_SIMPLICIAL;
    m_cholmod.print = 0;  // failures are returned, never printed
  }
  ~Simplicial() {
    cholmod_free_dense(&solution_, &m_cholmod);
    cholmod_free_dense(&work_y_, &m_cholmod);
    cholmod_free_dense(&work_e_, &m_cholmod);
  }
  Simplicial(const Simplicial&) = delete;
  Simplicial& operator=(const Simplicial&) = delete;

  // The factor's solve into x, by cholmod_solve2 with its solution and workspace kept (Eigen's
  // solve calls cholmod_solve, which allocates and frees them at every call).
  void solve_into(const VectorXd& b, VectorXd& x) {
    cholmod_dense rhs{};
    rhs.nrow = static_cast<std::size_t>(b.size());
    rhs.ncol = 1;
    rhs.nzmax = rhs.nrow;
    rhs.d = rhs.nrow;
    rhs.x = const_cast<double*>(b.data());  // read only: CHOLMOD's right-hand side is not const
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    x.resize(b.size());
    if (cholmod_solve2(CHOLMOD_A, m_cholmodFactor, &rhs, nullptr, &solution_, nullptr, &work_y_,
                       &work_e_, &m_cholmod) == 0) {
      x.setConstant(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    x = Eigen::Map<const VectorXd>(static_cast<const double*>(solution_->x), b.size());
  }

  // The pivots: D of the simplicial L D L^T, on L's diagonal (the squares of L's diagonal had
  // CHOLMOD made L L^T).
  [[nodiscard]] VectorXd pivots() const {
    const cholmod_factor& L = *m_cholmodFactor;
    VectorXd d(static_cast<Index>(L.n));
    const auto* x = static_cast<const double*>(L.x);
    const auto* p = static_cast<const int*>(L.p);
    for (Index j = 0; j < d.size(); ++j) {
      const double diagonal = x[p[j]];
      d(j) = L.is_ll != 0 ? diagonal * diagonal : diagonal;
    }
    return d;
  }

 private:
  cholmod_dense* solution_ = nullptr;
  cholmod_dense* work_y_ = nullptr;
  cholmod_dense* work_e_ = nullptr;
};

}  // namespace

struct ShiftedFactor::Backend {
  Simplicial factor;
};

bool ShiftedFactor::compute(const SparseMatrix& M, double lambda) {
  backend_ = std::make_unique<Backend>();
  backend_->factor.setShift(lambda);  // CHOLMOD factors M + lambda I without forming it
  backend_->factor.compute(M);
  return backend_->factor.info() == Eigen::Success;
}

void ShiftedFactor::solve(const VectorXd& r, VectorXd& x) const {
  backend_->factor.solve_into(r, x);
}

VectorXd ShiftedFactor::pivots() const {
  return backend_->factor.pivots();
}

#else

struct ShiftedFactor::Backend {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int> > factor;
};

bool ShiftedFactor::compute(const SparseMatrix& M, double lambda) {
  backend_ = std::make_unique<Backend>();
  backend_->factor.setShift(lambda);  // factors M + lambda I without forming it
  backend_->factor.compute(M);
  return backend_->factor.info() == Eigen::Success;
}

void ShiftedFactor::solve(const VectorXd& r, VectorXd& x) const {
  x = backend_->factor.solve(r);
  if (backend_->factor.info() != Eigen::Success) {
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
}

VectorXd ShiftedFactor::pivots() const {
  return backend_->factor.vectorD();
}

#endif

ShiftedFactor::ShiftedFactor() = default;
ShiftedFactor::~ShiftedFactor() = default;

}  // namespace impulse::detail
