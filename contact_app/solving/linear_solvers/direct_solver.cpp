// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/direct_solver.h"

#include <algorithm>
#include <string>
#include <type_traits>
#include <variant>

#include <Eigen/CholmodSupport>
#include <Eigen/KLUSupport>
#include <Eigen/SparseLU>
#include <umfpack.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {

namespace {

constexpr const char* kOrderingKey = "linear_solver_settings.ordering";

/// The ordering UMFPACK reports it used (Info[UMFPACK_ORDERING_USED]).
std::string UsedOrderingName(double code) {
    switch (static_cast<int>(code)) {
        case UMFPACK_ORDERING_AMD: return "amd";
        case UMFPACK_ORDERING_METIS: return "metis";
        case UMFPACK_ORDERING_CHOLMOD: return "cholmod";
        case UMFPACK_ORDERING_GIVEN: return "given";
        case UMFPACK_ORDERING_NONE: return "none";
        default: return "unknown";
    }
}

std::string UmfpackStatusText(long status) {
    switch (status) {
        case UMFPACK_WARNING_singular_matrix: return "singular matrix";
        case UMFPACK_ERROR_out_of_memory: return "out of memory";
        case UMFPACK_ERROR_invalid_matrix: return "invalid matrix";
        case UMFPACK_ERROR_different_pattern: return "pattern changed since the analysis";
        default: return "status " + std::to_string(status);
    }
}

}  // namespace

FillReducingOrdering ParseFillReducingOrdering(const std::string& name) {
    for (const auto ordering : {FillReducingOrdering::Auto, FillReducingOrdering::Amd, FillReducingOrdering::Metis})
        if (name == FillReducingOrderingName(ordering)) return ordering;
    const auto names = FillReducingOrderingNames();
    CONTACT_THROW(InputError, "unknown ", kOrderingKey, " \"", name, "\"", "\n  expected: one of ", QuotedList(names),
                  " (\"auto\": metis from ", kAutoMetisMinimumSize, " equations on, amd below)", DidYouMean(name, names));
}

const char* FillReducingOrderingName(FillReducingOrdering ordering) {
    switch (ordering) {
        case FillReducingOrdering::Auto: return "auto";
        case FillReducingOrdering::Amd: return "amd";
        case FillReducingOrdering::Metis: return "metis";
    }
    return "auto";
}

std::vector<std::string> FillReducingOrderingNames() { return {"amd", "auto", "metis"}; }

/// UMFPACK called directly (umfpack_dl_*: 64-bit indices, because the 32-bit variant cannot address
/// more than 2^31 words of factor memory and fails on 3D problems of ~10^5 unknowns). The 64-bit copy
/// of the pattern is made once per symbolic analysis; the values are read from the system matrix in
/// place, so a refactorisation copies nothing.
struct DirectSolver::Umfpack {
    std::vector<SuiteSparse_long> column_starts;
    std::vector<SuiteSparse_long> row_indices;
    void* symbolic = nullptr;
    void* numeric = nullptr;
    double control[UMFPACK_CONTROL];
    double info[UMFPACK_INFO];
    std::string ordering_used;

    Umfpack() {
        umfpack_dl_defaults(control);
        std::fill(std::begin(info), std::end(info), 0.0);
    }
    ~Umfpack() {
        FreeNumeric();
        FreeSymbolic();
    }
    Umfpack(const Umfpack&) = delete;
    Umfpack& operator=(const Umfpack&) = delete;

    void FreeNumeric() {
        if (numeric != nullptr) umfpack_dl_free_numeric(&numeric);
        numeric = nullptr;
    }
    void FreeSymbolic() {
        if (symbolic != nullptr) umfpack_dl_free_symbolic(&symbolic);
        symbolic = nullptr;
    }
};

struct DirectSolver::Backend {
    Umfpack umfpack;
    std::variant<std::monostate, Eigen::CholmodSupernodalLLT<SparseMatrixType>, Eigen::KLU<SparseMatrixType>,
                 Eigen::SparseLU<SparseMatrixType, Eigen::COLAMDOrdering<int>>>
        eigen;

    explicit Backend(DirectSolverKind kind) {
        switch (kind) {
            case DirectSolverKind::UmfPack: break;
            case DirectSolverKind::Cholmod: eigen.emplace<1>(); break;
            case DirectSolverKind::Klu: eigen.emplace<2>(); break;
            case DirectSolverKind::SparseLU: eigen.emplace<3>(); break;
        }
    }
};

DirectSolver::DirectSolver(DirectSolverKind kind, FillReducingOrdering ordering)
    : mKind(kind), mOrdering(ordering), mBackend(std::make_unique<Backend>(kind)) {
    mStatistics.solver = Info();
    if (kind == DirectSolverKind::UmfPack) mStatistics.ordering_setting = FillReducingOrderingName(ordering);
}

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

LinearSolverStatistics DirectSolver::Statistics() const { return mStatistics; }

void DirectSolver::Clear() {
    mBackend = std::make_unique<Backend>(mKind);
    mPattern.Clear();
}

void DirectSolver::SolveWithUmfpack(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB, bool analyse) {
    Umfpack& umf = mBackend->umfpack;
    const auto n = static_cast<SuiteSparse_long>(rA.rows());
    const double* values = rA.valuePtr();
    if (analyse || umf.symbolic == nullptr) {
        umf.FreeNumeric();
        umf.FreeSymbolic();
        umf.column_starts.assign(rA.outerIndexPtr(), rA.outerIndexPtr() + rA.cols() + 1);
        umf.row_indices.assign(rA.innerIndexPtr(), rA.innerIndexPtr() + rA.nonZeros());
        const bool metis = mOrdering == FillReducingOrdering::Metis ||
                           (mOrdering == FillReducingOrdering::Auto && static_cast<std::size_t>(n) >= kAutoMetisMinimumSize);
        umf.control[UMFPACK_ORDERING] = metis ? UMFPACK_ORDERING_METIS : UMFPACK_ORDERING_AMD;
        const auto status = umfpack_dl_symbolic(n, n, umf.column_starts.data(), umf.row_indices.data(), values,
                                                &umf.symbolic, umf.control, umf.info);
        if (status != UMFPACK_OK) {
            umf.FreeSymbolic();
            CONTACT_THROW(ConvergenceError, Info(), ": the symbolic analysis of the ", n, "x", n, " system failed (",
                          UmfpackStatusText(status), ")");
        }
        umf.ordering_used = UsedOrderingName(umf.info[UMFPACK_ORDERING_USED]);
        mStatistics.symbolic_seconds += umf.info[UMFPACK_SYMBOLIC_TIME];
    }
    umf.FreeNumeric();
    const auto status = umfpack_dl_numeric(umf.column_starts.data(), umf.row_indices.data(), values, umf.symbolic,
                                           &umf.numeric, umf.control, umf.info);
    if (status != UMFPACK_OK) {
        umf.FreeNumeric();
        CONTACT_THROW(ConvergenceError, Info(), ": the factorisation of the ", n, "x", n, " system failed (UMFPACK ",
                      UmfpackStatusText(status), ")",
                      status == UMFPACK_ERROR_out_of_memory
                          ? std::string("\n  fix: use \"ordering\": \"metis\" in linear_solver_settings (less fill), "
                                        "or a coarser mesh")
                          : std::string("\n  fix: check the boundary conditions (rigid-body modes) and the contact "
                                        "settings (a multiplier with no stiffness makes the system singular)"));
    }
    const double factor_nonzeros = umf.info[UMFPACK_LNZ] + umf.info[UMFPACK_UNZ];
    const double factor_memory = umf.info[UMFPACK_PEAK_MEMORY] * umf.info[UMFPACK_SIZE_OF_UNIT];
    mStatistics.ordering = umf.ordering_used;
    mStatistics.factor_nonzeros = factor_nonzeros;
    mStatistics.max_factor_nonzeros = std::max(mStatistics.max_factor_nonzeros, factor_nonzeros);
    mStatistics.factor_memory = factor_memory;
    mStatistics.max_factor_memory = std::max(mStatistics.max_factor_memory, factor_memory);
    mStatistics.factor_flops += umf.info[UMFPACK_FLOPS];
    mStatistics.numeric_seconds += umf.info[UMFPACK_NUMERIC_TIME];

    rX.resize(rA.rows());
    const auto solved = umfpack_dl_solve(UMFPACK_A, umf.column_starts.data(), umf.row_indices.data(), values,
                                         rX.data(), rB.data(), umf.numeric, umf.control, umf.info);
    CONTACT_CHECK(solved == UMFPACK_OK && rX.allFinite(), ConvergenceError, Info(),
                  ": the solve produced non-finite values (the matrix is numerically singular)");
}

void DirectSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    CONTACT_CHECK(rA.rows() == rA.cols() && rA.rows() == rB.size(), InternalError, Info(),
                  ": system of size ", rA.rows(), "x", rA.cols(), " with a right-hand side of size ", rB.size());
    if (rA.rows() == 0) {
        rX.resize(0);
        return;
    }
    rA.makeCompressed();
    const bool analyse = !mPattern.Matches(rA);
    if (analyse) {
        mPattern.Assign(rA);
        ++mAnalyses;
    }
    ++mStatistics.factorizations;
    mStatistics.system_size = static_cast<std::size_t>(rA.rows());
    if (mKind == DirectSolverKind::UmfPack) {
        SolveWithUmfpack(rA, rX, rB, analyse);
        return;
    }
    std::visit(
        [&](auto& solver) {
            using TSolver = std::decay_t<decltype(solver)>;
            if constexpr (!std::is_same_v<TSolver, std::monostate>) {
                if (analyse) solver.analyzePattern(rA);
                solver.factorize(rA);
                if (solver.info() != Eigen::Success)
                    CONTACT_THROW(ConvergenceError, Info(), ": the factorisation of the ", rA.rows(), "x", rA.cols(),
                                  " system failed (singular or, for cholmod, not positive definite)",
                                  "\n  fix: check the boundary conditions (rigid-body modes) and, for an indefinite or",
                                  " unsymmetric system, use an LU solver such as \"umfpack\"");
                rX = solver.solve(rB);
                CONTACT_CHECK(solver.info() == Eigen::Success && rX.allFinite(), ConvergenceError, Info(),
                              ": the solve produced non-finite values (the matrix is numerically singular)");
            }
        },
        mBackend->eigen);
}

}  // namespace contact_app
