// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/mumps_solver.h"

#include <algorithm>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include <cholmod.h>
#include <dmumps_c.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/solving/linear_solvers/available_memory.h"

namespace contact_app {

namespace {

constexpr MUMPS_INT kJobInit = -1;
constexpr MUMPS_INT kJobEnd = -2;
constexpr MUMPS_INT kJobAnalyse = 1;
constexpr MUMPS_INT kJobFactorise = 2;
constexpr MUMPS_INT kJobSolve = 3;
constexpr MUMPS_INT kUseCommWorld = -987654;  // the sequential library's only communicator
constexpr int kWorkspaceRetries = 2;           // ICNTL(14) doubled at most this often
constexpr MUMPS_INT kSingular = -10;           // also what null pivots (INFOG(28) > 0) are reported as

// MUMPS's ICNTL(7) and INFOG(7) codes.
constexpr MUMPS_INT kOrderingAmd = 0;
constexpr MUMPS_INT kOrderingGiven = 1;

/// The ordering MUMPS reports it used (INFOG(7)); "given" is ours, METIS through CHOLMOD.
const char* UsedOrderingName(MUMPS_INT code) {
    switch (code) {
        case kOrderingAmd: return "amd";
        case kOrderingGiven: return "metis";
        case 2: return "amf";
        case 3: return "scotch";
        case 4: return "pord";
        case 5: return "metis";
        case 6: return "qamd";
        default: return "unknown";
    }
}

/// What a negative INFOG(1) means, and what to do about it.
std::string MumpsErrorText(MUMPS_INT code, MUMPS_INT detail) {
    switch (code) {
        case kSingular:
            return "numerically singular matrix (MUMPS error -10" +
                   (detail > 0 ? "; null pivots: " + std::to_string(detail) : std::string()) + ")\n  fix: check the boundary conditions (rigid-body "
                   "modes) and the contact settings (a multiplier with no stiffness makes the system singular)";
        case -6:
            return "structurally singular matrix, structural rank " + std::to_string(detail) +
                   " (MUMPS error -6)\n  fix: check that every DoF is connected to an element or fixed";
        case -8:
        case -9:
            return "working space too small after " + std::to_string(kWorkspaceRetries) +
                   " enlargements of ICNTL(14) (MUMPS error " + std::to_string(code) +
                   ": pivoting created much more fill than the analysis predicted)\n  fix: use \"umfpack\"";
        case -13:
            return "out of memory, an allocation of " + std::to_string(detail) +
                   (detail < 0 ? " million" : "") + " bytes failed (MUMPS error -13)\n  fix: a coarser mesh, or "
                   "\"ordering\": \"metis\" in linear_solver_settings (less fill)";
        default:
            return "MUMPS error " + std::to_string(code) + " (INFO(2) = " + std::to_string(detail) +
                   "; the MUMPS users' guide lists the codes)";
    }
}

/// MUMPS reports counts above 2^31 as negative millions (INFOG(29)).
double Count(MUMPS_INT value) { return value < 0 ? -1.0e6 * value : static_cast<double>(value); }

double CpuSeconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

/// METIS nested dissection of the pattern of A + Aᵀ (1-based, MUMPS's PERM_IN), through CHOLMOD.
std::vector<MUMPS_INT> MetisOrdering(const SparseMatrixType& rA) {
    SparseMatrixType pattern = rA;
    std::fill(pattern.valuePtr(), pattern.valuePtr() + pattern.nonZeros(), 1.0);
    SparseMatrixType symmetric = pattern + SparseMatrixType(pattern.transpose());
    symmetric.makeCompressed();
    cholmod_common common;
    cholmod_start(&common);
    common.print = 0;
    cholmod_sparse view{};
    view.nrow = view.ncol = static_cast<std::size_t>(symmetric.rows());
    view.nzmax = static_cast<std::size_t>(symmetric.nonZeros());
    view.p = symmetric.outerIndexPtr();
    view.i = symmetric.innerIndexPtr();
    view.x = symmetric.valuePtr();
    view.stype = 1;  // symmetric, upper part read
    view.itype = CHOLMOD_INT;
    view.xtype = CHOLMOD_PATTERN;
    view.dtype = CHOLMOD_DOUBLE;
    view.sorted = 1;
    view.packed = 1;
    std::vector<int> permutation(view.nrow);
    const int done = cholmod_metis(&view, nullptr, 0, 1, permutation.data(), &common);
    cholmod_finish(&common);
    CONTACT_CHECK(done == 1, ConvergenceError, "mumps: the METIS ordering of the ", view.nrow, "x", view.nrow,
                  " system failed (CHOLMOD status ", common.status, ")",
                  "\n  fix: use \"ordering\": \"amd\" in linear_solver_settings");
    // CHOLMOD gives the elimination order (Perm[k] = k-th pivot); MUMPS wants each variable's position.
    std::vector<MUMPS_INT> position(view.nrow);
    for (std::size_t k = 0; k < view.nrow; ++k) position[static_cast<std::size_t>(permutation[k])] = static_cast<MUMPS_INT>(k + 1);
    return position;
}

}  // namespace

/// One MUMPS instance and the coordinate pattern it was analysed with (MUMPS keeps pointers into it).
struct MumpsSolver::Instance {
    DMUMPS_STRUC_C id{};
    std::vector<MUMPS_INT> rows;     // 1-based row of every stored entry, in the matrix's storage order
    std::vector<MUMPS_INT> columns;  // 1-based column
    std::vector<MUMPS_INT> permutation;

    Instance() {
        id.job = kJobInit;
        id.par = 1;  // the host works (there is only the host)
        id.sym = 0;  // unsymmetric
        id.comm_fortran = kUseCommWorld;
        dmumps_c(&id);
        CONTACT_CHECK(id.infog[0] >= 0, ConvergenceError, "mumps: initialisation failed (MUMPS error ", id.infog[0],
                      ")");
        // Silence errors, diagnostics, global information and messages (ICNTL(1..4)).
        id.icntl[0] = -1;
        id.icntl[1] = -1;
        id.icntl[2] = -1;
        id.icntl[3] = 0;
        // Null-pivot detection (ICNTL(24)): without it a pivot at round-off passes and a singular
        // system "solves" to huge finite values; with it INFOG(28) counts them.
        id.icntl[23] = 1;
    }
    ~Instance() {
        id.job = kJobEnd;
        dmumps_c(&id);
    }
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    /// ICNTL(x) and INFOG(x) with the users' guide's 1-based numbers.
    MUMPS_INT& Icntl(int x) { return id.icntl[x - 1]; }
    MUMPS_INT Infog(int x) const { return id.infog[x - 1]; }
    void Run(MUMPS_INT job) {
        id.job = job;
        dmumps_c(&id);
    }
};

MumpsSolver::MumpsSolver(FillReducingOrdering ordering, int workspace_percent, double out_of_core_bytes)
    : mOrdering(ordering), mWorkspacePercent(workspace_percent), mOutOfCoreBytes(out_of_core_bytes) {
    CONTACT_CHECK(workspace_percent >= 0, InputError, "mumps: the working space beyond the analysis's estimate must be ",
                  "a percentage >= 0 (ICNTL(14)), got ", workspace_percent);
    mStatistics.solver = Info();
    mStatistics.ordering_setting = FillReducingOrderingName(ordering);
}

MumpsSolver::~MumpsSolver() = default;

void MumpsSolver::Clear() {
    mInstance.reset();
    mPattern.Clear();
}

void MumpsSolver::Analyse(SparseMatrixType& rA) {
    Instance& mumps = *mInstance;
    const auto n = static_cast<std::size_t>(rA.rows());
    const auto nnz = static_cast<std::size_t>(rA.nonZeros());
    mumps.rows.resize(nnz);
    mumps.columns.resize(nnz);
    for (std::size_t j = 0; j < n; ++j)
        for (auto k = static_cast<std::size_t>(rA.outerIndexPtr()[j]); k < static_cast<std::size_t>(rA.outerIndexPtr()[j + 1]); ++k) {
            mumps.rows[k] = rA.innerIndexPtr()[k] + 1;
            mumps.columns[k] = static_cast<MUMPS_INT>(j + 1);
        }
    mumps.id.n = static_cast<MUMPS_INT>(n);
    mumps.id.nnz = static_cast<MUMPS_INT8>(nnz);
    mumps.id.irn = mumps.rows.data();
    mumps.id.jcn = mumps.columns.data();
    mumps.id.a = rA.valuePtr();  // the analysis's column permutation and scaling use the values
    const double start = CpuSeconds();
    if (mOrdering == FillReducingOrdering::Amd) {
        mumps.Icntl(7) = kOrderingAmd;
    } else {
        mumps.permutation = MetisOrdering(rA);
        mumps.id.perm_in = mumps.permutation.data();
        mumps.Icntl(7) = kOrderingGiven;
    }
    mumps.Run(kJobAnalyse);
    mStatistics.symbolic_seconds += CpuSeconds() - start;
    CONTACT_CHECK(mumps.Infog(1) >= 0, ConvergenceError, "mumps: the analysis of the ", n, "x", n, " system failed: ",
                  MumpsErrorText(mumps.Infog(1), mumps.Infog(2)));
    mStatistics.ordering = UsedOrderingName(mumps.Infog(7));
    // INFOG(17): the memory (MB, rounded) the analysis expects the in-core factorisation to take.
    const double limit = mOutOfCoreBytes >= 0.0 ? mOutOfCoreBytes : kOutOfCoreShare * AvailableMemoryBytes();
    const bool out_of_core = limit >= 0.0 && 1.0e6 * mumps.Infog(17) >= limit;
    mumps.Icntl(22) = out_of_core ? 1 : 0;
    if (out_of_core) {
        const std::string folder = std::filesystem::temp_directory_path().string();
        std::strncpy(mumps.id.ooc_tmpdir, folder.c_str(), sizeof(mumps.id.ooc_tmpdir) - 1);
        std::strncpy(mumps.id.ooc_prefix, "contact_app_mumps_", sizeof(mumps.id.ooc_prefix) - 1);
    }
}

void MumpsSolver::Factorise(SparseMatrixType& rA) {
    Instance& mumps = *mInstance;
    mumps.id.a = rA.valuePtr();
    const double start = CpuSeconds();
    mumps.Icntl(14) = mWorkspacePercent;
    for (int retry = 0;; ++retry) {
        mumps.Run(kJobFactorise);
        const MUMPS_INT code = mumps.Infog(1);
        // -8/-9: pivoting needed more working space than the analysis estimated; enlarge it and redo.
        if ((code != -8 && code != -9) || retry == kWorkspaceRetries) break;
        mumps.Icntl(14) = std::max(2 * mumps.Icntl(14), mumps.Icntl(14) + 20);
        ++mStatistics.workspace_enlargements;
    }
    mStatistics.numeric_seconds += CpuSeconds() - start;
    if (mumps.Icntl(22) == 1) ++mStatistics.out_of_core_factorizations;
    const MUMPS_INT code = mumps.Infog(1) >= 0 && mumps.Infog(28) > 0 ? kSingular : mumps.Infog(1);
    CONTACT_CHECK(code >= 0, ConvergenceError, "mumps: the factorisation of the ", rA.rows(), "x", rA.rows(),
                  " system failed: ", MumpsErrorText(code, mumps.Infog(28)));
    const double factor_nonzeros = Count(mumps.Infog(29));
    const double factor_memory = 1.0e6 * mumps.Infog(22);  // MUMPS counts millions of bytes
    mStatistics.factor_nonzeros = factor_nonzeros;
    mStatistics.max_factor_nonzeros = std::max(mStatistics.max_factor_nonzeros, factor_nonzeros);
    mStatistics.factor_memory = factor_memory;
    mStatistics.max_factor_memory = std::max(mStatistics.max_factor_memory, factor_memory);
    mStatistics.factor_flops += mumps.id.rinfog[2];  // RINFOG(3): flops of the elimination
}

void MumpsSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    CONTACT_CHECK(rA.rows() == rA.cols() && rA.rows() == rB.size(), InternalError, Info(), ": system of size ",
                  rA.rows(), "x", rA.cols(), " with a right-hand side of size ", rB.size());
    if (rA.rows() == 0) {
        rX.resize(0);
        return;
    }
    rA.makeCompressed();
    if (!mInstance) {
        mInstance = std::make_unique<Instance>();
        mPattern.Clear();
    }
    if (!mPattern.Matches(rA)) {
        mPattern.Clear();  // a failed analysis leaves nothing to reuse
        Analyse(rA);
        mPattern.Assign(rA);
        ++mAnalyses;
    }
    ++mStatistics.factorizations;
    mStatistics.system_size = static_cast<std::size_t>(rA.rows());
    Factorise(rA);
    rX = rB;  // MUMPS overwrites the right-hand side with the solution
    Instance& mumps = *mInstance;
    mumps.id.nrhs = 1;
    mumps.id.lrhs = static_cast<MUMPS_INT>(rA.rows());
    mumps.id.rhs = rX.data();
    mumps.Run(kJobSolve);
    CONTACT_CHECK(mumps.Infog(1) >= 0 && rX.allFinite(), ConvergenceError, Info(),
                  ": the solve produced non-finite values or failed (",
                  MumpsErrorText(mumps.Infog(1), mumps.Infog(2)), ")");
}

}  // namespace contact_app
