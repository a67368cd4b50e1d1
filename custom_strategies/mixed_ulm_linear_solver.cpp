// SPDX-License-Identifier: BSD-3-Clause
#include "custom_strategies/mixed_ulm_linear_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <Eigen/LU>

#include "custom_utilities/contact_variables.h"
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

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

/// How far @p rows fall short of diagonal dominance: max over the rows of Σ_{k≠i}|a_ik| / |a_ii|, with i the row's own
/// reduced position (@p rPositions); infinite for a zero diagonal.
double DominanceDeficit(const RowMatrix& rows, const std::vector<int>& rPositions) {
    double worst = 0.0;
    for (int r = 0; r < rows.outerSize(); ++r) {
        double diagonal = 0.0, others = 0.0;
        for (RowMatrix::InnerIterator it(rows, r); it; ++it)
            (it.col() == rPositions[r] ? diagonal : others) += std::abs(it.value());
        worst = std::max(worst, diagonal > 0.0 ? others / diagonal : std::numeric_limits<double>::infinity());
    }
    return worst;
}

/// Brings the moved multiplier rows of each node to the size of the displacement rows whose places they take
/// (docs/theory/condensation.md §5). A node's equations may be scaled and combined without changing the solution:
/// either each row is scaled so that its diagonal becomes |K_ss| (rows_j := K_d,j diag(B_j)⁻¹ rows_j), or the node's
/// rows are combined so that their block B_j on the node's own displacements becomes K_d,j = diag |K_ss| (rows_j :=
/// K_d,j B_j⁻¹ rows_j). The combination is what a slipping node needs: its tangential rows depend most on its normal
/// displacement (the μ|λ̄n| of the slip law), so their own diagonal is up to 70× smaller than another entry, and
/// the AMG's Gauss–Seidel smoother then diverges. Of the two, each node takes the one whose rows are closer to
/// diagonal dominance (the scaling where B_j cannot be inverted).
void ScaleMovedRows(const SparseMatrixType& rA, const std::vector<std::pair<int, int>>& rPairs,
                    const std::vector<int>& rReducedRow, const std::vector<int>& rNodeOfRow, SparseMatrixType& rReduced,
                    SystemVectorType& rReducedB) {
    using Triplet = Eigen::Triplet<double, int>;
    // Reduced positions of the moved rows by node, with the diagonal of the displacement row each one replaces.
    std::map<int, std::vector<std::pair<int, double>>> by_node;
    for (const auto& [lambda, row] : rPairs) {
        const int at = rReducedRow[lambda];
        const double displacement = std::abs(rA.coeff(row, row));
        // Without a node (none in the layout) a row is a block of its own.
        const int node = row < static_cast<int>(rNodeOfRow.size()) && rNodeOfRow[row] > 0 ? rNodeOfRow[row] : -1 - row;
        if (at >= 0 && displacement > 0.0) by_node[node].emplace_back(at, displacement);
    }
    // The moved rows, row-major (selected in by_node's order).
    std::vector<int> positions;
    for (const auto& [node, rows] : by_node)
        for (const auto& [at, displacement] : rows) positions.push_back(at);
    std::vector<Triplet> pick;
    for (int r = 0; r < static_cast<int>(positions.size()); ++r) pick.emplace_back(r, positions[r], 1.0);
    SparseMatrixType select(static_cast<int>(positions.size()), rReduced.rows());
    select.setFromTriplets(pick.begin(), pick.end());
    const RowMatrix moved_rows = RowMatrix(select * rReduced);

    std::vector<Triplet> transform;
    std::vector<char> moved(rReduced.rows(), 0);
    int first = 0;
    for (const auto& [node, rows] : by_node) {
        const int m = static_cast<int>(rows.size());
        const std::vector<int> own(positions.begin() + first, positions.begin() + first + m);
        const RowMatrix node_rows = moved_rows.middleRows(first, m);
        first += m;
        Eigen::MatrixXd block(m, m), scaled = Eigen::MatrixXd::Zero(m, m);
        for (int a = 0; a < m; ++a) {
            for (int b = 0; b < m; ++b) block(a, b) = node_rows.coeff(a, own[b]);
            scaled(a, a) = rows[a].second / (block(a, a) != 0.0 ? block(a, a) : rows[a].second);
        }
        const auto deficit = [&](const Eigen::MatrixXd& combination) {
            return DominanceDeficit(RowMatrix(RowMatrix(combination.sparseView()) * node_rows), own);
        };
        Eigen::MatrixXd chosen = scaled;
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(block);
        if (m > 1 && lu.isInvertible() && lu.rcond() > 1e-12) {
            Eigen::MatrixXd combined = lu.inverse();
            for (int a = 0; a < m; ++a) combined.row(a) *= rows[a].second;
            if (deficit(combined) < deficit(scaled)) chosen = combined;
        }
        for (int a = 0; a < m; ++a) {
            moved[own[a]] = 1;
            for (int b = 0; b < m; ++b)
                if (chosen(a, b) != 0.0) transform.emplace_back(own[a], own[b], chosen(a, b));
        }
    }
    for (int i = 0; i < rReduced.rows(); ++i)
        if (!moved[i]) transform.emplace_back(i, i, 1.0);
    SparseMatrixType combine(rReduced.rows(), rReduced.rows());
    combine.setFromTriplets(transform.begin(), transform.end());
    rReduced = SparseMatrixType(combine * rReduced);
    rReduced.makeCompressed();
    rReducedB = combine * rReducedB;
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

void MixedULMLinearSolver::ProvideAdditionalData(const std::vector<Dof*>& rDofSet, ModelPart& rModelPart) {
    mPairs.clear();
    mScalarCandidates.clear();
    if (mInner->UnknownLayoutIsNeeded()) {
        std::size_t size = 0;
        for (const Dof* dof : rDofSet) size = std::max<std::size_t>(size, dof->EquationId() + 1);
        mLayout = UnknownLayoutFromDofs(rDofSet, size, rModelPart);
    }
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
    for (const Dof* dof : rDofSet) {
        if (dof->IsFixed() || dof->GetVariable() != LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) continue;
        std::vector<int> rows;
        for (int c = 0; c < 3; ++c) {
            const auto found = displacement_rows.find({&dof->GetNode(), c});
            if (found != displacement_rows.end()) rows.push_back(found->second);
        }
        if (!rows.empty()) mScalarCandidates.emplace_back(static_cast<int>(dof->EquationId()), std::move(rows));
    }
    mHaveData = true;
}

void MixedULMLinearSolver::SolveFull(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    if (mInner->UnknownLayoutIsNeeded() && mLayout.size() > 0) mInner->ProvideUnknownLayout(mLayout);
    mInner->Solve(rA, rX, rB);
}

void MixedULMLinearSolver::Solve(SparseMatrixType& rA, SystemVectorType& rX, SystemVectorType& rB) {
    mLastCondensed = false;
    mLastCondensedCount = 0;
    const bool have_data = mHaveData;
    mHaveData = false;
    const int n = static_cast<int>(rA.rows());
    // Scalar multipliers: the row of the node where the multiplier couples most.
    std::vector<std::pair<int, int>> pairs = mPairs;
    for (const auto& [lambda, rows] : mScalarCandidates) {
        if (lambda >= n) continue;
        int best = -1;
        double largest = 0.0;
        for (const int row : rows) {
            if (row >= n) continue;
            const double value = std::abs(rA.coeff(row, lambda));
            if (value > largest) {
                largest = value;
                best = row;
            }
        }
        if (best >= 0) pairs.emplace_back(lambda, best);
    }
    if (!have_data || pairs.empty()) return SolveFull(rA, rX, rB);

    // Classify: condensed multiplier unknowns E, their paired rows S; everything else is kept (R).
    std::vector<int> multiplier_of_row(n, -1), is_condensed(n, 0);
    for (const auto& [lambda, row] : pairs) {
        if (lambda >= n || row >= n) return SolveFull(rA, rX, rB);
        multiplier_of_row[row] = lambda;
        is_condensed[lambda] = 1;
    }
    // K_SE must be diagonal (dual basis): a paired row may couple to its own multiplier only, other couplings being
    // round-off of the dual basis (|K| ≤ 1e-10 |K_diag|, dropped).
    std::vector<double> diagonal(n, 0.0);
    for (const auto& [lambda, row] : pairs) diagonal[row] = rA.coeff(row, lambda);
    constexpr double kRoundOff = 1.0e-10;
    for (int col = 0; col < rA.outerSize(); ++col)
        for (SparseMatrixType::InnerIterator it(rA, col); it; ++it) {
            const int row = static_cast<int>(it.row());
            if (multiplier_of_row[row] < 0 || !is_condensed[col] || col == multiplier_of_row[row]) continue;
            if (std::abs(it.value()) > kRoundOff * std::abs(diagonal[row])) return SolveFull(rA, rX, rB);
        }
    for (const auto& [lambda, row] : pairs)
        if (std::abs(diagonal[row]) < 1e-300) return SolveFull(rA, rX, rB);

    // Multiplier → its paired row.
    std::vector<int> row_of_multiplier(n, -1);
    for (const auto& [lambda, row] : pairs) row_of_multiplier[lambda] = row;

    // Reduced numbering: kept rows (not paired) and kept unknowns (not condensed) have the same count. For an
    // inner solver that wants the layout, the row of a condensed multiplier takes the place of its paired
    // displacement row (and the reduced unknown j is the full system's unknown kept[j]).
    const bool remap = mInner->UnknownLayoutIsNeeded();
    std::vector<int> reduced_row(n, -1), reduced_col(n, -1), kept_unknowns;
    int rows = 0, cols = 0;
    for (int i = 0; i < n; ++i) {
        if (!remap && multiplier_of_row[i] < 0) reduced_row[i] = rows++;
        if (!is_condensed[i]) {
            reduced_col[i] = cols++;
            kept_unknowns.push_back(i);
        }
    }
    if (remap)
        for (int i = 0; i < n; ++i) {
            if (multiplier_of_row[i] >= 0) continue;
            reduced_row[i] = is_condensed[i] ? reduced_col[row_of_multiplier[i]] : reduced_col[i];
            ++rows;
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
    if (remap) {
        ScaleMovedRows(rA, pairs, reduced_row, mLayout.node, reduced, reduced_b);
        mInner->ProvideUnknownLayout(mLayout.Subset(kept_unknowns));
    }

    SystemVectorType reduced_x = SystemVectorType::Zero(cols);
    mInner->Solve(reduced, reduced_x, reduced_b);

    rX.setZero(n);
    for (int i = 0; i < n; ++i)
        if (reduced_col[i] >= 0) rX[i] = reduced_x[reduced_col[i]];
    for (const auto& [lambda, row] : pairs) {
        double value = rB[row];
        for (const auto& [col, k_sr] : paired_row_entries[row]) value -= k_sr * rX[col];
        rX[lambda] = value / diagonal[row];
    }
    mLastCondensed = true;
    mLastCondensedCount = pairs.size();
}

}  // namespace contact_app
