// SPDX-License-Identifier: BSD-3-Clause
// The PETSc plugin (libcontact_app_petsc.so): Krylov + algebraic multigrid on PETSc's Mat, KSP and PC, with the
// system assembled on rank 0 and its rows distributed over PETSC_COMM_WORLD. Loaded by PetscKrylovSolver
// through dlopen (petsc_krylov_backend.h says why); docs/running.md, "Iterative solver (PETSc)".

#include <petsc.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "contact_app/solving/linear_solvers/petsc_krylov_backend.h"

namespace contact_app::petsc_plugin {
namespace {

bool g_we_initialised = false;

void Finalise() {
    PetscBool finalised = PETSC_FALSE;
    PetscFinalized(&finalised);
    if (g_we_initialised && !finalised) PetscFinalize();
}

/// PetscInitialize once per process, without PETSc's signal handlers (Python keeps its own).
int Initialise(std::string& message) {
    PetscBool initialised = PETSC_FALSE;
    PetscInitialized(&initialised);
    if (initialised) return 0;
    PetscErrorCode error = PetscOptionsSetValue(nullptr, "-no_signal_handler", nullptr);
    if (!error) error = PetscInitializeNoArguments();
    if (error) {
        message = "PetscInitialize failed with error " + std::to_string(error);
        return error;
    }
    g_we_initialised = true;
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    std::atexit(Finalise);
    return 0;
}

std::string ErrorText(PetscErrorCode code, const char* where) {
    const char* text = nullptr;
    PetscErrorMessage(code, &text, nullptr);
    return std::string(where) + ": PETSc error " + std::to_string(code) + (text ? std::string(" (") + text + ")" : "");
}

#define PLUGIN_CALL(call)                                      \
    do {                                                       \
        const PetscErrorCode plugin_error_ = (call);           \
        if (plugin_error_) {                                   \
            failure = ErrorText(plugin_error_, #call);         \
            return static_cast<int>(plugin_error_);            \
        }                                                      \
    } while (0)

double Seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

class PetscBackend final : public Backend {
public:
    explicit PetscBackend(const Options& options) : mOptions(options) {
        // Keep copies of the strings (the caller's may not outlive this object).
        mKrylov = options.krylov ? options.krylov : "gmres";
        mPreconditioner = options.preconditioner ? options.preconditioner : "gamg";
        mSmoother = options.smoother ? options.smoother : "";
        mExtra = options.extra_options ? options.extra_options : "";
        MPI_Comm_rank(PETSC_COMM_WORLD, &mRank);
        MPI_Comm_size(PETSC_COMM_WORLD, &mRanks);
    }
    ~PetscBackend() override = default;

    int Rank() const override { return mRank; }
    int Ranks() const override { return mRanks; }
    void Destroy() override { delete this; }

    int Solve(const System& system, double* x, Result* result, char* message, std::size_t message_size) override {
        std::string failure;
        Mat a = nullptr, p = nullptr;
        Vec b = nullptr, solution = nullptr;
        KSP ksp = nullptr;
        std::vector<Vec> modes;
        MatNullSpace near_null = nullptr;
        const int code = Run(system, x, *result, failure, a, p, b, solution, ksp, modes, near_null);
        if (code) {
            // After a PETSc error the objects may be half-built (destroying them crashed in PCReset_MG): keep them.
            if (message && message_size) std::snprintf(message, message_size, "%s", failure.c_str());
            return code;
        }
        if (near_null) MatNullSpaceDestroy(&near_null);
        for (Vec& mode : modes) VecDestroy(&mode);
        if (ksp) KSPDestroy(&ksp);
        if (solution) VecDestroy(&solution);
        if (b) VecDestroy(&b);
        if (a) MatDestroy(&a);
        if (p) MatDestroy(&p);
        if (code && message && message_size) std::snprintf(message, message_size, "%s", failure.c_str());
        return code;
    }

private:
    int Run(const System& system, double* x, Result& result, std::string& failure, Mat& a, Mat& p, Vec& b,
            Vec& solution, KSP& ksp, std::vector<Vec>& modes, MatNullSpace& near_null) {
        const auto start = std::chrono::steady_clock::now();
        const MPI_Comm comm = PETSC_COMM_WORLD;
        // Sizes from rank 0.
        long header[4] = {system.size, system.block_size, system.near_null_space_count,
                          system.preconditioner_values != nullptr ? 1 : 0};
        MPI_Bcast(header, 4, MPI_LONG, 0, comm);
        double scale = system.diagonal_scale;
        MPI_Bcast(&scale, 1, MPI_DOUBLE, 0, comm);
        mShift = 1.0e-10 * scale;
        const bool separate_preconditioner = header[3] != 0;
        const long n = header[0];
        const int bs = static_cast<int>(std::max(1L, header[1]));
        const int mode_count = static_cast<int>(header[2]);
        if (n < 0 || n % bs != 0) {
            failure = "system of " + std::to_string(n) + " rows is not made of blocks of " + std::to_string(bs);
            return 1;
        }
        // Rows per rank, in whole blocks.
        const long blocks = n / bs;
        std::vector<long> first(mRanks + 1, 0);
        for (int r = 0; r < mRanks; ++r) first[r + 1] = first[r] + (blocks / mRanks + (r < blocks % mRanks ? 1 : 0)) * bs;
        const long local = first[mRank + 1] - first[mRank];

        // Row lengths, columns and values of each rank's rows, scattered from rank 0.
        std::vector<int> counts(mRanks), offsets(mRanks);
        for (int r = 0; r < mRanks; ++r) {
            counts[r] = static_cast<int>(first[r + 1] - first[r]);
            offsets[r] = static_cast<int>(first[r]);
        }
        std::vector<long> lengths;
        if (mRank == 0) {
            lengths.resize(n);
            for (long i = 0; i < n; ++i) lengths[i] = system.row_start[i + 1] - system.row_start[i];
        }
        std::vector<long> local_lengths(local);
        MPI_Scatterv(lengths.data(), counts.data(), offsets.data(), MPI_LONG, local_lengths.data(),
                     static_cast<int>(local), MPI_LONG, 0, comm);
        std::vector<int> entry_counts(mRanks), entry_offsets(mRanks);
        if (mRank == 0)
            for (int r = 0; r < mRanks; ++r) {
                entry_offsets[r] = static_cast<int>(system.row_start[first[r]]);
                entry_counts[r] = static_cast<int>(system.row_start[first[r + 1]] - system.row_start[first[r]]);
            }
        std::vector<PetscInt> row_start(local + 1, 0);
        for (long i = 0; i < local; ++i) row_start[i + 1] = row_start[i] + static_cast<PetscInt>(local_lengths[i]);
        const int local_entries = static_cast<int>(row_start[local]);
        std::vector<PetscInt> columns(local_entries);
        std::vector<PetscScalar> values(local_entries);
        static_assert(sizeof(PetscInt) == sizeof(int), "the plugin expects 32-bit PetscInt (Debian libpetsc-real)");
        MPI_Scatterv(system.columns, entry_counts.data(), entry_offsets.data(), MPI_INT, columns.data(), local_entries,
                     MPI_INT, 0, comm);
        MPI_Scatterv(system.values, entry_counts.data(), entry_offsets.data(), MPI_DOUBLE, values.data(),
                     local_entries, MPI_DOUBLE, 0, comm);

        PLUGIN_CALL(MatCreate(comm, &a));
        PLUGIN_CALL(MatSetSizes(a, static_cast<PetscInt>(local), static_cast<PetscInt>(local), static_cast<PetscInt>(n),
                                static_cast<PetscInt>(n)));
        PLUGIN_CALL(MatSetBlockSize(a, bs));
        PLUGIN_CALL(MatSetType(a, MATAIJ));
        PLUGIN_CALL(MatSeqAIJSetPreallocationCSR(a, row_start.data(), columns.data(), values.data()));
        PLUGIN_CALL(MatMPIAIJSetPreallocationCSR(a, row_start.data(), columns.data(), values.data()));
        if (separate_preconditioner) {
            MPI_Scatterv(system.preconditioner_values, entry_counts.data(), entry_offsets.data(), MPI_DOUBLE,
                         values.data(), local_entries, MPI_DOUBLE, 0, comm);
            PLUGIN_CALL(MatCreate(comm, &p));
            PLUGIN_CALL(MatSetSizes(p, static_cast<PetscInt>(local), static_cast<PetscInt>(local),
                                    static_cast<PetscInt>(n), static_cast<PetscInt>(n)));
            PLUGIN_CALL(MatSetBlockSize(p, bs));
            PLUGIN_CALL(MatSetType(p, MATAIJ));
            PLUGIN_CALL(MatSeqAIJSetPreallocationCSR(p, row_start.data(), columns.data(), values.data()));
            PLUGIN_CALL(MatMPIAIJSetPreallocationCSR(p, row_start.data(), columns.data(), values.data()));
        }
        columns = {};
        values = {};

        // Right-hand side, scattered the same way.
        PLUGIN_CALL(MatCreateVecs(a, &solution, &b));
        {
            PetscScalar* local_b = nullptr;
            PLUGIN_CALL(VecGetArray(b, &local_b));
            MPI_Scatterv(system.rhs, counts.data(), offsets.data(), MPI_DOUBLE, local_b, static_cast<int>(local),
                         MPI_DOUBLE, 0, comm);
            PLUGIN_CALL(VecRestoreArray(b, &local_b));
        }
        // Near-null space (orthonormal on rank 0).
        for (int k = 0; k < mode_count; ++k) {
            Vec mode = nullptr;
            PLUGIN_CALL(VecDuplicate(b, &mode));
            modes.push_back(mode);
            PetscScalar* local_mode = nullptr;
            PLUGIN_CALL(VecGetArray(mode, &local_mode));
            MPI_Scatterv(mRank == 0 ? system.near_null_space + static_cast<std::size_t>(k) * n : nullptr, counts.data(),
                         offsets.data(), MPI_DOUBLE, local_mode, static_cast<int>(local), MPI_DOUBLE, 0, comm);
            PLUGIN_CALL(VecRestoreArray(mode, &local_mode));
        }
        if (mode_count > 0) {
            PLUGIN_CALL(MatNullSpaceCreate(comm, PETSC_FALSE, mode_count, modes.data(), &near_null));
            PLUGIN_CALL(MatSetNearNullSpace(p != nullptr ? p : a, near_null));
        }

        PLUGIN_CALL(KSPCreate(comm, &ksp));
        PLUGIN_CALL(KSPSetOptionsPrefix(ksp, "contact_"));
        PLUGIN_CALL(SetOptions());
        PLUGIN_CALL(KSPSetOperators(ksp, a, p != nullptr ? p : a));
        PLUGIN_CALL(KSPSetFromOptions(ksp));
        PLUGIN_CALL(KSPSetUp(ksp));
        result.setup_seconds = Seconds(start);
        PetscLogDouble memory = 0.0;
        result.preconditioner_memory = PetscMemoryGetCurrentUsage(&memory) == 0 ? memory : -1.0;

        const auto solve_start = std::chrono::steady_clock::now();
        PLUGIN_CALL(KSPSolve(ksp, b, solution));
        result.solve_seconds = Seconds(solve_start);
        KSPConvergedReason reason;
        PetscInt iterations = 0;
        PLUGIN_CALL(KSPGetConvergedReason(ksp, &reason));
        PLUGIN_CALL(KSPGetIterationNumber(ksp, &iterations));
        // The true relative residual, whatever norm the Krylov method monitored.
        {
            Vec residual = nullptr;
            PLUGIN_CALL(VecDuplicate(b, &residual));
            PLUGIN_CALL(MatMult(a, solution, residual));
            PLUGIN_CALL(VecAYPX(residual, -1.0, b));
            PetscReal r_norm = 0.0, b_norm = 0.0;
            PLUGIN_CALL(VecNorm(residual, NORM_2, &r_norm));
            PLUGIN_CALL(VecNorm(b, NORM_2, &b_norm));
            VecDestroy(&residual);
            result.relative_residual = b_norm > 0.0 ? r_norm / b_norm : r_norm;
        }
        // Converged by PETSc's test and by the true residual (10x margin for the round-off of the recurrences).
        result.converged = reason > 0 && result.relative_residual <= 10.0 * mOptions.tolerance ? 1 : 0;
        result.iterations = static_cast<int>(iterations);
        result.ranks = mRanks;
        PC pc = nullptr;
        PLUGIN_CALL(KSPGetPC(ksp, &pc));
        std::string reason_text = KSPConvergedReasons[reason];
        if (reason == KSP_DIVERGED_PC_FAILED) {
            PCFailedReason pc_reason;
            PLUGIN_CALL(PCGetFailedReasonRank(pc, &pc_reason));
            reason_text += std::string(": ") + PCFailedReasons[pc_reason];
        }
        std::snprintf(result.reason, sizeof(result.reason), "%s", reason_text.c_str());
        PCType pc_type = nullptr;
        PLUGIN_CALL(PCGetType(pc, &pc_type));
        KSPType ksp_type = nullptr;
        PLUGIN_CALL(KSPGetType(ksp, &ksp_type));
        PetscBool is_mg = PETSC_FALSE;
        PLUGIN_CALL(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(pc), &is_mg, PCGAMG, PCMG, ""));
        result.levels = 0;
        if (is_mg) {
            PetscInt levels = 0;
            PLUGIN_CALL(PCMGGetLevels(pc, &levels));
            result.levels = static_cast<int>(levels);
        }
        mLastSize = n;
        mLastRegularised = separate_preconditioner;
        std::string description = std::string(ksp_type) + " + " + pc_type;
        if (result.levels > 0) description += ", " + std::to_string(result.levels) + " levels";
        if (mRanks > 1) description += ", " + std::to_string(mRanks) + " MPI ranks";
        std::snprintf(result.description, sizeof(result.description), "%s", description.c_str());

        // The solution, gathered on every rank.
        const PetscScalar* local_x = nullptr;
        PLUGIN_CALL(VecGetArrayRead(solution, &local_x));
        MPI_Allgatherv(local_x, static_cast<int>(local), MPI_DOUBLE, x, counts.data(), offsets.data(), MPI_DOUBLE, comm);
        PLUGIN_CALL(VecRestoreArrayRead(solution, &local_x));
        if (mOptions.verbosity > 0 && mRank == 0)
            std::printf("petsc: %s, %ld equations%s, %d iterations, relative residual %.3e (%s), set-up %.3f s, "
                        "solve %.3f s\n",
                        result.description, mLastSize, mLastRegularised ? " (zero diagonals regularised)" : "",
                        result.iterations, result.relative_residual, result.reason, result.setup_seconds,
                        result.solve_seconds);
        return 0;
    }

    /// The options of this solver under the prefix "contact_", then the user's extra string.
    PetscErrorCode SetOptions() const {
        PetscCall(SetOwnOptions());
        if (!mExtra.empty()) PetscCall(PetscOptionsInsertString(nullptr, mExtra.c_str()));
        return 0;
    }

    PetscErrorCode SetOwnOptions() const {
        // The options database is global: first clear what an earlier solver set.
        static std::vector<std::string> keys_set;
        for (const std::string& key : keys_set) PetscCall(PetscOptionsClearValue(nullptr, key.c_str()));
        keys_set.clear();
        auto set = [](const std::string& key, const std::string& value) {
            keys_set.push_back("-contact_" + key);
            return PetscOptionsSetValue(nullptr, keys_set.back().c_str(), value.empty() ? nullptr : value.c_str());
        };
        PetscCall(set("ksp_type", mKrylov));
        char tolerance[32];
        std::snprintf(tolerance, sizeof(tolerance), "%.17g", mOptions.tolerance);  // not to_string: 1e-10 -> "0.000000"
        PetscCall(set("ksp_rtol", tolerance));
        PetscCall(set("ksp_atol", "1e-300"));
        PetscCall(set("ksp_max_it", std::to_string(mOptions.max_iteration)));
        PetscCall(set("ksp_gmres_restart", std::to_string(mOptions.restart)));
        // Right preconditioning: the Krylov method then measures the true residual (GMRES, BiCGSTAB); CG
        // (left only) is told to.
        if (mKrylov == "cg") {  // left preconditioning only
            PetscCall(set("ksp_pc_side", "left"));
            PetscCall(set("ksp_norm_type", "unpreconditioned"));
        } else if (mKrylov == "bcgsl") {  // left only, its own norm (right gave a wrong x); the true residual is checked
            PetscCall(set("ksp_pc_side", "left"));
        } else {
            PetscCall(set("ksp_pc_side", "right"));
        }
        if (mOptions.verbosity >= 2) PetscCall(set("ksp_monitor_true_residual", ""));
        const bool relaxation_only = mPreconditioner != "gamg" && mPreconditioner != "hypre";
        if (relaxation_only) {
            PetscCall(set("pc_type", mPreconditioner));
            if (mPreconditioner == "bjacobi") PetscCall(set("sub_pc_type", "ilu"));
            return 0;
        }
        PetscCall(set("pc_type", mPreconditioner));
        if (mPreconditioner == "hypre") {
            PetscCall(set("pc_hypre_type", "boomeramg"));
            if (mOptions.max_levels > 0) PetscCall(set("pc_hypre_boomeramg_max_levels", std::to_string(mOptions.max_levels)));
            PetscCall(set("pc_hypre_boomeramg_grid_sweeps_all", std::to_string(mOptions.smoothing_steps)));
            return 0;
        }
        PetscCall(set("pc_gamg_type", "agg"));
        PetscCall(set("pc_gamg_agg_nsmooths", std::to_string(mOptions.aggregation_smoothing)));
        PetscCall(set("pc_gamg_coarse_eq_limit", std::to_string(mOptions.coarse_enough)));
        if (mOptions.max_levels > 0) PetscCall(set("pc_mg_levels", std::to_string(mOptions.max_levels)));
        PetscCall(set("mg_levels_ksp_max_it", std::to_string(mOptions.smoothing_steps)));
        // A Galerkin coarse operator of the condensed contact system can have a zero diagonal: SOR then divides by
        // a shift of 1e-10 of the largest fine diagonal instead of failing.
        char shift[32];
        std::snprintf(shift, sizeof(shift), "%.6e", mShift);
        PetscCall(set("mg_levels_pc_sor_diagonal_shift", shift));
        if (mSmoother == "chebyshev") {
            PetscCall(set("mg_levels_ksp_type", "chebyshev"));
            PetscCall(set("mg_levels_pc_type", "jacobi"));
        } else {
            PetscCall(set("mg_levels_ksp_type", "richardson"));
            if (mSmoother == "ilu") {
                PetscCall(set("mg_levels_pc_type", "bjacobi"));
                PetscCall(set("mg_levels_sub_pc_type", "ilu"));
            } else {
                PetscCall(set("mg_levels_pc_type", mSmoother));
            }
            if (mSmoother == "jacobi") PetscCall(set("mg_levels_ksp_richardson_scale", "0.72"));
        }
        return 0;
    }

    Options mOptions;
    double mShift = 0.0;
    long mLastSize = 0;
    bool mLastRegularised = false;
    std::string mKrylov, mPreconditioner, mSmoother, mExtra;
    int mRank = 0, mRanks = 1;
};

}  // namespace
}  // namespace contact_app::petsc_plugin

extern "C" __attribute__((visibility("default"))) contact_app::petsc_plugin::Backend* contact_app_petsc_create(
    const contact_app::petsc_plugin::Options* options, char* message, std::size_t message_size) {
    using namespace contact_app::petsc_plugin;
    std::string failure;
    if (options == nullptr || options->interface_version != kInterfaceVersion) {
        std::snprintf(message, message_size, "libcontact_app_petsc.so was built for another version of contact_app");
        return nullptr;
    }
    if (Initialise(failure)) {
        std::snprintf(message, message_size, "%s", failure.c_str());
        return nullptr;
    }
    return new PetscBackend(*options);
}
