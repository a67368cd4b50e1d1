// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"

namespace contact_app {

class Node;

/// linear_solver_settings.static_condensation: "auto" (condense when the bulk is linear and the
/// condensation pays), true (condense whenever the system has an interface and a bulk), false (never).
enum class StaticCondensationMode { Auto, On, Off };

/// "auto", "on" or "off" → the mode. @throws InputError naming linear_solver_settings.static_condensation.
StaticCondensationMode ParseStaticCondensationMode(const std::string& name);

/// "auto" condenses systems of at least this many equations (below it a sparse LU per iteration takes
/// seconds at most, and every Kratos reference case keeps the sparse solver's results to the bit:
/// benchmarks/README.md, "Static condensation")...
inline constexpr std::size_t kAutoCondensationMinimumSize = 20000;
/// ...whose interface holds at most this share of the equations...
inline constexpr double kAutoCondensationMaximumShare = 0.1;
/// ...and at most this many equations (P and S are dense, 8 n_I² bytes each: 3.2 GB each at 20 000; the LU of S
/// ∝ n_I³ took 7.5 s at 10 288 and about 60 s at 19 142 on 2 cores, against 55 s and, extrapolated, about 300 s for
/// one sparse factorisation of the whole 4.1e5- and 1.05e6-equation systems: benchmarks/README.md, "Larger levels")...
inline constexpr std::size_t kAutoCondensationMaximumInterface = 20000;
/// ...while P and S (16 n_I² bytes) take at most this share of the memory available (that of a condensation already
/// held counted as available).
inline constexpr double kAutoCondensationDenseShare = 0.5;
/// MUMPS's factors for the Schur product P are written to disk as they are computed (out of core) when its analysis
/// expects more than this many bytes of them: P is all that is kept, so the factors never need to be read back, and
/// out of core they no longer add their size to the run's peak memory (docs/theory/static_condensation.md §2).
inline constexpr double kSchurOutOfCoreFactorBytes = 256.0 * (1 << 20);

/// A bulk whose Cholesky factor CHOLMOD's analysis expects to take more than this share of the memory available is
/// not factorised in memory: MUMPS's factorisation for P is kept instead, out of core, and solves the bulk from disk
/// (docs/theory/static_condensation.md §2).
inline constexpr double kBulkInCoreShare = 0.5;

namespace detail {

/// How MUMPS factorises [A_BB A_BC; A_CB 0] (SYM): the whole matrix (LU), or its lower triangle when A_CB = A_BCᵀ,
/// with A_BB positive definite (LDLᵀ, no pivoting) or of any inertia (LDLᵀ with 2×2 pivots).
enum class SchurSymmetry { UNSYMMETRIC = 0, POSITIVE_DEFINITE = 1, SYMMETRIC = 2 };

/// MUMPS's factorisation of [A_BB A_BC; A_CB 0] with C eliminated last (ICNTL(19)): P = A_CB A_BB⁻¹ A_BC is minus its
/// Schur complement on C, one sparse factorisation instead of n_C solves with a bulk factor. While kept, the factor
/// also solves A_BB x = b (job 3 with ICNTL(26) = 0: the internal problem, C held at zero).
class MumpsSchurFactorisation {
public:
    MumpsSchurFactorisation();
    ~MumpsSchurFactorisation();
    MumpsSchurFactorisation(const MumpsSchurFactorisation&) = delete;
    MumpsSchurFactorisation& operator=(const MumpsSchurFactorisation&) = delete;

    /// @param a_bb the bulk block A_BB (n_B × n_B)
    /// @param a_bc the coupling block A_BC (n_B × n_C)
    /// @param a_cb the coupling block A_CB (n_C × n_B)
    /// @param symmetry how MUMPS factorises (the symmetric kinds read the lower triangles only)
    /// @param bulk_order elimination order of the bulk (CHOLMOD's), or empty for MUMPS's own
    /// @param[out] rProduct P, n_C × n_C; MUMPS writes into its storage, which must outlive a kept factor
    /// @param out_of_core_bytes factors expected above this size go to the temporary directory (TMPDIR, else /tmp)
    /// @return false if MUMPS fails (nothing is kept)
    bool Compute(const SparseMatrixType& a_bb, const SparseMatrixType& a_bc, const SparseMatrixType& a_cb,
                 SchurSymmetry symmetry, const std::vector<int>& bulk_order, Eigen::MatrixXd& rProduct,
                 double out_of_core_bytes);
    /// @param rhs n_B rows @return A_BB⁻¹ rhs from the kept factor @throws ConvergenceError if MUMPS fails
    Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const;
    /// True when the factor is out of core.
    bool OutOfCore() const;
    /// Frees the factor and deletes its files.
    void Release();

private:
    struct Instance;
    std::unique_ptr<Instance> mInstance;
};

/// P alone: MumpsSchurFactorisation::Compute, then its factor released. @return false if MUMPS fails
bool SchurProductWithMumps(const SparseMatrixType& a_bb, const SparseMatrixType& a_bc, const SparseMatrixType& a_cb,
                           SchurSymmetry symmetry, const std::vector<int>& bulk_order, Eigen::MatrixXd& rProduct,
                           double out_of_core_bytes = kSchurOutOfCoreFactorBytes);

}  // namespace detail

/// Solves A x = b by condensing a constant bulk onto the contact interface (docs/theory/static_condensation.md).
/// Interface I: every DoF of the INTERFACE nodes and every DoF that is not a displacement (the multipliers);
/// bulk B: the other equations, coupled by the elements only. With linear bodies A_BB, A_BI and A_IB do not
/// change, so the bulk is factorised once (CHOLMOD if symmetric, else UMFPACK), P = A_IB A_BB⁻¹ A_BI is kept
/// dense (MUMPS's Schur complement), and each solve is  S = A_II − P,  S x_I = b_I − A_IB A_BB⁻¹ b_B (dense
/// LU),  x_B = A_BB⁻¹(b_B − A_BI x_I).
/// Every solve hashes the B rows and columns: a changed bulk is condensed again, one that changes on two
/// consecutive solves ends the condensation. Without DoF data (master–slave constraints), or when it does not
/// apply, the inner solver solves the full system; Statistics().condensation says which and why.
class StaticCondensationSolver : public LinearSolver {
public:
    /// @param[in] inner solver of the full system when not condensing (not null, shared with the caller)
    /// @param[in] mode when to condense (linear_solver_settings.static_condensation)
    /// @param[in] bulk_not_linear why the bodies' stiffness may change ("" = it does not); "auto" then refuses
    StaticCondensationSolver(LinearSolver::Pointer inner, StaticCondensationMode mode, std::string bulk_not_linear = "");
    ~StaticCondensationSolver() override;

    /// @throws ConvergenceError if the interface system is singular, naming its size
    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    /// Clears the inner solver only: the condensed bulk is checked at every solve and survives the
    /// DoF-set rebuild of every contact step.
    void Clear() override;
    std::string Info() const override;
    std::size_t NumberOfSymbolicAnalyses() const override { return mInner->NumberOfSymbolicAnalyses(); }
    /// The inner solver's figures plus the condensation fields.
    LinearSolverStatistics Statistics() const override;
    bool AdditionalPhysicalDataIsNeeded() const override { return true; }
    /// Classifies the equations (interface or bulk) and passes the data on to the inner solver.
    void ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) override;

    /// Whether the last Solve was condensed.
    bool LastSolveWasCondensed() const { return mLastCondensed; }
    /// Bulk factors CHOLMOD expects above @p bytes are kept out of core by MUMPS instead (0: always; negative, the
    /// default: kBulkInCoreShare of the memory available when the bulk is factorised).
    void SetBulkInCoreLimit(double bytes) { mBulkInCoreBytes = bytes; }
    /// The solver of the full system.
    LinearSolver::Pointer InnerSolver() const { return mInner; }

private:
    struct Bulk;
    /// "" if the condensation applies to the system described by the last data, else why not.
    std::string Refusal(std::size_t size, std::size_t interface_size) const;
    /// Classifies the equations of a system of @p size (mIsInterface, mLocal and the keys).
    void Partition(std::size_t size);
    /// Hash of every non-zero of A off the interface block; @p rDofHashes gets one per bulk DoF.
    std::uint64_t BulkHash(const SparseMatrixType& rA, std::vector<std::uint64_t>& rDofHashes) const;
    void Condense(const SparseMatrixType& rA, std::uint64_t hash, std::vector<std::uint64_t> dof_hashes);
    /// Fills @p rBulk's coupled DoFs, A_BC and A_CB; returns A_BB.
    SparseMatrixType ExtractBlocks(const SparseMatrixType& rA, Bulk& rBulk) const;
    /// Factorises A_BB into @p rBulk and forms P. @throws ConvergenceError if A_BB is singular
    void FactoriseBulk(SparseMatrixType a_bb, Bulk& rBulk) const;
    /// True if every interface DoF of the condensed bulk is an interface equation of this system.
    bool CoupledDofsPresent(std::size_t size) const;
    void SolveCondensed(const SparseMatrixType& rA, SystemVectorType& rX, const SystemVectorType& rB);

    LinearSolver::Pointer mInner;
    StaticCondensationMode mMode;
    std::string mBulkNotLinear;
    bool mHaveData = false;
    std::vector<const Dof*> mDofs;          // the DoF set of the next solve
    std::unordered_set<const Node*> mConditionNodes;  // nodes of the model part's conditions
    std::unordered_set<const Node*> mPromotedNodes;   // bulk nodes whose rows changed once: interface for the run
    std::vector<const Dof*> mDofOfEquation;  // per equation of the next solve
    std::vector<char> mIsInterface;        // per equation of the next solve
    std::vector<int> mLocal;               // position of each equation in its set (I or B)
    std::vector<const Dof*> mInterfaceKey;  // the DoFs of each set, in equation order
    std::vector<const Dof*> mBulkKey;
    std::unique_ptr<Bulk> mBulk;
    bool mBulkChangedLastSolve = false;
    std::string mStopped;  // why the condensation was given up for the run ("" = it was not)
    bool mLastCondensed = false;
    double mBulkInCoreBytes = -1.0;
    LinearSolverStatistics mStatistics;
};

}  // namespace contact_app
