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
    ~PetscBackend() override { DestroyObjects(); }

    int Rank() const override { return mRank; }
    int Ranks() const override { return mRanks; }
    void Destroy() override { delete this; }

    int Solve(const System& system, double* x, Result* result, char* message, std::size_t message_size) override {
        std::string failure;
        const int code = Run(system, x, *result, failure);
        if (code) {
            // After a PETSc error the objects may be half-built (destroying them crashed in PCReset_MG): drop
            // them without destroying, and build new ones at the next solve.
            ForgetObjects();
            if (message && message_size) std::snprintf(message, message_size, "%s", failure.c_str());
        }
        return code;
    }

private:
    /// The layout of the system the kept objects were built for (every rank), and on rank 0 its CSR pattern.
    struct Pattern {
        long n = -1;
        int block_size = 0;
        int mode_count = 0;
        bool separate_preconditioner = false;
        std::vector<long> row_start;  // rank 0 of several (one rank compares with its own rows)
        std::vector<int> columns;
    };

    /// Whether rank 0's system has the pattern of the kept objects; collective, the same answer on every rank.
    bool SamePattern(const System& system, const long header[4]) const {
        int same = mKsp != nullptr ? 1 : 0;
        if (mRank == 0 && same) {
            const long n = header[0];
            const bool one = mRanks == 1;
            same = n == mPattern.n && header[1] == mPattern.block_size && header[2] == mPattern.mode_count &&
                   (header[3] != 0) == mPattern.separate_preconditioner &&
                   (one ? std::equal(system.row_start, system.row_start + n + 1, mLocalRowStart.begin())
                        : std::equal(system.row_start, system.row_start + n + 1, mPattern.row_start.begin())) &&
                   (one ? std::equal(system.columns, system.columns + system.row_start[n], mLocalColumns.begin())
                        : std::equal(system.columns, system.columns + system.row_start[n], mPattern.columns.begin()));
        }
        int all = 0;
        MPI_Allreduce(&same, &all, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD);
        return all != 0;
    }

    void DestroyObjects() {
        PetscBool finalised = PETSC_FALSE;
        PetscFinalized(&finalised);
        if (!finalised) {  // after PetscFinalize the objects are gone with it
            if (mKsp) KSPDestroy(&mKsp);
            if (mX) VecDestroy(&mX);
            if (mB) VecDestroy(&mB);
            if (mA) MatDestroy(&mA);
            if (mP) MatDestroy(&mP);
        }
        ForgetObjects();
    }

    void ForgetObjects() {
        mKsp = nullptr;
        mX = mB = nullptr;
        mA = mP = nullptr;
        mPattern = Pattern{};
    }

    /// An AIJ matrix of this rank's rows (global column indices, sorted in each row).
    int CreateMatrix(Mat& matrix, long local, long n, int bs, const std::vector<PetscInt>& row_start,
                     const std::vector<PetscInt>& columns, const std::vector<PetscScalar>& values,
                     std::string& failure) const {
        PLUGIN_CALL(MatCreate(PETSC_COMM_WORLD, &matrix));
        PLUGIN_CALL(MatSetSizes(matrix, static_cast<PetscInt>(local), static_cast<PetscInt>(local),
                                static_cast<PetscInt>(n), static_cast<PetscInt>(n)));
        PLUGIN_CALL(MatSetBlockSize(matrix, bs));
        PLUGIN_CALL(MatSetType(matrix, MATAIJ));
        PLUGIN_CALL(MatSeqAIJSetPreallocationCSR(matrix, row_start.data(), columns.data(), values.data()));
        PLUGIN_CALL(MatMPIAIJSetPreallocationCSR(matrix, row_start.data(), columns.data(), values.data()));
        return 0;
    }

    /// New values on the pattern the matrix was created with (this rank's rows, in its CSR order).
    int UpdateMatrix(Mat matrix, const std::vector<PetscScalar>& values, std::string& failure) const {
        if (mRanks == 1) {
            // One rank: the SeqAIJ arrays are our CSR (sorted columns, explicit zeros kept), copied in one go.
            PetscScalar* stored = nullptr;
            PLUGIN_CALL(MatSeqAIJGetArray(matrix, &stored));
            std::copy(values.begin(), values.end(), stored);
            PLUGIN_CALL(MatSeqAIJRestoreArray(matrix, &stored));
            return 0;
        }
        PetscInt first_row = 0;
        PLUGIN_CALL(MatGetOwnershipRange(matrix, &first_row, nullptr));
        for (std::size_t i = 0; i + 1 < mLocalRowStart.size(); ++i) {
            const PetscInt row = first_row + static_cast<PetscInt>(i);
            const PetscInt at = mLocalRowStart[i];
            PLUGIN_CALL(MatSetValues(matrix, 1, &row, mLocalRowStart[i + 1] - at, mLocalColumns.data() + at,
                                     values.data() + at, INSERT_VALUES));
        }
        PLUGIN_CALL(MatAssemblyBegin(matrix, MAT_FINAL_ASSEMBLY));
        PLUGIN_CALL(MatAssemblyEnd(matrix, MAT_FINAL_ASSEMBLY));
        return 0;
    }

    int Run(const System& system, double* x, Result& result, std::string& failure) {
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
        const bool same = SamePattern(system, header);
        // Rows per rank, in whole blocks.
        const long blocks = n / bs;
        std::vector<long> first(mRanks + 1, 0);
        for (int r = 0; r < mRanks; ++r) first[r + 1] = first[r] + (blocks / mRanks + (r < blocks % mRanks ? 1 : 0)) * bs;
        const long local = first[mRank + 1] - first[mRank];
        std::vector<int> counts(mRanks), offsets(mRanks);
        for (int r = 0; r < mRanks; ++r) {
            counts[r] = static_cast<int>(first[r + 1] - first[r]);
            offsets[r] = static_cast<int>(first[r]);
        }
        std::vector<int> entry_counts(mRanks), entry_offsets(mRanks);
        if (mRank == 0)
            for (int r = 0; r < mRanks; ++r) {
                entry_offsets[r] = static_cast<int>(system.row_start[first[r]]);
                entry_counts[r] = static_cast<int>(system.row_start[first[r + 1]] - system.row_start[first[r]]);
            }

        if (!same) {
            // A new pattern (or the first solve): new Mat, Vec and KSP objects.
            DestroyObjects();
            std::vector<long> lengths;
            if (mRank == 0) {
                lengths.resize(n);
                for (long i = 0; i < n; ++i) lengths[i] = system.row_start[i + 1] - system.row_start[i];
            }
            std::vector<long> local_lengths(local);
            MPI_Scatterv(lengths.data(), counts.data(), offsets.data(), MPI_LONG, local_lengths.data(),
                         static_cast<int>(local), MPI_LONG, 0, comm);
            mLocalRowStart.assign(local + 1, 0);
            for (long i = 0; i < local; ++i)
                mLocalRowStart[i + 1] = mLocalRowStart[i] + static_cast<PetscInt>(local_lengths[i]);
            mLocalColumns.resize(mLocalRowStart[local]);
            static_assert(sizeof(PetscInt) == sizeof(int), "the plugin expects 32-bit PetscInt (Debian libpetsc-real)");
            MPI_Scatterv(system.columns, entry_counts.data(), entry_offsets.data(), MPI_INT, mLocalColumns.data(),
                         static_cast<int>(mLocalColumns.size()), MPI_INT, 0, comm);
        }
        // This rank's values (and those of the preconditioning matrix), scattered from rank 0.
        const int local_entries = static_cast<int>(mLocalColumns.size());
        std::vector<PetscScalar> values(local_entries), preconditioner_values;
        MPI_Scatterv(system.values, entry_counts.data(), entry_offsets.data(), MPI_DOUBLE, values.data(),
                     local_entries, MPI_DOUBLE, 0, comm);
        if (separate_preconditioner) {
            preconditioner_values.resize(local_entries);
            MPI_Scatterv(system.preconditioner_values, entry_counts.data(), entry_offsets.data(), MPI_DOUBLE,
                         preconditioner_values.data(), local_entries, MPI_DOUBLE, 0, comm);
        }
        if (same) {
            if (int code = UpdateMatrix(mA, values, failure)) return code;
            if (separate_preconditioner)
                if (int code = UpdateMatrix(mP, preconditioner_values, failure)) return code;
        } else {
            if (int code = CreateMatrix(mA, local, n, bs, mLocalRowStart, mLocalColumns, values, failure)) return code;
            if (separate_preconditioner)
                if (int code = CreateMatrix(mP, local, n, bs, mLocalRowStart, mLocalColumns, preconditioner_values,
                                            failure))
                    return code;
            PLUGIN_CALL(MatCreateVecs(mA, &mX, &mB));
            PLUGIN_CALL(KSPCreate(comm, &mKsp));
            PLUGIN_CALL(KSPSetOptionsPrefix(mKsp, "contact_"));
            PLUGIN_CALL(SetOptions());
            PLUGIN_CALL(KSPSetFromOptions(mKsp));
            mPattern.n = n;
            mPattern.block_size = bs;
            mPattern.mode_count = mode_count;
            mPattern.separate_preconditioner = separate_preconditioner;
            if (mRank == 0 && mRanks > 1) {
                mPattern.row_start.assign(system.row_start, system.row_start + n + 1);
                mPattern.columns.assign(system.columns, system.columns + system.row_start[n]);
            }
        }
        values = {};
        preconditioner_values = {};
        Mat p = separate_preconditioner ? mP : mA;

        // Right-hand side, scattered the same way.
        {
            PetscScalar* local_b = nullptr;
            PLUGIN_CALL(VecGetArray(mB, &local_b));
            MPI_Scatterv(system.rhs, counts.data(), offsets.data(), MPI_DOUBLE, local_b, static_cast<int>(local),
                         MPI_DOUBLE, 0, comm);
            PLUGIN_CALL(VecRestoreArray(mB, &local_b));
        }
        // reform_preconditioner_at_each_step false: the preconditioner of the first solve on this pattern serves
        // every later one (KSPSetReusePreconditioner); otherwise it is set up on each solve's values.
        bool reuse = same && mOptions.reuse_preconditioner != 0;
        // Near-null space (orthonormal on rank 0), for the set-ups to come.
        if (mode_count > 0 && !reuse) {
            std::vector<Vec> modes;
            int code = 0;
            for (int k = 0; k < mode_count && !code; ++k) {
                Vec mode = nullptr;
                PetscScalar* local_mode = nullptr;
                code = VecDuplicate(mB, &mode);
                if (!code) modes.push_back(mode);
                if (!code) code = VecGetArray(mode, &local_mode);
                if (code) break;
                MPI_Scatterv(mRank == 0 ? system.near_null_space + static_cast<std::size_t>(k) * n : nullptr,
                             counts.data(), offsets.data(), MPI_DOUBLE, local_mode, static_cast<int>(local),
                             MPI_DOUBLE, 0, comm);
                code = VecRestoreArray(mode, &local_mode);
            }
            MatNullSpace near_null = nullptr;
            if (!code) code = MatNullSpaceCreate(comm, PETSC_FALSE, mode_count, modes.data(), &near_null);
            for (Vec& mode : modes) VecDestroy(&mode);  // the null space holds its own references
            if (!code) code = MatSetNearNullSpace(p, near_null);
            if (near_null) MatNullSpaceDestroy(&near_null);
            if (code) {
                failure = ErrorText(code, "near-null space (rigid-body modes)");
                return code;
            }
        }
        // The options database is shared by every solver of the process: ours again before a set-up reads it.
        PLUGIN_CALL(SetOptions());
        PLUGIN_CALL(KSPSetReusePreconditioner(mKsp, reuse ? PETSC_TRUE : PETSC_FALSE));
        PLUGIN_CALL(KSPSetOperators(mKsp, mA, p));  // also tells the KSP that the values changed
        PLUGIN_CALL(KSPSetUp(mKsp));
        result.setup_seconds = Seconds(start);
        result.preconditioner_set_up = reuse ? 0 : 1;
        result.pattern_reused = same ? 1 : 0;
        PetscLogDouble memory = 0.0;
        result.preconditioner_memory = PetscMemoryGetCurrentUsage(&memory) == 0 ? memory : -1.0;

        auto solve_start = std::chrono::steady_clock::now();
        PLUGIN_CALL(KSPSolve(mKsp, mB, mX));
        KSPConvergedReason reason;
        PetscInt iterations = 0;
        PLUGIN_CALL(KSPGetConvergedReason(mKsp, &reason));
        PC pc = nullptr;
        PLUGIN_CALL(KSPGetPC(mKsp, &pc));
        const bool reused_interpolation = same && !reuse && mOptions.reuse_interpolation != 0;
        if ((reuse || reused_interpolation) && reason <= 0) {
            // What was kept (the preconditioner, or GAMG's prolongators) no longer fits the values: a complete
            // set-up on them, and the solve again. The empty assembly raises the matrix state, so that PCSetUp
            // does not take the values for those it was set up with.
            const auto setup_start = std::chrono::steady_clock::now();
            PLUGIN_CALL(KSPSetReusePreconditioner(mKsp, PETSC_FALSE));
            PLUGIN_CALL(PCGAMGSetReuseInterpolation(pc, PETSC_FALSE));
            PLUGIN_CALL(MatAssemblyBegin(p, MAT_FINAL_ASSEMBLY));
            PLUGIN_CALL(MatAssemblyEnd(p, MAT_FINAL_ASSEMBLY));
            PLUGIN_CALL(KSPSetOperators(mKsp, mA, p));
            PLUGIN_CALL(KSPSetUp(mKsp));
            PLUGIN_CALL(PCGAMGSetReuseInterpolation(pc, mOptions.reuse_interpolation ? PETSC_TRUE : PETSC_FALSE));
            result.setup_seconds += Seconds(setup_start);
            result.preconditioner_set_up = 1;
            result.retried = 1;
            PLUGIN_CALL(KSPSolve(mKsp, mB, mX));
            PLUGIN_CALL(KSPGetConvergedReason(mKsp, &reason));
        }
        result.solve_seconds = Seconds(solve_start);
        PLUGIN_CALL(KSPGetIterationNumber(mKsp, &iterations));
        // The true relative residual, whatever norm the Krylov method monitored.
        {
            Vec residual = nullptr;
            PLUGIN_CALL(VecDuplicate(mB, &residual));
            PLUGIN_CALL(MatMult(mA, mX, residual));
            PLUGIN_CALL(VecAYPX(residual, -1.0, mB));
            PetscReal r_norm = 0.0, b_norm = 0.0;
            PLUGIN_CALL(VecNorm(residual, NORM_2, &r_norm));
            PLUGIN_CALL(VecNorm(mB, NORM_2, &b_norm));
            VecDestroy(&residual);
            result.relative_residual = b_norm > 0.0 ? r_norm / b_norm : r_norm;
        }
        // Converged by PETSc's test and by the true residual (10x margin for the round-off of the recurrences).
        result.converged = reason > 0 && result.relative_residual <= 10.0 * mOptions.tolerance ? 1 : 0;
        result.iterations = static_cast<int>(iterations);
        result.ranks = mRanks;
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
        PLUGIN_CALL(KSPGetType(mKsp, &ksp_type));
        PetscBool is_mg = PETSC_FALSE;
        PLUGIN_CALL(PetscObjectTypeCompareAny(reinterpret_cast<PetscObject>(pc), &is_mg, PCGAMG, PCMG, ""));
        result.levels = 0;
        if (is_mg) {
            PetscInt levels = 0;
            PLUGIN_CALL(PCMGGetLevels(pc, &levels));
            result.levels = static_cast<int>(levels);
        }
        std::string description = std::string(ksp_type) + " + " + pc_type;
        if (result.levels > 0) description += ", " + std::to_string(result.levels) + " levels";
        if (mRanks > 1) description += ", " + std::to_string(mRanks) + " MPI ranks";
        std::snprintf(result.description, sizeof(result.description), "%s", description.c_str());

        // The solution, gathered on every rank.
        const PetscScalar* local_x = nullptr;
        PLUGIN_CALL(VecGetArrayRead(mX, &local_x));
        MPI_Allgatherv(local_x, static_cast<int>(local), MPI_DOUBLE, x, counts.data(), offsets.data(), MPI_DOUBLE, comm);
        PLUGIN_CALL(VecRestoreArrayRead(mX, &local_x));
        if (mOptions.verbosity > 0 && mRank == 0)
            std::printf("petsc: %s, %ld equations%s, %d iterations, relative residual %.3e (%s), %s, set-up %.3f s, "
                        "solve %.3f s\n",
                        result.description, n, separate_preconditioner ? " (zero diagonals regularised)" : "",
                        result.iterations, result.relative_residual, result.reason,
                        result.retried              ? "preconditioner set up anew after a failed reuse"
                        : result.preconditioner_set_up ? "preconditioner set up"
                                                       : "preconditioner reused",
                        result.setup_seconds, result.solve_seconds);
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
        PetscCall(set("pc_gamg_reuse_interpolation", mOptions.reuse_interpolation ? "true" : "false"));
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
    // Kept between solves while the pattern stays (docs/running.md, "Iterative solver (PETSc)").
    Mat mA = nullptr, mP = nullptr;
    Vec mB = nullptr, mX = nullptr;
    KSP mKsp = nullptr;
    Pattern mPattern;
    std::vector<PetscInt> mLocalRowStart, mLocalColumns;  // this rank's rows of the pattern (one rank: all of it)
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
