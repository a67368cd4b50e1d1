// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The interface between PetscKrylovSolver (in the solving library) and the PETSc plugin
// (libcontact_app_petsc.so, built from petsc_plugin/ when PETSc is found). The plugin is loaded with dlopen
// in its own symbol scope: Debian's PETSc brings the MPI build of MUMPS and the real MPI library, which
// must not meet the sequential MUMPS and its MPI stub linked into the module (docs/architecture.md,
// "Dependencies"). Only plain data crosses this boundary (no exceptions, no STL), so the two sides share
// nothing but this header.

#include <cstddef>

namespace contact_app::petsc_plugin {

/// Version of this interface; the plugin refuses another.
inline constexpr int kInterfaceVersion = 2;

/// What the Krylov solver is asked to do (the Kratos amgcl keys, mapped by PetscKrylovSolver).
struct Options {
    int interface_version = kInterfaceVersion;
    const char* krylov = "gmres";        ///< PETSc KSPType: gmres, fgmres, lgmres, cg, bcgs, bcgsl
    const char* preconditioner = "gamg"; ///< PETSc PCType: gamg, hypre (BoomerAMG), jacobi, sor, bjacobi, none
    /// Smoother of the AMG levels, or the whole preconditioner under preconditioner "relaxation":
    /// sor (Gauss-Seidel sweeps, the default: 4x fewer iterations than Chebyshev + Jacobi on the condensed 3D Hertz
    /// systems), chebyshev (+ Jacobi), jacobi (damped), ilu (block Jacobi + ILU(0)). Richardson sweeps except chebyshev.
    const char* smoother = "sor";
    double tolerance = 1.0e-6;  ///< relative true residual ‖b − A x‖ / ‖b‖
    int max_iteration = 1000;
    int restart = 100;          ///< GMRES restart (Kratos gmres_krylov_space_dimension)
    int smoothing_steps = 1;    ///< smoother sweeps per level (pre_sweeps = post_sweeps)
    int max_levels = -1;        ///< -1 = PETSc's choice
    int coarse_enough = 1000;   ///< coarsest level size
    int aggregation_smoothing = 1;  ///< GAMG prolongator smoothing steps (0 = plain aggregation)
    int verbosity = 0;          ///< 0 silent, 1 one line per solve, 2 the residual history
    const char* extra_options = "";  ///< PETSc options string applied last (CONTACT_APP_PETSC_OPTIONS)
    /// 1: keep the preconditioner while the pattern stays (Kratos reform_preconditioner_at_each_step false);
    /// the Mat and KSP are kept either way.
    int reuse_preconditioner = 0;
    /// 1: a GAMG set-up on new values of the same pattern keeps the prolongators (PCGAMGSetReuseInterpolation)
    /// and recomputes only the coarse operators and smoothers. A solve that fails with what was kept (either
    /// reuse) is redone after a complete set-up.
    int reuse_interpolation = 0;
};

/// One solve. Rank 0 passes the system; the other ranks pass size = -1 (they receive their rows from rank 0).
/// Row i of the CSR (row_start[i] .. row_start[i + 1]) holds the sorted columns of row i.
struct System {
    long size = -1;
    int block_size = 1;                 ///< size is a multiple of it (nodal blocks of the displacements)
    const long* row_start = nullptr;    ///< size + 1
    const int* columns = nullptr;
    const double* values = nullptr;
    const double* rhs = nullptr;        ///< size
    /// Values of the preconditioning matrix on the same pattern (null = the system matrix): the system matrix
    /// with the zero diagonals of the uncondensed multiplier rows regularised, so the smoothers can divide.
    const double* preconditioner_values = nullptr;
    double diagonal_scale = 1.0;        ///< largest |a_ii| (the smoother's zero-pivot shift is relative to it)
    int near_null_space_count = 0;      ///< orthonormal vectors the AMG must reproduce (rigid-body modes)
    const double* near_null_space = nullptr;  ///< near_null_space_count × size, vector after vector
};

/// What a solve did.
struct Result {
    int converged = 0;        ///< 1 if the tolerance was met
    int iterations = 0;
    double relative_residual = 0.0;  ///< ‖b − A x‖ / ‖b‖ at the end
    int ranks = 1;
    double setup_seconds = 0.0;      ///< matrix distribution + preconditioner set-up (wall)
    double solve_seconds = 0.0;      ///< Krylov iterations (wall)
    double preconditioner_memory = 0.0;  ///< bytes PETSc holds after the set-up (PetscMallocGetCurrentUsage), -1 unknown
    int levels = 0;                  ///< multigrid levels (0 = not a multigrid)
    int preconditioner_set_up = 0;   ///< 1 if the preconditioner was set up for this solve, 0 if reused
    int pattern_reused = 0;          ///< 1 if the Mat and KSP of the previous solve were kept (same pattern)
    int retried = 0;                 ///< 1 if the reused preconditioner failed and the solve was redone after a set-up
    char reason[96] = {};            ///< KSPConvergedReason as text
    char description[160] = {};      ///< "gmres(100) + gamg (chebyshev/jacobi), 4 levels"
};

/// The plugin's solver object (created by the factory below, deleted through Destroy()).
class Backend {
public:
    virtual ~Backend() = default;
    /// Solves; the solution (size entries) is written to @p x on every rank. Returns 0, or a PETSc/MPI
    /// error code with @p message filled. The Mat, Vec and KSP objects are kept for the next solve while the
    /// pattern stays (size, block size, row_start, columns, near-null-space count, preconditioner_values given
    /// or not; rank 0 decides): only the values are then copied in.
    virtual int Solve(const System& system, double* x, Result* result, char* message, std::size_t message_size) = 0;
    /// This process's rank and the number of ranks of PETSC_COMM_WORLD.
    virtual int Rank() const = 0;
    virtual int Ranks() const = 0;
    virtual void Destroy() = 0;
};

/// extern "C" entry point of the plugin: initialises PETSc (and MPI) once, then creates a solver.
/// Returns nullptr with @p message filled on failure.
using CreateFunction = Backend* (*)(const Options* options, char* message, std::size_t message_size);
inline constexpr const char* kCreateSymbol = "contact_app_petsc_create";
inline constexpr const char* kLibraryName = "libcontact_app_petsc.so";

}  // namespace contact_app::petsc_plugin
