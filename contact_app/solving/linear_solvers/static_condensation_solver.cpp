// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/static_condensation_solver.h"

#include <algorithm>
#include <numeric>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <unordered_set>

#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/UmfPackSupport>
#include <dmumps_c.h>

#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/flags.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/variables.h"
#include "contact_app/solving/linear_solvers/available_memory.h"

// LAPACK (OpenBLAS, threaded): the dense LU of the interface system.
extern "C" void dgetrf_(const int* m, const int* n, double* a, const int* lda, int* ipiv, int* info);

namespace contact_app {

namespace {

using detail::Concat;

constexpr const char* kModeKey = "linear_solver_settings.static_condensation";

double SecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// splitmix64's finaliser: the entries of the bulk hash are summed, so it must spread every bit.
std::uint64_t Mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

bool IsDisplacement(const Variable<double>& variable) {
    return variable == DISPLACEMENT_X || variable == DISPLACEMENT_Y || variable == DISPLACEMENT_Z;
}

/// Columns per block of the multi-right-hand-side bulk solves: a dense block of about 128 MB (wider
/// blocks run the supernodal solve at BLAS-3 speed).
Eigen::Index BlockColumns(Eigen::Index bulk_size) {
    return std::clamp<Eigen::Index>((Eigen::Index{16} << 20) / std::max<Eigen::Index>(bulk_size, 1), 16, 1024);
}

}  // namespace

/// One MUMPS instance on [A_BB A_BC; A_CB 0] and what it keeps pointers to.
struct detail::MumpsSchurFactorisation::Instance {
    DMUMPS_STRUC_C id{};
    bool initialised = false;
    MUMPS_INT n_b = 0, n_c = 0;
    std::vector<MUMPS_INT> schur_variables;

    ~Instance() {
        if (!initialised) return;
        id.job = -2;  // frees the factors and deletes their files
        dmumps_c(&id);
    }
};

detail::MumpsSchurFactorisation::MumpsSchurFactorisation() = default;
detail::MumpsSchurFactorisation::~MumpsSchurFactorisation() = default;

void detail::MumpsSchurFactorisation::Release() {
    mInstance.reset();
}

bool detail::MumpsSchurFactorisation::OutOfCore() const {
    return mInstance && mInstance->id.icntl[21] == 1;
}

bool detail::MumpsSchurFactorisation::Compute(const SparseMatrixType& a_bb, const SparseMatrixType& a_bc,
                                              const SparseMatrixType& a_cb, SchurSymmetry symmetry,
                                              const std::vector<int>& bulk_order, Eigen::MatrixXd& rProduct,
                                              double out_of_core_bytes) {
    Release();
    auto instance = std::make_unique<Instance>();
    const bool lower_only = symmetry != SchurSymmetry::UNSYMMETRIC;
    const auto n_b = static_cast<MUMPS_INT>(a_bb.rows()), n_c = static_cast<MUMPS_INT>(a_bc.cols());
    std::vector<MUMPS_INT> rows, columns;
    std::vector<double> values;
    const auto add = [&](const SparseMatrixType& block, MUMPS_INT row_offset, MUMPS_INT column_offset) {
        for (Eigen::Index j = 0; j < block.outerSize(); ++j)
            for (SparseMatrixType::InnerIterator entry(block, j); entry; ++entry) {
                if (lower_only && entry.row() + row_offset < j + column_offset) continue;
                rows.push_back(static_cast<MUMPS_INT>(entry.row()) + 1 + row_offset);
                columns.push_back(static_cast<MUMPS_INT>(j) + 1 + column_offset);
                values.push_back(entry.value());
            }
    };
    add(a_bb, 0, 0);
    if (!lower_only) add(a_bc, 0, n_b);
    add(a_cb, n_b, 0);
    for (MUMPS_INT c = 1; c <= n_c; ++c) {  // the (zero) diagonal of the Schur variables
        rows.push_back(n_b + c);
        columns.push_back(n_b + c);
        values.push_back(0.0);
    }
    instance->n_b = n_b;
    instance->n_c = n_c;
    instance->schur_variables.resize(static_cast<std::size_t>(n_c));
    std::iota(instance->schur_variables.begin(), instance->schur_variables.end(), n_b + 1);
    // MUMPS writes S by rows (the lower triangle by rows when symmetric) into P's storage: read column-major, that is
    // Sᵀ (the upper triangle), turned round below without a second n_C × n_C matrix.
    rProduct.setZero(n_c, n_c);  // the triangle MUMPS does not write must be finite too

    DMUMPS_STRUC_C& id = instance->id;
    id.job = -1;  // initialise
    id.par = 1;
    id.sym = static_cast<MUMPS_INT>(symmetry);
    id.comm_fortran = -987654;  // the sequential library's only communicator
    dmumps_c(&id);
    if (id.infog[0] < 0) return false;
    instance->initialised = true;
    id.icntl[0] = id.icntl[1] = id.icntl[2] = -1;  // silent
    id.icntl[3] = 0;
    id.n = n_b + n_c;
    id.nnz = static_cast<MUMPS_INT8>(values.size());
    id.irn = rows.data();
    id.jcn = columns.data();
    id.a = values.data();
    id.size_schur = n_c;
    id.listvar_schur = instance->schur_variables.data();
    id.icntl[18] = 1;  // ICNTL(19): the Schur complement centralised, by rows
    id.schur = rProduct.data();
    id.schur_lld = n_c;
    std::vector<MUMPS_INT> position;
    if (!bulk_order.empty()) {  // ICNTL(7) = 1: PERM_IN(i) = the position of variable i, C last
        position.resize(static_cast<std::size_t>(n_b + n_c));
        for (std::size_t k = 0; k < bulk_order.size(); ++k)
            position[static_cast<std::size_t>(bulk_order[k])] = static_cast<MUMPS_INT>(k + 1);
        std::iota(position.begin() + n_b, position.end(), n_b + 1);
        id.perm_in = position.data();
        id.icntl[6] = 1;
    }
    id.job = 1;  // analysis
    dmumps_c(&id);
    if (id.infog[0] < 0) return false;
    // INFOG(3): the factors' expected size in entries (in millions when negative). Out of core they go to disk as
    // they are computed, and are read back only by Solve.
    const double factor_entries = id.infog[2] < 0 ? -1e6 * id.infog[2] : static_cast<double>(id.infog[2]);
    if (factor_entries * sizeof(double) > out_of_core_bytes) {
        const std::string folder = std::filesystem::temp_directory_path().string();
        std::strncpy(id.ooc_tmpdir, folder.c_str(), sizeof(id.ooc_tmpdir) - 1);
        std::strncpy(id.ooc_prefix, "contact_app_schur_", sizeof(id.ooc_prefix) - 1);
        id.icntl[21] = 1;  // ICNTL(22): out of core
    }
    id.job = 2;  // factorisation
    for (int retry = 0; retry < 3; ++retry) {
        dmumps_c(&id);
        if (id.infog[0] != -8 && id.infog[0] != -9) break;
        id.icntl[13] = std::max<MUMPS_INT>(2 * id.icntl[13], 40);  // ICNTL(14): more working space
    }
    // The coordinate arrays go with this scope: the solve phase reads the factor only.
    id.irn = id.jcn = nullptr;
    id.a = nullptr;
    id.perm_in = nullptr;
    if (id.infog[0] < 0) return false;
    if (lower_only)
        rProduct.triangularView<Eigen::StrictlyLower>() = rProduct.transpose();
    else
        rProduct.transposeInPlace();
    if (!rProduct.allFinite()) return false;
    rProduct *= -1.0;
    mInstance = std::move(instance);
    return true;
}

Eigen::MatrixXd detail::MumpsSchurFactorisation::Solve(const Eigen::MatrixXd& rhs) const {
    CONTACT_CHECK(mInstance != nullptr, InternalError, "MumpsSchurFactorisation::Solve without a kept factor");
    Instance& instance = *mInstance;
    const Eigen::Index n_b = instance.n_b, n = instance.n_b + instance.n_c;
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n, rhs.cols());
    full.topRows(n_b) = rhs;
    DMUMPS_STRUC_C& id = instance.id;
    id.nrhs = static_cast<MUMPS_INT>(rhs.cols());
    id.lrhs = static_cast<MUMPS_INT>(n);
    id.rhs = full.data();
    id.icntl[25] = 0;  // ICNTL(26): the internal problem A_BB x_B = b_B
    id.job = 3;
    dmumps_c(&id);
    id.rhs = nullptr;
    CONTACT_CHECK(id.infog[0] >= 0 && full.allFinite(), ConvergenceError,
                  "static condensation: MUMPS's solve with the bulk factor failed (MUMPS error ", id.infog[0], ")",
                  "\n  fix: set linear_solver_settings.static_condensation to false");
    return full.topRows(n_b);
}

bool detail::SchurProductWithMumps(const SparseMatrixType& a_bb, const SparseMatrixType& a_bc,
                                   const SparseMatrixType& a_cb, SchurSymmetry symmetry,
                                   const std::vector<int>& bulk_order, Eigen::MatrixXd& rProduct,
                                   double out_of_core_bytes) {
    MumpsSchurFactorisation factorisation;
    return factorisation.Compute(a_bb, a_bc, a_cb, symmetry, bulk_order, rProduct, out_of_core_bytes);
}

StaticCondensationMode ParseStaticCondensationMode(const std::string& name) {
    if (name == "auto") return StaticCondensationMode::Auto;
    if (name == "on") return StaticCondensationMode::On;
    if (name == "off") return StaticCondensationMode::Off;
    CONTACT_THROW(InputError, "unknown ", kModeKey, " \"", name, "\"\n  expected: \"auto\", true or false",
                  "\n  fix: remove the key (\"auto\") or give true / false");
}

/// CHOLMOD's supernodal Cholesky with its fill-reducing order in view (handed to MUMPS).
struct BulkCholesky : Eigen::CholmodSupernodalLLT<SparseMatrixType> {
    std::vector<int> EliminationOrder() const {
        const auto* perm = static_cast<const int*>(m_cholmodFactor->Perm);
        return {perm, perm + m_cholmodFactor->n};
    }
    /// The numeric factor's size the symbolic analysis computed (the supernodal values, in bytes).
    double FactorBytes() const { return static_cast<double>(m_cholmodFactor->xsize) * sizeof(double); }
};

/// The factorised bulk block and the Schur product of one condensation. The interface DoFs the bulk
/// couples to (C, displacements of interface nodes) are kept by identity, so the condensation
/// survives a change of the other interface DoFs (the multipliers of each contact step).
struct StaticCondensationSolver::Bulk {
    std::vector<const Dof*> bulk_key;
    std::vector<const Dof*> coupled;        // C, in the order of the columns of a_bc and of P
    std::uint64_t hash = 0;
    std::vector<std::uint64_t> dof_hashes;  // per bulk DoF: which ones a later change touches
    SparseMatrixType a_bc, a_cb;            // A_BC (n_B × n_C) and A_CB (n_C × n_B)
    SparseMatrixType a_bb;                  // kept for UmfPackLU, which refers to its matrix
    std::unique_ptr<BulkCholesky> cholesky;  // A_BB symmetric positive definite
    std::unique_ptr<Eigen::UmfPackLU<SparseMatrixType>> lu;                  // otherwise
    Eigen::MatrixXd schur_product;          // P = A_CB A_BB⁻¹ A_BC, n_C × n_C
    /// A bulk too large for memory: MUMPS's factorisation for P, kept out of core (after schur_product, into
    /// whose storage it wrote).
    std::unique_ptr<detail::MumpsSchurFactorisation> mumps;

    Eigen::MatrixXd SolveBulk(const Eigen::MatrixXd& rhs) const {
        if (cholesky) return cholesky->solve(rhs);
        return mumps ? mumps->Solve(rhs) : Eigen::MatrixXd(lu->solve(rhs));
    }
    const char* FactorName() const { return cholesky ? "cholmod" : mumps ? "mumps out of core" : "umfpack"; }
};

StaticCondensationSolver::StaticCondensationSolver(LinearSolver::Pointer inner, StaticCondensationMode mode,
                                                   std::string bulk_not_linear)
    : mInner(std::move(inner)), mMode(mode), mBulkNotLinear(std::move(bulk_not_linear)) {
    CONTACT_CHECK(mInner != nullptr, InternalError, "static condensation created without an inner solver");
}

StaticCondensationSolver::~StaticCondensationSolver() = default;

void StaticCondensationSolver::Clear() {
    mInner->Clear();
}

std::string StaticCondensationSolver::Info() const {
    return "static_condensation(" + mInner->Info() + ")";
}

LinearSolverStatistics StaticCondensationSolver::Statistics() const {
    LinearSolverStatistics statistics = mInner->Statistics();
    statistics.condensation = mStatistics.condensation;
    statistics.interface_size = mStatistics.interface_size;
    statistics.bulk_size = mStatistics.bulk_size;
    statistics.bulk_factorizations = mStatistics.bulk_factorizations;
    statistics.condensed_solves = mStatistics.condensed_solves;
    statistics.bulk_seconds = mStatistics.bulk_seconds;
    statistics.interface_seconds = mStatistics.interface_seconds;
    // Every solve condensed: the inner solver never ran, so name what did.
    if (statistics.factorizations == 0 && mBulk)
        statistics.solver = std::string("static condensation (bulk ") + mBulk->FactorName() + ", interface dense LU)";
    return statistics;
}

void StaticCondensationSolver::ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) {
    // The system size is only known at Solve (the elimination builder numbers fixed DoFs past it).
    mDofs.assign(rDofSet.begin(), rDofSet.end());
    // Conditions (contact pairs, and loads on the current configuration) may change their matrices
    // at every iteration: their nodes belong to the interface, assembled now or not.
    mConditionNodes.clear();
    for (const auto& condition : rModelPart.Conditions())
        for (std::size_t k = 0; k < condition->GetGeometry().size(); ++k)
            mConditionNodes.insert(&condition->GetGeometry()[k]);
    mHaveData = true;
    if (mInner->AdditionalPhysicalDataIsNeeded()) mInner->ProvideAdditionalData(rDofSet, rModelPart);
}

void StaticCondensationSolver::Partition(std::size_t size) {
    std::vector<const Dof*>& by_equation = mDofOfEquation;
    by_equation.assign(size, nullptr);
    for (const Dof* dof : mDofs)
        if (dof->EquationId() < size) by_equation[dof->EquationId()] = dof;
    mIsInterface.assign(size, 1);
    mLocal.assign(size, 0);
    mInterfaceKey.clear();
    mBulkKey.clear();
    for (std::size_t k = 0; k < size; ++k) {
        const Dof* dof = by_equation[k];
        const Node* node = dof != nullptr ? &dof->GetNode() : nullptr;
        mIsInterface[k] = node == nullptr || !IsDisplacement(dof->GetVariable()) || node->Is(INTERFACE) ||
                          mConditionNodes.count(node) || mPromotedNodes.count(node);
        auto& key = mIsInterface[k] ? mInterfaceKey : mBulkKey;
        mLocal[k] = static_cast<int>(key.size());
        key.push_back(dof);
    }
}

std::string StaticCondensationSolver::Refusal(std::size_t size, std::size_t interface_size) const {
    if (interface_size == 0) return "no contact interface: no equation of an INTERFACE node or a multiplier";
    if (interface_size == size) return "every equation is on the interface";
    if (mMode == StaticCondensationMode::On) return "";
    if (!mBulkNotLinear.empty()) return mBulkNotLinear;
    if (size < kAutoCondensationMinimumSize)
        return Concat(size, " equations, fewer than the ", kAutoCondensationMinimumSize, " from which \"auto\" condenses");
    if (static_cast<double>(interface_size) > kAutoCondensationMaximumShare * static_cast<double>(size))
        return Concat("interface of ", interface_size, " equations, over ", 100.0 * kAutoCondensationMaximumShare,
                      " % of the ", size);
    const double dense_bytes = 16.0 * static_cast<double>(interface_size) * static_cast<double>(interface_size);
    const double held = mBulk ? 8.0 * static_cast<double>(mBulk->schur_product.size()) : 0.0;
    const double available = AvailableMemoryBytes();
    if (available >= 0.0 && dense_bytes > kAutoCondensationDenseShare * (available + held))
        return Concat("interface of ", interface_size, " equations, whose dense P and S (", dense_bytes / 1e9,
                      " GB) would take over ", 100.0 * kAutoCondensationDenseShare, " % of the ",
                      (available + held) / 1e9, " GB of memory available");
    if (interface_size > kAutoCondensationMaximumInterface)
        return Concat("interface of ", interface_size, " equations, over the ", kAutoCondensationMaximumInterface,
                      " a dense Schur complement may hold");
    return "";
}

std::uint64_t StaticCondensationSolver::BulkHash(const SparseMatrixType& rA, std::vector<std::uint64_t>& rDofHashes) const {
    // Sums of per-entry hashes: independent of the order of the entries, so of the pattern of the
    // interface block (it changes with the contact pairs). Bulk DoFs by position, interface DoFs by
    // identity (their numbering changes with the multipliers). Per bulk DoF too, to find what changed.
    rDofHashes.assign(mBulkKey.size(), 0);
    auto identity = [&](std::size_t k) -> std::uint64_t {
        if (!mIsInterface[k]) return static_cast<std::uint64_t>(mLocal[k]) << 1;
        return (static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(mDofOfEquation[k])) << 1) | 1U;
    };
    std::uint64_t hash = 0;
    for (Eigen::Index j = 0; j < rA.outerSize(); ++j) {
        const auto column = static_cast<std::size_t>(j);
        const bool column_interface = mIsInterface[column];
        const std::uint64_t column_identity = Mix(identity(column));
        for (SparseMatrixType::InnerIterator entry(rA, j); entry; ++entry) {
            const auto i = static_cast<std::size_t>(entry.row());
            if ((mIsInterface[i] && column_interface) || entry.value() == 0.0) continue;
            std::uint64_t bits;
            const double value = entry.value();
            std::memcpy(&bits, &value, sizeof bits);
            const std::uint64_t entry_hash = Mix(bits ^ Mix(column_identity + identity(i)));
            hash += entry_hash;
            if (!mIsInterface[i]) rDofHashes[static_cast<std::size_t>(mLocal[i])] += entry_hash;
            if (!column_interface) rDofHashes[static_cast<std::size_t>(mLocal[column])] += entry_hash;
        }
    }
    return hash;
}

void StaticCondensationSolver::Condense(const SparseMatrixType& rA, std::uint64_t hash,
                                        std::vector<std::uint64_t> dof_hashes) {
    const auto start = std::chrono::steady_clock::now();
    mBulk.reset();  // the old factor's memory first
    auto bulk = std::make_unique<Bulk>();
    FactoriseBulk(ExtractBlocks(rA, *bulk), *bulk);
    bulk->bulk_key = mBulkKey;
    bulk->hash = hash;
    bulk->dof_hashes = std::move(dof_hashes);
    mBulk = std::move(bulk);
    ++mStatistics.bulk_factorizations;
    mStatistics.bulk_seconds += SecondsSince(start);
}

SparseMatrixType StaticCondensationSolver::ExtractBlocks(const SparseMatrixType& rA, Bulk& rBulk) const {
    const auto n = static_cast<std::size_t>(rA.rows());
    // C: the interface equations with an entry in a bulk row or column.
    std::vector<int> coupled_index(n, -1);
    for (Eigen::Index j = 0; j < rA.outerSize(); ++j)
        for (SparseMatrixType::InnerIterator entry(rA, j); entry; ++entry) {
            const auto i = static_cast<std::size_t>(entry.row()), column = static_cast<std::size_t>(j);
            if (mIsInterface[i] != mIsInterface[column] && entry.value() != 0.0)
                coupled_index[mIsInterface[i] ? i : column] = 0;
        }
    for (std::size_t k = 0; k < n; ++k)
        if (coupled_index[k] == 0) {
            coupled_index[k] = static_cast<int>(rBulk.coupled.size());
            rBulk.coupled.push_back(mDofOfEquation[k]);
        }
    const auto n_c = static_cast<Eigen::Index>(rBulk.coupled.size());
    const auto n_b = static_cast<Eigen::Index>(mBulkKey.size());
    // The three blocks, column by column; rows arrive sorted because each set keeps the equation order.
    Eigen::VectorXi bb_sizes = Eigen::VectorXi::Zero(n_b), cb_sizes = Eigen::VectorXi::Zero(n_b),
                    bc_sizes = Eigen::VectorXi::Zero(n_c);
    for (Eigen::Index j = 0; j < rA.outerSize(); ++j) {
        const auto column = static_cast<std::size_t>(j);
        for (SparseMatrixType::InnerIterator entry(rA, j); entry; ++entry) {
            const bool row_interface = mIsInterface[static_cast<std::size_t>(entry.row())];
            if (mIsInterface[column]) bc_sizes[std::max(coupled_index[column], 0)] += !row_interface;
            else ++(row_interface ? cb_sizes : bb_sizes)[mLocal[column]];
        }
    }
    SparseMatrixType a_bb(n_b, n_b);
    a_bb.reserve(bb_sizes);
    rBulk.a_cb.resize(n_c, n_b);
    rBulk.a_cb.reserve(cb_sizes);
    rBulk.a_bc.resize(n_b, n_c);
    rBulk.a_bc.reserve(bc_sizes);
    for (Eigen::Index j = 0; j < rA.outerSize(); ++j) {
        const auto column = static_cast<std::size_t>(j);
        for (SparseMatrixType::InnerIterator entry(rA, j); entry; ++entry) {
            const auto i = static_cast<std::size_t>(entry.row());
            if ((mIsInterface[column] && mIsInterface[i]) || entry.value() == 0.0) continue;
            if (mIsInterface[column]) rBulk.a_bc.insert(mLocal[i], coupled_index[column]) = entry.value();
            else if (mIsInterface[i]) rBulk.a_cb.insert(coupled_index[i], mLocal[column]) = entry.value();
            else a_bb.insert(mLocal[i], mLocal[column]) = entry.value();
        }
    }
    a_bb.makeCompressed();
    rBulk.a_cb.makeCompressed();
    rBulk.a_bc.makeCompressed();
    return a_bb;
}

void StaticCondensationSolver::FactoriseBulk(SparseMatrixType a_bb, Bulk& rBulk) const {
    const Eigen::Index n_b = a_bb.rows(), n_c = rBulk.a_bc.cols();
    // CHOLMOD reads one triangle: take it only when A_BB is symmetric to round-off of the element matrices.
    const bool symmetric = [&] {
        const SparseMatrixType asymmetry = a_bb - SparseMatrixType(a_bb.transpose());
        const double scale = a_bb.nonZeros() ? a_bb.coeffs().cwiseAbs().maxCoeff() : 0.0;
        return (asymmetry.nonZeros() ? asymmetry.coeffs().cwiseAbs().maxCoeff() : 0.0) <= 1e-14 * scale;
    }();
    // CHOLMOD's order first (symbolic), then MUMPS's factorisation for P, then CHOLMOD's numeric factor: MUMPS frees
    // its factor before CHOLMOD builds its own, so the peak holds one factor of the bulk, not two
    // (docs/theory/static_condensation.md §2).
    if (symmetric) {
        rBulk.cholesky = std::make_unique<BulkCholesky>();
        rBulk.cholesky->analyzePattern(a_bb);
        if (rBulk.cholesky->info() != Eigen::Success) rBulk.cholesky.reset();
    }
    // P from MUMPS's Schur complement (LDLᵀ in CHOLMOD's order when the bulk is symmetric).
    const SparseMatrixType bc_transposed = rBulk.a_bc.transpose();
    const bool symmetric_coupling = rBulk.cholesky && (bc_transposed - rBulk.a_cb).norm() <= 1e-14 * rBulk.a_cb.norm();
    const std::vector<int> order = symmetric_coupling ? rBulk.cholesky->EliminationOrder() : std::vector<int>{};
    // A factor too large for the memory: MUMPS's, out of core, solves the bulk too (LDLᵀ with 2×2 pivots, as nothing
    // has shown A_BB definite); CHOLMOD's is not formed.
    const double in_core_limit = mBulkInCoreBytes >= 0.0 ? mBulkInCoreBytes : kBulkInCoreShare * AvailableMemoryBytes();
    if (rBulk.cholesky && in_core_limit >= 0.0 && rBulk.cholesky->FactorBytes() > in_core_limit) {
        rBulk.mumps = std::make_unique<detail::MumpsSchurFactorisation>();
        const auto symmetry =
            symmetric_coupling ? detail::SchurSymmetry::SYMMETRIC : detail::SchurSymmetry::UNSYMMETRIC;
        if (rBulk.mumps->Compute(a_bb, rBulk.a_bc, rBulk.a_cb, symmetry, order, rBulk.schur_product, 0.0)) {
            rBulk.cholesky.reset();
            return;
        }
        rBulk.mumps.reset();  // MUMPS failed: the factor in memory after all
    }
    bool have_product = detail::SchurProductWithMumps(
        a_bb, rBulk.a_bc, rBulk.a_cb,
        symmetric_coupling ? detail::SchurSymmetry::POSITIVE_DEFINITE : detail::SchurSymmetry::UNSYMMETRIC, order,
        rBulk.schur_product);
    if (rBulk.cholesky) {
        rBulk.cholesky->factorize(a_bb);
        if (rBulk.cholesky->info() != Eigen::Success) {
            rBulk.cholesky.reset();
            // Not positive definite: MUMPS's symmetric run assumed it was; take its unsymmetric factorisation.
            if (symmetric_coupling)
                have_product = detail::SchurProductWithMumps(a_bb, rBulk.a_bc, rBulk.a_cb,
                                                             detail::SchurSymmetry::UNSYMMETRIC, {},
                                                             rBulk.schur_product);
        }
    }
    if (!rBulk.cholesky) {
        rBulk.a_bb = std::move(a_bb);
        rBulk.lu = std::make_unique<Eigen::UmfPackLU<SparseMatrixType>>();
        rBulk.lu->compute(rBulk.a_bb);
        CONTACT_CHECK(rBulk.lu->info() == Eigen::Success, ConvergenceError, Info(), ": the ", n_b, "x", n_b,
                      " bulk block (every equation off the contact interface) is singular",
                      "\n  fix: check the boundary conditions (a body held only through contact has rigid-body "
                      "modes), or set ", kModeKey, " to false");
    }

    // Without MUMPS's product: P in blocks of columns of A_BC (dense right-hand sides of the bulk factor).
    if (!have_product) rBulk.schur_product.resize(n_c, n_c);
    const Eigen::Index block = BlockColumns(n_b);
    for (Eigen::Index first = 0; !have_product && first < n_c; first += block) {
        const Eigen::Index width = std::min(block, n_c - first);
        const Eigen::MatrixXd rhs = Eigen::MatrixXd(rBulk.a_bc.middleCols(first, width));
        rBulk.schur_product.middleCols(first, width) = rBulk.a_cb * rBulk.SolveBulk(rhs);
    }
    CONTACT_CHECK(rBulk.schur_product.allFinite(), ConvergenceError, Info(),
                  ": the Schur complement of the bulk has non-finite values (the bulk block is numerically singular)",
                  "\n  fix: check the boundary conditions, or set ", kModeKey, " to false");
}

void StaticCondensationSolver::SolveCondensed(const SparseMatrixType& rA, SystemVectorType& rX,
                                              const SystemVectorType& rB) {
    const auto start = std::chrono::steady_clock::now();
    const auto n = static_cast<std::size_t>(rA.rows());
    const auto n_i = static_cast<Eigen::Index>(mInterfaceKey.size());
    const auto n_b = static_cast<Eigen::Index>(mBulkKey.size());
    const auto n_c = static_cast<Eigen::Index>(mBulk->coupled.size());
    std::vector<Eigen::Index> position(static_cast<std::size_t>(n_c));  // of each C DoF in I now
    for (Eigen::Index c = 0; c < n_c; ++c)
        position[static_cast<std::size_t>(c)] = mLocal[mBulk->coupled[static_cast<std::size_t>(c)]->EquationId()];
    Eigen::VectorXd x_i(n_i), b_b(n_b);
    for (std::size_t k = 0; k < n; ++k) (mIsInterface[k] ? x_i : b_b)[mLocal[k]] = rB[static_cast<Eigen::Index>(k)];

    // S = A_II − P: the interface block of this iteration (contact and multipliers included).
    Eigen::MatrixXd schur = Eigen::MatrixXd::Zero(n_i, n_i);
    for (std::size_t j = 0; j < n; ++j) {
        if (!mIsInterface[j]) continue;
        for (SparseMatrixType::InnerIterator entry(rA, static_cast<Eigen::Index>(j)); entry; ++entry)
            if (mIsInterface[static_cast<std::size_t>(entry.row())])
                schur(mLocal[static_cast<std::size_t>(entry.row())], mLocal[j]) += entry.value();
    }
    for (Eigen::Index c = 0; c < n_c; ++c)
        for (Eigen::Index r = 0; r < n_c; ++r)
            schur(position[static_cast<std::size_t>(r)], position[static_cast<std::size_t>(c)]) -=
                mBulk->schur_product(r, c);
    // b_I − A_IB A_BB⁻¹ b_B, through the coupled rows.
    const Eigen::VectorXd reduction = mBulk->a_cb * mBulk->SolveBulk(b_b);
    for (Eigen::Index r = 0; r < n_c; ++r) x_i[position[static_cast<std::size_t>(r)]] -= reduction[r];

    const int size = static_cast<int>(n_i);
    std::vector<int> pivots(static_cast<std::size_t>(n_i));
    int info = 0;
    dgetrf_(&size, &size, schur.data(), &size, pivots.data(), &info);
    CONTACT_CHECK(info == 0, ConvergenceError, Info(), ": the ", n_i, "x", n_i,
                  " interface system is singular (LAPACK dgetrf info ", info, ")",
                  "\n  fix: check the contact settings (a multiplier with no stiffness makes the system singular)");
    for (int k = 0; k < size; ++k) std::swap(x_i[k], x_i[pivots[static_cast<std::size_t>(k)] - 1]);
    schur.triangularView<Eigen::UnitLower>().solveInPlace(x_i);
    schur.triangularView<Eigen::Upper>().solveInPlace(x_i);
    Eigen::VectorXd x_c(n_c);
    for (Eigen::Index c = 0; c < n_c; ++c) x_c[c] = x_i[position[static_cast<std::size_t>(c)]];
    const Eigen::VectorXd x_b = mBulk->SolveBulk(Eigen::MatrixXd(b_b - mBulk->a_bc * x_c));
    CONTACT_CHECK(x_i.allFinite() && x_b.allFinite(), ConvergenceError, Info(),
                  ": the solve produced non-finite values (the interface system is numerically singular)");
    rX.resize(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < n; ++k) rX[static_cast<Eigen::Index>(k)] = mIsInterface[k] ? x_i[mLocal[k]] : x_b[mLocal[k]];
    ++mStatistics.condensed_solves;
    mStatistics.interface_seconds += SecondsSince(start);
}

bool StaticCondensationSolver::CoupledDofsPresent(std::size_t size) const {
    for (const Dof* dof : mBulk->coupled)
        if (dof->EquationId() >= size || mDofOfEquation[dof->EquationId()] != dof || !mIsInterface[dof->EquationId()])
            return false;
    return true;
}

void StaticCondensationSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    mLastCondensed = false;
    const bool have_data = mHaveData;
    mHaveData = false;
    auto full_solve = [&](const std::string& why) {
        mStatistics.condensation = "no (" + why + ")";
        mInner->Solve(rA, rX, rB);
    };
    if (mMode == StaticCondensationMode::Off) return full_solve(Concat("switched off by ", kModeKey));
    if (!mStopped.empty()) return full_solve(mStopped);
    if (!have_data) return full_solve("no DoF data: master-slave constraints are active");

    const auto n = static_cast<std::size_t>(rA.rows());
    Partition(n);
    const std::string refusal = Refusal(n, mInterfaceKey.size());
    if (!refusal.empty()) return full_solve(refusal);

    std::vector<std::uint64_t> dof_hashes;
    std::uint64_t hash = BulkHash(rA, dof_hashes);
    const bool same_sets = mBulk && mBulk->bulk_key == mBulkKey && CoupledDofsPresent(n);
    if (same_sets && mBulk->hash == hash) {
        mBulkChangedLastSolve = false;
    } else {
        if (same_sets) {
            // The bulk changed. Twice in a row is a stiffness that follows the iterate (a non-linear body).
            // Once: a few DoFs (an entity that was not foreseen) join the interface, or all of them (a new
            // time step size) are condensed again.
            if (mBulkChangedLastSolve) {
                mStopped = "the bulk block changed on two consecutive solves: the bodies' stiffness is not constant";
                mBulk.reset();
                return full_solve(mStopped);
            }
            mBulkChangedLastSolve = true;
            std::unordered_set<const Node*> changed;
            for (std::size_t b = 0; b < dof_hashes.size(); ++b)
                if (dof_hashes[b] != mBulk->dof_hashes[b]) changed.insert(&mBulkKey[b]->GetNode());
            std::size_t joining = 0;
            for (const Dof* dof : mBulkKey) joining += changed.count(&dof->GetNode());
            const auto joined = static_cast<double>(mInterfaceKey.size() + joining);
            if (joined <= kAutoCondensationMaximumShare * static_cast<double>(n) &&
                joined <= static_cast<double>(kAutoCondensationMaximumInterface)) {
                mPromotedNodes.insert(changed.begin(), changed.end());
                Partition(n);
                hash = BulkHash(rA, dof_hashes);
            }
        }
        Condense(rA, hash, std::move(dof_hashes));
    }
    SolveCondensed(rA, rX, rB);
    mLastCondensed = true;
    mStatistics.condensation = "yes";
    mStatistics.interface_size = mInterfaceKey.size();
    mStatistics.bulk_size = mBulkKey.size();
}

}  // namespace contact_app
