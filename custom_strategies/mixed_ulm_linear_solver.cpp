// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/mixed_ulm_linear_solver.h"

#include <cmath>
#include <map>

#include "contact_app/application.h"
#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"
#include "contact_app/kernel/node.h"

namespace contact_app {
namespace {

const Variable<double>* const kMultipliers[] = {&VECTOR_LAGRANGE_MULTIPLIER_X, &VECTOR_LAGRANGE_MULTIPLIER_Y,
                                                &VECTOR_LAGRANGE_MULTIPLIER_Z};
const Variable<double>* const kDisplacements[] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};

int ComponentOf(const Variable<double>& variable, const Variable<double>* const (&table)[3]) {
    for (int c = 0; c < 3; ++c)
        if (variable == *table[c]) return c;
    return -1;
}

}  // namespace

MixedULMLinearSolver::MixedULMLinearSolver(LinearSolver::Pointer inner) : mInner(std::move(inner)) {
    CONTACT_CHECK(mInner != nullptr, InternalError, "mixed_ulm_linear_solver created without an inner solver");
}

void MixedULMLinearSolver::Clear() {
    mInner->Clear();
}

std::string MixedULMLinearSolver::Info() const {
    return "mixed_ulm_linear_solver(" + mInner->Info() + ")";
}

void MixedULMLinearSolver::ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart&) {
    mPairs.clear();
    // Free displacement equations of active slave nodes, by (node, component).
    std::map<std::pair<const Node*, int>, int> displacement_rows;
    for (const Dof* dof : rDofSet) {
        if (dof->IsFixed()) continue;
        const int c = ComponentOf(dof->GetVariable(), kDisplacements);
        const Node& node = dof->GetNode();
        if (c < 0 || !node.Is(SLAVE) || !node.Is(ACTIVE)) continue;
        displacement_rows[{&node, c}] = static_cast<int>(dof->EquationId());
    }
    for (const Dof* dof : rDofSet) {
        if (dof->IsFixed()) continue;
        const int c = ComponentOf(dof->GetVariable(), kMultipliers);
        if (c < 0) continue;
        const auto found = displacement_rows.find({&dof->GetNode(), c});
        if (found != displacement_rows.end()) mPairs.emplace_back(static_cast<int>(dof->EquationId()), found->second);
    }
    mHaveData = true;
}

void MixedULMLinearSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    mLastCondensed = false;
    mLastCondensedCount = 0;
    const bool have_data = mHaveData;
    mHaveData = false;
    const int n = static_cast<int>(rA.rows());
    if (!have_data || mPairs.empty()) return mInner->Solve(rA, rX, rB);

    // Classify: condensed multiplier unknowns E, their paired rows S; everything else is kept (R).
    std::vector<int> multiplier_of_row(n, -1), is_condensed(n, 0);
    for (const auto& [lambda, row] : mPairs) {
        if (lambda >= n || row >= n) return mInner->Solve(rA, rX, rB);
        multiplier_of_row[row] = lambda;
        is_condensed[lambda] = 1;
    }
    // K_SE must be diagonal (dual basis): a paired row may couple to its own multiplier only, other couplings being
    // round-off of the dual basis (|K| ≤ 1e-10 |K_diag|, dropped).
    std::vector<double> diagonal(n, 0.0);
    for (const auto& [lambda, row] : mPairs) diagonal[row] = rA.coeff(row, lambda);
    constexpr double kRoundOff = 1.0e-10;
    for (int col = 0; col < rA.outerSize(); ++col)
        for (SparseMatrixType::InnerIterator it(rA, col); it; ++it) {
            const int row = static_cast<int>(it.row());
            if (multiplier_of_row[row] < 0 || !is_condensed[col] || col == multiplier_of_row[row]) continue;
            if (std::abs(it.value()) > kRoundOff * std::abs(diagonal[row])) return mInner->Solve(rA, rX, rB);
        }
    for (const auto& [lambda, row] : mPairs)
        if (std::abs(diagonal[row]) < 1e-300) return mInner->Solve(rA, rX, rB);

    // Reduced numbering: kept rows (not paired) and kept unknowns (not condensed) have the same count.
    std::vector<int> reduced_row(n, -1), reduced_col(n, -1);
    int rows = 0, cols = 0;
    for (int i = 0; i < n; ++i) {
        if (multiplier_of_row[i] < 0) reduced_row[i] = rows++;
        if (!is_condensed[i]) reduced_col[i] = cols++;
    }
    CONTACT_CHECK(rows == cols, InternalError, "mixed_ulm_linear_solver: ", rows, " kept rows for ", cols,
                  " kept unknowns");

    // K_R,R, K_R,E (as row → (multiplier, value)), K_S,R (by paired row).
    using Triplet = Eigen::Triplet<double, int>;
    std::vector<Triplet> kept;
    std::vector<std::vector<std::pair<int, double>>> row_to_multiplier(n), paired_row_entries(n);
    for (int col = 0; col < rA.outerSize(); ++col)
        for (SparseMatrixType::InnerIterator it(rA, col); it; ++it) {
            const int row = static_cast<int>(it.row());
            if (it.value() == 0.0) continue;
            if (multiplier_of_row[row] >= 0) {
                if (!is_condensed[col]) paired_row_entries[row].emplace_back(col, it.value());
            } else if (is_condensed[col]) {
                row_to_multiplier[row].emplace_back(col, it.value());
            } else {
                kept.emplace_back(reduced_row[row], reduced_col[col], it.value());
            }
        }
    // Multiplier → its paired row.
    std::vector<int> row_of_multiplier(n, -1);
    for (const auto& [lambda, row] : mPairs) row_of_multiplier[lambda] = row;

    SystemVectorType reduced_b(rows);
    for (int i = 0; i < n; ++i)
        if (reduced_row[i] >= 0) reduced_b[reduced_row[i]] = rB[i];
    // − K_R,E K_SE⁻¹ [K_S,R | r_S]
    for (int row = 0; row < n; ++row) {
        if (reduced_row[row] < 0) continue;
        for (const auto& [lambda, k_re] : row_to_multiplier[row]) {
            const int paired = row_of_multiplier[lambda];
            const double factor = k_re / diagonal[paired];
            reduced_b[reduced_row[row]] -= factor * rB[paired];
            for (const auto& [col, k_sr] : paired_row_entries[paired])
                kept.emplace_back(reduced_row[row], reduced_col[col], -factor * k_sr);
        }
    }
    SparseMatrixType reduced(rows, cols);
    reduced.setFromTriplets(kept.begin(), kept.end());
    reduced.makeCompressed();

    SystemVectorType reduced_x = SystemVectorType::Zero(cols);
    mInner->Solve(reduced, reduced_x, reduced_b);

    rX.setZero(n);
    for (int i = 0; i < n; ++i)
        if (reduced_col[i] >= 0) rX[i] = reduced_x[reduced_col[i]];
    for (const auto& [lambda, row] : mPairs) {
        double value = rB[row];
        for (const auto& [col, k_sr] : paired_row_entries[row]) value -= k_sr * rX[col];
        rX[lambda] = value / diagonal[row];
    }
    mLastCondensed = true;
    mLastCondensedCount = mPairs.size();
}

}  // namespace contact_app
