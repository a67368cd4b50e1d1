// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/petsc_krylov_solver.h"

#include <dlfcn.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <utility>

#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"

#ifndef CONTACT_APP_PETSC_PACKAGE
#define CONTACT_APP_PETSC_PACKAGE "libpetsc-real3.18"
#endif

namespace contact_app {
namespace {

constexpr const char* kPackageHint =
    "PETSc comes from the Debian package " CONTACT_APP_PETSC_PACKAGE
    " (build: libpetsc-real-dev, which scripts/bootstrap.sh installs before building contact_app)";

/// The plugin, loaded once per process: its create function, or why it is not there.
struct Plugin {
    petsc_plugin::CreateFunction create = nullptr;
    std::string failure;
};

std::string PluginPath() {
    if (const char* path = std::getenv("CONTACT_APP_PETSC_PLUGIN"); path != nullptr && *path != '\0') return path;
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&PetscUnavailableReason), &info) == 0 || info.dli_fname == nullptr)
        return petsc_plugin::kLibraryName;
    return (std::filesystem::path(info.dli_fname).parent_path() / petsc_plugin::kLibraryName).string();
}

const Plugin& LoadPlugin() {
    static const Plugin plugin = [] {
        Plugin loaded;
        const std::string path = PluginPath();
        if (!std::filesystem::exists(path)) {
            loaded.failure = detail::Concat("this build of contact_app has no PETSc solver (", path,
                                    " is missing: CMake did not find PETSc through pkg-config). ", kPackageHint,
                                    "; then rebuild (bash scripts/bootstrap.sh)");
            return loaded;
        }
        // RTLD_LOCAL: PETSc's MPI and parallel MUMPS stay out of the module's symbol scope (petsc_krylov_backend.h).
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle == nullptr) {
            const char* why = dlerror();
            loaded.failure = detail::Concat("the PETSc solver did not load (", why ? why : "unknown dlopen error", "). ",
                                    kPackageHint);
            return loaded;
        }
        loaded.create = reinterpret_cast<petsc_plugin::CreateFunction>(dlsym(handle, petsc_plugin::kCreateSymbol));
        if (loaded.create == nullptr) loaded.failure = detail::Concat(path, " has no ", petsc_plugin::kCreateSymbol);
        return loaded;
    }();
    return plugin;
}

struct Choice {
    const char* name;
    const char* value;
};

template <std::size_t N>
const char* Pick(const std::string& key, const std::string& given, const Choice (&choices)[N]) {
    std::vector<std::string> names;
    for (const auto& choice : choices) {
        if (given == choice.name) return choice.value;
        if (*choice.name) names.emplace_back(choice.name);
    }
    CONTACT_THROW(InputError, "linear_solver_settings.", key, " \"", given, "\" is not available with the PETSc solver",
                  "\n  expected: one of ", QuotedList(names), DidYouMean(given, names));
}

// GMRES runs in its flexible form: it keeps the preconditioned vectors, and with a fixed preconditioner it takes the
// same iterates as right-preconditioned GMRES. Measured (cattaneo_mindlin_3d level 3, contact rows condensed and
// combined): PETSc's GMRES broke down (DIVERGED_BREAKDOWN, residual 2e-5 after 200 iterations) in step 1 where
// FGMRES solved every system of the run (docs/running.md, "Iterative solver").
constexpr Choice kKrylov[] = {{"", "fgmres"}, {"gmres", "fgmres"},  {"fgmres", "fgmres"},    {"lgmres", "lgmres"},
                              {"cg", "cg"},    {"bicgstab", "bcgs"}, {"bicgstabl", "bcgsl"}};
constexpr Choice kSmoother[] = {{"", "sor"},
                                {"chebyshev", "chebyshev"},
                                {"damped_jacobi", "jacobi"},
                                {"spai0", "jacobi"},
                                {"gauss_seidel", "sor"},
                                {"ilu0", "ilu"},
                                {"ilut", "ilu"},
                                {"iluk", "ilu"}};
constexpr Choice kCoarsening[] = {{"", "gamg"},
                                  {"smoothed_aggregation", "gamg"},
                                  {"smoothed_aggr_emin", "gamg"},
                                  {"aggregation", "gamg-plain"},
                                  {"ruge_stuben", "hypre"}};
constexpr Choice kPreconditioner[] = {{"", "amg"},           {"amg", "amg"},         {"relaxation", "relaxation"},
                                      {"diagonal", "jacobi"}, {"ilu0", "bjacobi"},   {"none", "none"},
                                      {"dummy", "none"}};

/// Rigid-body modes (2D: 3, 3D: 6) of the nodal blocks, orthonormalised, as columns.
Eigen::MatrixXd RigidBodyModes(const std::vector<std::array<double, 3>>& rCoordinates, int dimension) {
    const auto n = static_cast<Eigen::Index>(rCoordinates.size());
    const int count = dimension == 3 ? 6 : 3;
    Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(n, count);
    std::array<double, 3> centre{0.0, 0.0, 0.0};
    for (const auto& x : rCoordinates)
        for (int c = 0; c < 3; ++c) centre[c] += x[c] / static_cast<double>(std::max<Eigen::Index>(n, 1));
    for (Eigen::Index i = 0; i < n; ++i) {
        const int c = static_cast<int>(i % dimension);
        const double x = rCoordinates[i][0] - centre[0], y = rCoordinates[i][1] - centre[1],
                     z = rCoordinates[i][2] - centre[2];
        modes(i, c) = 1.0;
        if (dimension == 2) {
            modes(i, 2) = c == 0 ? -y : x;
        } else {
            // rotations about z, x, y
            const double about_z[3] = {-y, x, 0.0}, about_x[3] = {0.0, -z, y}, about_y[3] = {z, 0.0, -x};
            modes(i, 3) = about_z[c];
            modes(i, 4) = about_x[c];
            modes(i, 5) = about_y[c];
        }
    }
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(modes);
    return qr.householderQ() * Eigen::MatrixXd::Identity(n, count);
}

}  // namespace

std::string PetscUnavailableReason() { return LoadPlugin().failure; }

petsc_plugin::Options PetscOptionsFromSettings(const KrylovSettings& settings) {
    CONTACT_CHECK(settings.tolerance > 0.0 && settings.tolerance < 1.0, InputError,
                  "linear_solver_settings.tolerance of the PETSc solver must be in (0, 1), got ", settings.tolerance);
    CONTACT_CHECK(settings.max_iteration > 0, InputError, "linear_solver_settings.max_iteration must be at least 1, got ",
                  settings.max_iteration);
    petsc_plugin::Options options;
    options.krylov = Pick("krylov_type", settings.krylov_type, kKrylov);
    options.smoother = Pick("smoother_type", settings.smoother_type, kSmoother);
    const std::string coarsening = Pick("coarsening_type", settings.coarsening_type, kCoarsening);
    const std::string preconditioner = Pick("preconditioner_type", settings.preconditioner_type, kPreconditioner);
    if (preconditioner == "amg") {
        options.preconditioner = coarsening == "hypre" ? "hypre" : "gamg";
        options.aggregation_smoothing = coarsening == "gamg-plain" ? 0 : 1;
    } else if (preconditioner == "relaxation") {
        const std::string smoother = options.smoother;
        options.preconditioner = smoother == "chebyshev" || smoother == "jacobi" ? "jacobi"
                                 : smoother == "sor"                                                   ? "sor"
                                                                                                       : "bjacobi";
    } else {
        options.preconditioner = preconditioner == "jacobi" ? "jacobi" : preconditioner == "bjacobi" ? "bjacobi" : "none";
    }
    options.tolerance = settings.tolerance;
    options.max_iteration = settings.max_iteration;
    options.restart = std::max(1, settings.gmres_krylov_space_dimension);
    options.smoothing_steps = std::max({1, settings.pre_sweeps, settings.post_sweeps});
    options.max_levels = settings.max_levels;
    options.coarse_enough = std::max(1, settings.coarse_enough);
    options.verbosity = settings.verbosity;
    options.reuse_preconditioner = settings.reform_preconditioner_at_each_step ? 0 : 1;
    // Measured on the 3D Hertz and Cattaneo-Mindlin cases: a third of the set-up time on a kept pattern, the
    // same iterations (benchmarks/README.md, "Iterative solver on PETSc").
    options.reuse_interpolation = 1;
    return options;
}

PetscKrylovSolver::PetscKrylovSolver(const KrylovSettings& settings)
    : mSettings(settings), mOptions(PetscOptionsFromSettings(settings)) {
    const Plugin& plugin = LoadPlugin();
    CONTACT_CHECK(plugin.create != nullptr, ConfigurationError, "solver_type \"amgcl\" / \"gmres\" needs PETSc: ",
                  plugin.failure, "\n  fix: install it, or use a direct solver (\"mumps\", \"skyline_lu_factorization\")");
    if (const char* extra = std::getenv("CONTACT_APP_PETSC_OPTIONS")) mExtraOptions = extra;
    mOptions.extra_options = mExtraOptions.c_str();
    char message[512] = {};
    mBackend = plugin.create(&mOptions, message, sizeof(message));
    CONTACT_CHECK(mBackend != nullptr, ConfigurationError, "the PETSc solver could not start: ", message);
    mStatistics.solver = Info();
    mStatistics.krylov = true;
    mStatistics.tolerance = settings.tolerance;
    mStatistics.ranks = mBackend->Ranks();
}

PetscKrylovSolver::~PetscKrylovSolver() {
    if (mBackend != nullptr) mBackend->Destroy();
}

int PetscKrylovSolver::Rank() const { return mBackend->Rank(); }
int PetscKrylovSolver::Ranks() const { return mBackend->Ranks(); }

void PetscKrylovSolver::ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) {
    std::size_t size = 0;
    for (const Dof* dof : rDofSet) size = std::max<std::size_t>(size, dof->EquationId() + 1);
    mLayout = UnknownLayoutFromDofs(rDofSet, size, rModelPart);
    mHaveLayout = true;
}

void PetscKrylovSolver::ProvideUnknownLayout(UnknownLayout layout) {
    mLayout = std::move(layout);
    mHaveLayout = true;
}

void PetscKrylovSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    const auto n = static_cast<std::size_t>(rA.rows());
    if (n == 0) {
        rX.resize(0);
        return;
    }
    // Renumbering: complete nodal displacement blocks first (block size = dimension), then every other unknown,
    // padded with identity rows to whole blocks.
    const int dimension = mHaveLayout && mLayout.size() >= n ? mLayout.dimension : 0;
    std::vector<int> order;  // new position -> old equation (-1 = padding)
    std::vector<std::array<double, 3>> coordinates;
    int block = 1;
    if (dimension >= 2) {
        std::map<int, std::array<int, 3>> blocks;  // node id -> equations of its components
        for (std::size_t i = 0; i < n; ++i)
            if (mLayout.component[i] >= 0 && mLayout.component[i] < dimension) {
                auto [it, inserted] = blocks.try_emplace(mLayout.node[i], std::array<int, 3>{-1, -1, -1});
                it->second[mLayout.component[i]] = static_cast<int>(i);
            }
        std::vector<char> placed(n, 0);
        for (const auto& [node, equations] : blocks) {
            if (std::any_of(equations.begin(), equations.begin() + dimension, [](int e) { return e < 0; })) continue;
            for (int c = 0; c < dimension; ++c) {
                order.push_back(equations[c]);
                placed[equations[c]] = 1;
            }
        }
        for (std::size_t i = 0; i < n; ++i)
            if (!placed[i]) order.push_back(static_cast<int>(i));
        while (order.size() % dimension != 0) order.push_back(-1);
        block = dimension;
        coordinates.reserve(order.size());
        for (const int old : order)
            coordinates.push_back(old >= 0 ? mLayout.coordinates[old] : std::array<double, 3>{0.0, 0.0, 0.0});
    } else {
        order.resize(n);
        for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<int>(i);
    }
    const std::size_t size = order.size();
    std::vector<int> position(n, -1);
    for (std::size_t k = 0; k < size; ++k)
        if (order[k] >= 0) position[order[k]] = static_cast<int>(k);

    // The renumbered system as CSR, rows sorted, every diagonal present (an explicit zero if need be): one
    // counting pass, then the columns in their new order, so that every row receives its columns sorted.
    std::vector<long> row_start(size + 1, 0);
    std::vector<char> has_diagonal(size, 0);
    for (int col = 0; col < rA.outerSize(); ++col)
        for (SparseMatrixType::InnerIterator it(rA, col); it; ++it) {
            const int row = position[it.row()];
            ++row_start[row + 1];
            if (row == position[col]) has_diagonal[row] = 1;
        }
    for (std::size_t k = 0; k < size; ++k)
        if (!has_diagonal[k]) ++row_start[k + 1];  // padding rows get their 1, the others an explicit 0
    for (std::size_t k = 0; k < size; ++k) row_start[k + 1] += row_start[k];
    std::vector<long> fill(row_start.begin(), row_start.end() - 1);
    std::vector<int> columns(row_start[size]);
    std::vector<double> values(row_start[size]);
    for (std::size_t k = 0; k < size; ++k) {
        const int column = static_cast<int>(k);
        if (!has_diagonal[k]) {  // rows below k were filled up to column k - 1 only: the diagonal goes here
            columns[fill[k]] = column;
            values[fill[k]++] = order[k] < 0 ? 1.0 : 0.0;
        }
        if (order[k] < 0) continue;
        for (SparseMatrixType::InnerIterator it(rA, order[k]); it; ++it) {
            const long at = fill[position[it.row()]]++;
            columns[at] = column;
            values[at] = it.value();
        }
    }
    std::vector<std::pair<long, double>> regularised;  // (entry, value in the preconditioner's matrix)
    double diagonal_scale = 0.0;
    for (std::size_t k = 0; k < size; ++k) {
        double largest = 0.0, diagonal = 0.0;
        long diagonal_at = -1;
        for (long at = row_start[k]; at < row_start[k + 1]; ++at) {
            largest = std::max(largest, std::abs(values[at]));
            if (columns[at] == static_cast<int>(k)) {
                diagonal = values[at];
                diagonal_at = at;
            }
        }
        diagonal_scale = std::max(diagonal_scale, std::abs(diagonal));
        if (largest > 0.0 && std::abs(diagonal) <= 1.0e-12 * largest) regularised.emplace_back(diagonal_at, largest);
    }
    std::vector<double> preconditioner_values;
    if (!regularised.empty()) {
        preconditioner_values = values;
        for (const auto& [at, value] : regularised) preconditioner_values[at] = value;
    }
    std::vector<double> rhs(size, 0.0);
    for (std::size_t k = 0; k < size; ++k)
        if (order[k] >= 0) rhs[k] = rB[order[k]];
    Eigen::MatrixXd modes;
    if (block >= 2 && mOptions.preconditioner == std::string("gamg")) modes = RigidBodyModes(coordinates, block);

    petsc_plugin::System system;
    system.size = static_cast<long>(size);
    system.block_size = block;
    system.row_start = row_start.data();
    system.columns = columns.data();
    system.values = values.data();
    system.rhs = rhs.data();
    system.preconditioner_values = preconditioner_values.empty() ? nullptr : preconditioner_values.data();
    system.diagonal_scale = diagonal_scale > 0.0 ? diagonal_scale : 1.0;
    system.near_null_space_count = static_cast<int>(modes.cols());
    system.near_null_space = modes.data();
    std::vector<double> solution(size, 0.0);
    petsc_plugin::Result result;
    char message[512] = {};
    const int code = mBackend->Solve(system, solution.data(), &result, message, sizeof(message));
    mHaveLayout = false;
    CONTACT_CHECK(code == 0, ConvergenceError, "PETSc solver failed at ", NewtonStepText(mLayout.model_part), ": ",
                  message);
    rX.setZero(static_cast<Eigen::Index>(n));
    for (std::size_t k = 0; k < size; ++k)
        if (order[k] >= 0) rX[order[k]] = solution[k];

    mStatistics.krylov_iterations.push_back(result.iterations);
    mStatistics.krylov_method = result.description;
    mStatistics.last_relative_residual = result.relative_residual;
    mStatistics.preconditioner_seconds += result.setup_seconds;
    mStatistics.preconditioner_setups += static_cast<std::size_t>(result.preconditioner_set_up);
    mStatistics.krylov_seconds += result.solve_seconds;
    mStatistics.ranks = result.ranks;
    mStatistics.system_size = n;
    mStatistics.near_null_space = static_cast<std::size_t>(modes.cols());
    const std::string where = NewtonStepText(mLayout.model_part);
    CONTACT_CHECK(result.converged && rX.allFinite(), ConvergenceError, "PETSc ", result.description,
                  ": no convergence", where.empty() ? "" : " at ", where, " after ", result.iterations,
                  " iterations (relative residual ", result.relative_residual, ", tolerance ", mSettings.tolerance,
                  ", PETSc reason ", result.reason, ")",
                  "\n  fix: raise linear_solver_settings.max_iteration (now ", mSettings.max_iteration,
                  ") or gmres_krylov_space_dimension (now ", mSettings.gmres_krylov_space_dimension,
                  "), loosen tolerance, keep contact_settings.use_mixed_ulm_solver true (the AMG needs the multipliers "
                  "condensed), or use a direct solver (\"mumps\")");
}

}  // namespace contact_app
