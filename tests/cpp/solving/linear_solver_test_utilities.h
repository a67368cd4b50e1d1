// SPDX-License-Identifier: BSD-3-Clause
// Small systems with known properties, and the statistics checks, for the linear-solver tests.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "contact_app/solving/linear_solvers/linear_solver.h"
#include "contact_app/solving/system_types.h"

namespace contact_app::testing {

/// Files in the temporary directory whose names start with @p prefix (MUMPS's out-of-core factors).
inline std::size_t TemporaryFiles(const std::string& prefix) {
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
        count += entry.path().filename().string().rfind(prefix, 0) == 0;
    return count;
}

/// 1D Laplacian with Dirichlet ends (SPD, condition ~ n²).
inline SparseMatrixType Laplacian(int n) {
    std::vector<Eigen::Triplet<double, int>> entries;
    for (int i = 0; i < n; ++i) {
        entries.emplace_back(i, i, 2.0);
        if (i > 0) entries.emplace_back(i, i - 1, -1.0);
        if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
    }
    SparseMatrixType matrix(n, n);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

/// Saddle-point system [K Bᵀ; B 0] with a one-row B (indefinite, like a contact multiplier block).
inline SparseMatrixType SaddlePoint(int n) {
    const SparseMatrixType stiffness = Laplacian(n);
    std::vector<Eigen::Triplet<double, int>> entries;
    for (int j = 0; j < stiffness.outerSize(); ++j)
        for (SparseMatrixType::InnerIterator it(stiffness, j); it; ++it) entries.emplace_back(it.row(), it.col(), it.value());
    entries.emplace_back(n, n / 2, 1.0);
    entries.emplace_back(n / 2, n, 1.0);
    entries.emplace_back(n, n - 1, -0.5);
    entries.emplace_back(n - 1, n, -0.5);
    SparseMatrixType matrix(n + 1, n + 1);
    matrix.setFromTriplets(entries.begin(), entries.end());
    return matrix;
}

/// A direct solver's figures after `factorizations` factorisations of one matrix `rMatrix`.
inline void ExpectFactorStatistics(const LinearSolverStatistics& statistics, const std::string& solver,
                                   const std::string& ordering, std::size_t factorizations,
                                   const SparseMatrixType& rMatrix) {
    EXPECT_EQ(statistics.solver, solver);
    EXPECT_EQ(statistics.ordering, ordering);
    EXPECT_EQ(statistics.factorizations, factorizations);
    EXPECT_EQ(statistics.system_size, static_cast<std::size_t>(rMatrix.rows()));
    EXPECT_GE(statistics.factor_nonzeros, static_cast<double>(rMatrix.nonZeros()));
    EXPECT_GT(statistics.factor_memory, 0.0);
    EXPECT_EQ(statistics.max_factor_memory, statistics.factor_memory);
    EXPECT_GT(statistics.factor_flops, 0.0);
}

}  // namespace contact_app::testing
