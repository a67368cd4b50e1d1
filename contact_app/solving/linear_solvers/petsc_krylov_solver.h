// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/linear_solvers/petsc_krylov_backend.h"

namespace contact_app {

/// The Kratos amgcl settings a Krylov solver takes (linear_solver_settings; docs/running.md,
/// "Iterative solver (PETSc)"). Empty strings are the defaults.
struct KrylovSettings {
    double tolerance = 1.0e-6;          ///< relative true residual ‖b − Ax‖/‖b‖
    int max_iteration = 1000;
    std::string krylov_type;            ///< gmres (default), fgmres, lgmres, cg, bicgstab, bicgstabl
    std::string preconditioner_type;    ///< amg (default), relaxation, diagonal, ilu0, none/dummy
    std::string smoother_type;          ///< gauss_seidel (default), chebyshev, damped_jacobi, spai0, ilu0, ilut, iluk
    std::string coarsening_type;        ///< smoothed_aggregation (default), aggregation, ruge_stuben (BoomerAMG)
    int gmres_krylov_space_dimension = 100;
    int verbosity = 0;
    int max_levels = -1;
    int coarse_enough = 1000;
    int pre_sweeps = 1;
    int post_sweeps = 1;
    /// false: the preconditioner is set up on the first solve and again only when the sparsity pattern
    /// changes (or a solve with it fails); true: on every solve.
    bool reform_preconditioner_at_each_step = true;
};

/// The plugin options these settings map to. @throws InputError naming the linear_solver_settings key of an
/// unknown value, with the accepted ones.
petsc_plugin::Options PetscOptionsFromSettings(const KrylovSettings& settings);

/// Whether this build has the PETSc plugin and it loads; "" if so, else why not and which package provides it.
std::string PetscUnavailableReason();

/// Krylov + algebraic multigrid on PETSc (Mat, KSP, PC): GMRES (or the krylov_type) preconditioned by GAMG
/// smoothed aggregation with the rigid-body modes as near-null space (BoomerAMG under coarsening_type
/// "ruge_stuben"). The system arrives assembled on every rank; rank 0's copy is distributed row-wise over
/// PETSC_COMM_WORLD (one rank in a plain run, all of them under mpirun) and the solution is gathered back
/// on every rank. The displacement unknowns are renumbered into nodal blocks (block size = dimension) and the
/// rigid-body modes are built from the node coordinates of the DoF set (ProvideAdditionalData, or the layout
/// of a reduced system from MixedULMLinearSolver).
class PetscKrylovSolver : public LinearSolver {
public:
    /// @throws InputError for unknown settings; ConfigurationError when PETSc is not available, naming the
    /// package that provides it.
    explicit PetscKrylovSolver(const KrylovSettings& settings);
    ~PetscKrylovSolver() override;

    /// @throws ConvergenceError when the tolerance is not met: the Newton step, the iterations, the residual
    /// reached and what to change.
    void Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) override;
    std::string Info() const override { return "petsc"; }
    LinearSolverStatistics Statistics() const override { return mStatistics; }
    bool AdditionalPhysicalDataIsNeeded() const override { return true; }
    void ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) override;
    bool UnknownLayoutIsNeeded() const override { return true; }
    void ProvideUnknownLayout(UnknownLayout layout) override;

    /// This process's MPI rank and the number of ranks.
    int Rank() const;
    int Ranks() const;

private:
    KrylovSettings mSettings;
    petsc_plugin::Options mOptions;
    std::string mExtraOptions;  // CONTACT_APP_PETSC_OPTIONS at construction
    petsc_plugin::Backend* mBackend = nullptr;
    UnknownLayout mLayout;
    bool mHaveLayout = false;
    LinearSolverStatistics mStatistics;
};

}  // namespace contact_app
