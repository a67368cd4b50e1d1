// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/direct_solver.h"

#include <string>
#include <type_traits>
#include <variant>

#include <Eigen/CholmodSupport>
#include <Eigen/KLUSupport>
#include <Eigen/SparseLU>
#include <Eigen/UmfPackSupport>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

namespace {
// UMFPACK runs on 64-bit indices (umfpack_dl): the 32-bit variant cannot address more than 2^31
// words of factor memory and fails on 3D problems of ~10^5 unknowns.
using LongIndexMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, long>;
using UmfPackSolver = Eigen::UmfPackLU<LongIndexMatrix>;
}  // namespace

struct DirectSolver::Backend {
    LongIndexMatrix long_index_copy;
    std::variant<UmfPackSolver, Eigen::CholmodSupernodalLLT<SparseMatrixType>,
                 Eigen::KLU<SparseMatrixType>, Eigen::SparseLU<SparseMatrixType, Eigen::COLAMDOrdering<int>>>
        solver;

    explicit Backend(DirectSolverKind kind) {
        switch (kind) {
            case DirectSolverKind::UmfPack: solver.emplace<0>(); break;
            case DirectSolverKind::Cholmod: solver.emplace<1>(); break;
            case DirectSolverKind::Klu: solver.emplace<2>(); break;
            case DirectSolverKind::SparseLU: solver.emplace<3>(); break;
        }
    }
};

DirectSolver::DirectSolver(DirectSolverKind kind) : mKind(kind), mBackend(std::make_unique<Backend>(kind)) {}

DirectSolver::~DirectSolver() = default;

std::string DirectSolver::Info() const {
    switch (mKind) {
        case DirectSolverKind::UmfPack: return "umfpack";
        case DirectSolverKind::Cholmod: return "cholmod";
        case DirectSolverKind::Klu: return "klu";
        case DirectSolverKind::SparseLU: return "sparse_lu";
    }
    return "direct";
}

bool DirectSolver::PatternChanged(const SparseMatrixType& rA) const {
    const auto cols = static_cast<std::size_t>(rA.cols());
    const auto nnz = static_cast<std::size_t>(rA.nonZeros());
    if (mOuter.size() != cols + 1 || mInner.size() != nnz) return true;
    return !std::equal(mOuter.begin(), mOuter.end(), rA.outerIndexPtr()) ||
           !std::equal(mInner.begin(), mInner.end(), rA.innerIndexPtr());
}

void DirectSolver::Clear() {
    mBackend = std::make_unique<Backend>(mKind);
    mOuter.clear();
    mInner.clear();
}

void DirectSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    CONTACT_CHECK(rA.rows() == rA.cols() && rA.rows() == rB.size(), InternalError, Info(),
                  ": system of size ", rA.rows(), "x", rA.cols(), " with a right-hand side of size ", rB.size());
    if (rA.rows() == 0) {
        rX.resize(0);
        return;
    }
    rA.makeCompressed();
    const bool analyse = PatternChanged(rA);
    if (analyse) {
        mOuter.assign(rA.outerIndexPtr(), rA.outerIndexPtr() + rA.cols() + 1);
        mInner.assign(rA.innerIndexPtr(), rA.innerIndexPtr() + rA.nonZeros());
        ++mAnalyses;
    }
    std::visit(
        [&](auto& solver) {
            using TSolver = std::decay_t<decltype(solver)>;
            if constexpr (std::is_same_v<TSolver, UmfPackSolver>) {
                mBackend->long_index_copy = rA;
                if (analyse) solver.analyzePattern(mBackend->long_index_copy);
                solver.factorize(mBackend->long_index_copy);
            } else {
                if (analyse) solver.analyzePattern(rA);
                solver.factorize(rA);
            }
            if (solver.info() != Eigen::Success) {
                std::string detail;
                if constexpr (std::is_same_v<TSolver, UmfPackSolver>)
                    detail = " (UMFPACK status " + std::to_string(solver.umfpackFactorizeReturncode()) +
                             (solver.umfpackFactorizeReturncode() == 1 ? ": singular matrix)" : ")");
                CONTACT_THROW(ConvergenceError, Info(), ": the factorisation of the ", rA.rows(), "x", rA.cols(),
                              " system failed", detail, " (singular or, for cholmod, not positive definite)",
                              "\n  fix: check the boundary conditions (rigid-body modes) and, for an indefinite or",
                              " unsymmetric system, use an LU solver such as \"umfpack\"");
            }
            rX = solver.solve(rB);
            CONTACT_CHECK(solver.info() == Eigen::Success && rX.allFinite(), ConvergenceError, Info(),
                          ": the solve produced non-finite values (the matrix is numerically singular)");
        },
        mBackend->solver);
}

}  // namespace contact_app
