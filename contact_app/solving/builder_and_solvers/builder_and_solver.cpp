// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"

#include <algorithm>
#include <chrono>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

namespace {

/// Adds the lifetime of the object to a seconds counter.
class ScopedTimer {
public:
    explicit ScopedTimer(double& total) : mTotal(total), mStart(std::chrono::steady_clock::now()) {}
    ~ScopedTimer() { mTotal += std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count(); }
    ScopedTimer(const ScopedTimer&) = delete;
    ScopedTimer& operator=(const ScopedTimer&) = delete;

private:
    double& mTotal;
    std::chrono::steady_clock::time_point mStart;
};

bool DofLess(const Dof* a, const Dof* b) {
    if (a->Id() != b->Id()) return a->Id() < b->Id();
    return a->GetVariable().Key() < b->GetVariable().Key();
}

/// Calls @p action(entity) for every assembled element and condition.
template <class TAction>
void ForEachAssembled(ModelPart& rModelPart, TAction action) {
    for (const auto& element : rModelPart.Elements())
        if (IsAssembled(*element)) action(*element);
    for (const auto& condition : rModelPart.Conditions())
        if (IsAssembled(*condition)) action(*condition);
}

}  // namespace

BuilderAndSolver::BuilderAndSolver(LinearSolver::Pointer linear_solver) : mLinearSolver(std::move(linear_solver)) {
    CONTACT_CHECK(mLinearSolver != nullptr, InternalError, "builder-and-solver created without a linear solver");
}

void BuilderAndSolver::SetUpDofSet(Scheme&, ModelPart& rModelPart) {
    ScopedTimer timer(mTimings.setup);
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    DofsArrayType dofs, slaves, masters;
    ForEachAssembled(rModelPart, [&](auto& entity) {
        DofsVectorType local;
        entity.GetDofList(local, info);
        dofs.insert(dofs.end(), local.begin(), local.end());
    });
    for (const auto& constraint : rModelPart.MasterSlaveConstraints()) {
        constraint->GetDofList(slaves, masters, info);
        dofs.insert(dofs.end(), slaves.begin(), slaves.end());
        dofs.insert(dofs.end(), masters.begin(), masters.end());
    }
    std::sort(dofs.begin(), dofs.end(), DofLess);
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    mDofSet = std::move(dofs);
    mDofSetIsInitialized = true;
}

void BuilderAndSolver::ResizeAndInitializeVectors(Scheme& rScheme, SparseMatrixType& rA, SystemVectorType& rDx,
                                                  SystemVectorType& rB, ModelPart& rModelPart) {
    ScopedTimer timer(mTimings.setup);
    const auto size = static_cast<int>(mEquationSystemSize);
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    // Column lists of the graph; every equation keeps its diagonal so Dirichlet rows stay solvable.
    std::vector<std::vector<int>> columns(mEquationSystemSize);
    for (int i = 0; i < size; ++i) columns[i].push_back(i);
    EquationIdVectorType ids;
    auto add_block = [&](const EquationIdVectorType& rows_ids, const EquationIdVectorType& column_ids) {
        for (const std::size_t j : column_ids) {
            if (j >= mEquationSystemSize) continue;
            for (const std::size_t i : rows_ids)
                if (i < mEquationSystemSize) columns[j].push_back(static_cast<int>(i));
        }
    };
    ForEachAssembled(rModelPart, [&](auto& entity) {
        entity.EquationIdVector(ids, info);
        add_block(ids, ids);
    });
    for (const auto& contributor : mContributors)
        contributor->AddGraph(rModelPart, info, [&](const EquationIdVectorType& rows, const EquationIdVectorType& cols,
                                                    const Matrix*) { add_block(rows, cols); });
    (void)rScheme;
    std::size_t nonzeros = 0;
    for (auto& column : columns) {
        std::sort(column.begin(), column.end());
        column.erase(std::unique(column.begin(), column.end()), column.end());
        nonzeros += column.size();
    }
    rA.resize(size, size);
    rA.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
    int* outer = rA.outerIndexPtr();
    int* inner = rA.innerIndexPtr();
    outer[0] = 0;
    for (int j = 0; j < size; ++j) {
        std::copy(columns[j].begin(), columns[j].end(), inner + outer[j]);
        outer[j + 1] = outer[j] + static_cast<int>(columns[j].size());
    }
    std::fill(rA.valuePtr(), rA.valuePtr() + nonzeros, 0.0);
    rDx.setZero(size);
    rB.setZero(size);
}

void BuilderAndSolver::Assemble(SparseMatrixType* pA, SystemVectorType* pB, const Matrix* pLHS, const Vector* pRHS,
                                const EquationIdVectorType& rIds) {
    const std::size_t n = rIds.size();
    if (pB != nullptr && pRHS != nullptr && pRHS->size() != 0) {
        CONTACT_CHECK(static_cast<std::size_t>(pRHS->size()) == n, InternalError, "local RHS of size ", pRHS->size(),
                      " for ", n, " equation ids");
        for (std::size_t a = 0; a < n; ++a)
            if (rIds[a] < mEquationSystemSize) (*pB)[static_cast<Eigen::Index>(rIds[a])] += (*pRHS)[a];
    }
    if (pA != nullptr && pLHS != nullptr && pLHS->size() != 0) {
        CONTACT_CHECK(static_cast<std::size_t>(pLHS->rows()) == n && static_cast<std::size_t>(pLHS->cols()) == n,
                      InternalError, "local LHS of size ", pLHS->rows(), "x", pLHS->cols(), " for ", n, " equation ids");
        for (std::size_t b = 0; b < n; ++b) {
            if (rIds[b] >= mEquationSystemSize) continue;
            for (std::size_t a = 0; a < n; ++a) {
                if (rIds[a] >= mEquationSystemSize) continue;
                pA->coeffRef(static_cast<Eigen::Index>(rIds[a]), static_cast<Eigen::Index>(rIds[b])) += (*pLHS)(a, b);
            }
        }
    }
}

void BuilderAndSolver::Build(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rB) {
    ScopedTimer timer(mTimings.build);
    ++mTimings.builds;
    std::fill(rA.valuePtr(), rA.valuePtr() + rA.nonZeros(), 0.0);
    rB.setZero(static_cast<Eigen::Index>(mEquationSystemSize));
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    Matrix lhs;
    Vector rhs;
    EquationIdVectorType ids;
    ForEachAssembled(rModelPart, [&](auto& entity) {
        rScheme.CalculateSystemContributions(entity, lhs, rhs, ids, info);
        Assemble(&rA, &rB, &lhs, &rhs, ids);
    });
    AssembleContributors(rModelPart, rA);
}

void BuilderAndSolver::AssembleContributors(ModelPart& rModelPart, SparseMatrixType& rA) {
    for (const auto& contributor : mContributors)
        contributor->AddLHS(rModelPart, rModelPart.GetProcessInfo(),
                            [&](const EquationIdVectorType& rows, const EquationIdVectorType& cols, const Matrix* block) {
                                for (std::size_t b = 0; b < cols.size(); ++b) {
                                    if (cols[b] >= mEquationSystemSize) continue;
                                    for (std::size_t a = 0; a < rows.size(); ++a)
                                        if (rows[a] < mEquationSystemSize)
                                            rA.coeffRef(static_cast<Eigen::Index>(rows[a]),
                                                        static_cast<Eigen::Index>(cols[b])) += (*block)(a, b);
                                }
                            });
}

void BuilderAndSolver::BuildLHS(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA) {
    std::fill(rA.valuePtr(), rA.valuePtr() + rA.nonZeros(), 0.0);
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    Matrix lhs;
    EquationIdVectorType ids;
    ForEachAssembled(rModelPart, [&](auto& entity) {
        rScheme.CalculateLHSContribution(entity, lhs, ids, info);
        Assemble(&rA, nullptr, &lhs, nullptr, ids);
    });
    AssembleContributors(rModelPart, rA);
}

void BuilderAndSolver::AssembleResidual(Scheme& rScheme, ModelPart& rModelPart, SystemVectorType& rResidual,
                                        std::size_t size) {
    rResidual.setZero(static_cast<Eigen::Index>(size));
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    Vector rhs;
    EquationIdVectorType ids;
    ForEachAssembled(rModelPart, [&](auto& entity) {
        rScheme.CalculateRHSContribution(entity, rhs, ids, info);
        for (std::size_t a = 0; a < ids.size() && a < static_cast<std::size_t>(rhs.size()); ++a)
            if (ids[a] < size) rResidual[static_cast<Eigen::Index>(ids[a])] += rhs[a];
    });
}

void BuilderAndSolver::BuildRHS(Scheme& rScheme, ModelPart& rModelPart, SystemVectorType& rB) {
    ScopedTimer timer(mTimings.build);
    AssembleResidual(rScheme, rModelPart, rB, mEquationSystemSize);
    for (const Dof* dof : mDofSet)
        if (dof->IsFixed() && dof->EquationId() < mEquationSystemSize) rB[static_cast<Eigen::Index>(dof->EquationId())] = 0.0;
}

bool BuilderAndSolver::HasActiveConstraints(const ModelPart& rModelPart) const {
    for (const auto& constraint : rModelPart.MasterSlaveConstraints())
        if (IsAssembled(*constraint)) return true;
    return false;
}

void BuilderAndSolver::BuildRelationMatrix(ModelPart& rModelPart) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    const std::size_t n = mEquationSystemSize;
    std::vector<char>& is_slave = mIsSlave;
    is_slave.assign(n, 0);
    mConstrainedEquations.assign(n, 0);
    std::vector<Eigen::Triplet<double, int>> triplets, test_triplets;
    Matrix relation, test;
    Vector constant;
    EquationIdVectorType slave_ids, master_ids;
    mHasTestRelation = false;
    for (const auto& constraint : rModelPart.MasterSlaveConstraints()) {
        if (!IsAssembled(*constraint)) continue;
        constraint->CalculateLocalSystem(relation, constant, info);
        constraint->EquationIdVector(slave_ids, master_ids, info);
        const bool own_test = constraint->CalculateTestRelation(test, info);
        mHasTestRelation = mHasTestRelation || own_test;
        const Matrix& weights = own_test ? test : relation;
        for (std::size_t s = 0; s < slave_ids.size(); ++s) {
            if (slave_ids[s] >= n) continue;  // an eliminated (fixed) slave keeps its prescribed value
            is_slave[slave_ids[s]] = 1;
            mConstrainedEquations[slave_ids[s]] = 1;
            for (std::size_t m = 0; m < master_ids.size(); ++m) {
                if (master_ids[m] >= n) continue;
                mConstrainedEquations[master_ids[m]] = 1;
                const auto r = static_cast<Eigen::Index>(s), c = static_cast<Eigen::Index>(m);
                triplets.emplace_back(static_cast<int>(slave_ids[s]), static_cast<int>(master_ids[m]), relation(r, c));
                test_triplets.emplace_back(static_cast<int>(slave_ids[s]), static_cast<int>(master_ids[m]),
                                           weights(r, c));
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i)
        if (!is_slave[i]) {
            triplets.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
            test_triplets.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
        }
    mT.resize(static_cast<int>(n), static_cast<int>(n));
    mT.setFromTriplets(triplets.begin(), triplets.end());  // duplicates (a slave in several constraints) are summed
    mW.resize(0, 0);
    if (mHasTestRelation) {
        mW.resize(static_cast<int>(n), static_cast<int>(n));
        mW.setFromTriplets(test_triplets.begin(), test_triplets.end());
    }
}

void BuilderAndSolver::ApplyConstraints(Scheme&, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rB) {
    mConstraintsApplied = HasActiveConstraints(rModelPart);
    if (!mConstraintsApplied) return;
    BuildRelationMatrix(rModelPart);
    // Galerkin (TᵀAT) unless a constraint tests its slave's residual with other weights (WᵀAT, see
    // MasterSlaveConstraint::CalculateTestRelation); the increments are always Δx = TΔx̃.
    const SparseMatrixType& test = mHasTestRelation ? mW : mT;
    SparseMatrixType transformed = SparseMatrixType(test.transpose()) * rA * mT;
    rB = test.transpose() * rB;
    const double max_diagonal = transformed.diagonal().cwiseAbs().maxCoeff();
    for (int i = 0; i < transformed.rows(); ++i) {
        // A slave row is empty after the transformation: give it a well-scaled diagonal.
        if (mIsSlave[static_cast<std::size_t>(i)]) {
            transformed.coeffRef(i, i) = max_diagonal > 0.0 ? max_diagonal : 1.0;
            rB[i] = 0.0;
        }
    }
    transformed.makeCompressed();
    rA = std::move(transformed);
}

void BuilderAndSolver::SystemSolve(SparseMatrixType& rA, SystemVectorType& rDx, SystemVectorType& rB) {
    ScopedTimer timer(mTimings.solve);
    ++mTimings.solves;
    if (rB.size() == 0 || rB.norm() == 0.0) {
        rDx.setZero(rB.size());
        return;
    }
    mLinearSolver->Solve(rA, rDx, rB);
}

void BuilderAndSolver::BuildAndSolve(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA,
                                     SystemVectorType& rDx, SystemVectorType& rB) {
    Build(rScheme, rModelPart, rA, rB);
    if (HasActiveConstraints(rModelPart)) {
        // The transformed matrix has its own pattern; keep the assembled one for the next Build.
        SparseMatrixType work = rA;
        ApplyConstraints(rScheme, rModelPart, work, rB);
        ApplyDirichletConditions(rScheme, rModelPart, work, rDx, rB);
        SystemSolve(work, rDx, rB);
        rDx = mT * rDx;
        return;
    }
    mConstraintsApplied = false;
    ApplyDirichletConditions(rScheme, rModelPart, rA, rDx, rB);
    if (mLinearSolver->AdditionalPhysicalDataIsNeeded()) mLinearSolver->ProvideAdditionalData(mDofSet, rModelPart);
    SystemSolve(rA, rDx, rB);
}

void BuilderAndSolver::InitializeSolutionStep(ModelPart& rModelPart, SparseMatrixType&, SystemVectorType&,
                                              SystemVectorType&) {
    if (HasActiveConstraints(rModelPart)) BuildRelationMatrix(rModelPart);
    else mConstrainedEquations.assign(mEquationSystemSize, 0);
}

void BuilderAndSolver::FinalizeSolutionStep(ModelPart&, SparseMatrixType&, SystemVectorType&, SystemVectorType&) {}

void BuilderAndSolver::Clear() {
    mDofSet.clear();
    mEquationSystemSize = 0;
    mDofSetIsInitialized = false;
    mT.resize(0, 0);
    mW.resize(0, 0);
    mHasTestRelation = false;
    mConstrainedEquations.clear();
    mLinearSolver->Clear();
}

}  // namespace contact_app
