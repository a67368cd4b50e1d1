// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/builder_and_solvers/builder_and_solver.h"

#include <algorithm>
#include <chrono>
#include <exception>

#ifdef _OPENMP
#include <omp.h>
#endif

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

/// A DoF with the key it is ordered by (node id, then variable key), so that sorting compares numbers held side by side
/// instead of following two pointers per comparison (a 2D mesh of 3.7e5 nodes lists 3e6 DoFs, each several times).
struct KeyedDof {
    std::size_t node;
    std::size_t variable;
    Dof* dof;
    bool operator<(const KeyedDof& other) const {
        return node != other.node ? node < other.node : variable < other.variable;
    }
};

/// The distinct DoFs of @p rDofs ordered by node id and variable key.
DofsArrayType SortedDistinctDofs(DofsArrayType& rDofs) {
    std::sort(rDofs.begin(), rDofs.end());  // by address: the duplicates adjacent, cheaply
    rDofs.erase(std::unique(rDofs.begin(), rDofs.end()), rDofs.end());
    std::vector<KeyedDof> keyed;
    keyed.reserve(rDofs.size());
    for (Dof* dof : rDofs) keyed.push_back({dof->Id(), dof->GetVariable().Key(), dof});
    std::sort(keyed.begin(), keyed.end());
    DofsArrayType result;
    result.reserve(keyed.size());
    for (const KeyedDof& entry : keyed) result.push_back(entry.dof);
    return result;
}

/// The blocks (rows × columns of equation ids) the entities couple, recorded flat, then compressed into the
/// compressed-column graph with every diagonal: one count pass, one fill pass and a sort per column, without a
/// container per column (the allocations of which dominated the set-up of large meshes).
class GraphBlocks {
public:
    explicit GraphBlocks(std::size_t size) : mSize(size) {}

    /// Records rows × columns; ids ≥ the system size (fixed DoFs of the elimination builder) are skipped.
    void Add(const EquationIdVectorType& rows, const EquationIdVectorType& columns) {
        const std::size_t start = mIds.size();
        for (const std::size_t i : rows)
            if (i < mSize) mIds.push_back(static_cast<int>(i));
        const auto row_count = static_cast<int>(mIds.size() - start);
        for (const std::size_t j : columns)
            if (j < mSize) mIds.push_back(static_cast<int>(j));
        if (row_count == 0 || mIds.size() == start + static_cast<std::size_t>(row_count)) {
            mIds.resize(start);
            return;
        }
        mBlocks.push_back({start, row_count, static_cast<int>(mIds.size() - start) - row_count});
    }

    /// @return the number of stored entries of @p rA, which receives the graph (values zero)
    std::size_t Compress(SparseMatrixType& rA) const {
        const auto size = static_cast<int>(mSize);
        std::vector<std::size_t> start(mSize + 1, 0);
        for (std::size_t j = 0; j < mSize; ++j) start[j + 1] = 1;  // the diagonal
        for (const Block& block : mBlocks)
            for (int c = 0; c < block.columns; ++c) start[mIds[block.first + block.rows + c] + 1] += block.rows;
        for (std::size_t j = 0; j < mSize; ++j) start[j + 1] += start[j];
        std::vector<int> rows(start[mSize]);
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        for (std::size_t j = 0; j < mSize; ++j) rows[fill[j]++] = static_cast<int>(j);
        for (const Block& block : mBlocks) {
            const int* block_rows = mIds.data() + block.first;
            for (int c = 0; c < block.columns; ++c) {
                std::size_t& next = fill[mIds[block.first + block.rows + c]];
                std::copy(block_rows, block_rows + block.rows, rows.begin() + static_cast<std::ptrdiff_t>(next));
                next += block.rows;
            }
        }
        std::vector<int> counts(mSize);
        const auto n = static_cast<std::ptrdiff_t>(mSize);
#pragma omp parallel for schedule(static)
        for (std::ptrdiff_t j = 0; j < n; ++j) {
            const auto first = rows.begin() + static_cast<std::ptrdiff_t>(start[j]);
            const auto last = rows.begin() + static_cast<std::ptrdiff_t>(start[j + 1]);
            std::sort(first, last);
            counts[j] = static_cast<int>(std::unique(first, last) - first);
        }
        std::size_t nonzeros = 0;
        for (const int count : counts) nonzeros += static_cast<std::size_t>(count);
        rA.resize(size, size);
        rA.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
        int* outer = rA.outerIndexPtr();
        int* inner = rA.innerIndexPtr();
        outer[0] = 0;
        for (std::size_t j = 0; j < mSize; ++j) {
            std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(start[j]), counts[j], inner + outer[j]);
            outer[j + 1] = outer[j] + counts[j];
        }
        std::fill(rA.valuePtr(), rA.valuePtr() + nonzeros, 0.0);
        return nonzeros;
    }

private:
    struct Block {
        std::size_t first;  ///< position of its rows in mIds, its columns follow
        int rows;
        int columns;
    };
    std::size_t mSize;
    std::vector<int> mIds;
    std::vector<Block> mBlocks;
};

/// Calls @p action(entity) for every assembled element and condition.
template <class TAction>
void ForEachAssembled(ModelPart& rModelPart, TAction action) {
    for (const auto& element : rModelPart.Elements())
        if (IsAssembled(*element)) action(*element);
    for (const auto& condition : rModelPart.Conditions())
        if (IsAssembled(*condition)) action(*condition);
}

// -- Parallel assembly (docs/architecture.md, "Threading model") --
// The local systems of a chunk of entities are evaluated in parallel, each into its own slot, and then scattered in
// entity order by threads that own disjoint ranges of columns (and of RHS rows): every global entry receives its terms
// in the serial order whatever the thread count, so the assembled system is bit-identical for any OMP_NUM_THREADS.

/// Entities per chunk: bounds the buffered local systems (3D hexahedra: 4096 × 4.6 kB) and keeps the parallel regions
/// few (each one is a wake-up of the threads, which costs most on a machine shared with other jobs).
constexpr std::size_t kAssemblyChunk = 4096;

/// The local systems of one chunk, slot k for its k-th entity.
struct LocalSystems {
    std::vector<Matrix> lhs;
    std::vector<Vector> rhs;
    std::vector<EquationIdVectorType> ids;
    std::vector<std::exception_ptr> errors;

    void Resize(std::size_t count) {
        lhs.resize(count);
        rhs.resize(count);
        ids.resize(count);
        errors.assign(count, nullptr);
    }
};

/// Pointers to the assembled entities of @p rEntities, in container (id) order.
template <class TContainer>
auto AssembledEntities(const TContainer& rEntities) {
    std::vector<std::remove_reference_t<decltype(*rEntities.begin()->get())>*> result;
    result.reserve(rEntities.size());
    for (const auto& entity : rEntities)
        if (IsAssembled(*entity)) result.push_back(entity.get());
    return result;
}

/// Throws unless the local sizes of slot @p k match its equation ids.
void CheckLocalSizes(const LocalSystems& rLocal, std::size_t k, bool with_lhs, bool with_rhs) {
    const std::size_t n = rLocal.ids[k].size();
    const Vector& rhs = rLocal.rhs[k];
    const Matrix& lhs = rLocal.lhs[k];
    CONTACT_CHECK(!with_rhs || rhs.size() == 0 || static_cast<std::size_t>(rhs.size()) == n, InternalError,
                  "local RHS of size ", rhs.size(), " for ", n, " equation ids");
    CONTACT_CHECK(!with_lhs || lhs.size() == 0 ||
                      (static_cast<std::size_t>(lhs.rows()) == n && static_cast<std::size_t>(lhs.cols()) == n),
                  InternalError, "local LHS of size ", lhs.rows(), "x", lhs.cols(), " for ", n, " equation ids");
}

/// The stored entry (row, column) of the compressed @p rA; null when the sparsity graph lacks it.
double* FindEntry(SparseMatrixType& rA, std::size_t row, std::size_t column) {
    const int* inner = rA.innerIndexPtr();
    const int* first = inner + rA.outerIndexPtr()[column];
    const int* last = inner + rA.outerIndexPtr()[column + 1];
    const int* found = std::lower_bound(first, last, static_cast<int>(row));
    if (found == last || *found != static_cast<int>(row)) return nullptr;
    return rA.valuePtr() + (found - inner);
}

/// Adds slots [0, count) into @p pA / @p pB (either may be null) for the columns and RHS rows [first, last), in slot
/// order; equation ids ≥ @p size skipped. @return false if an entry is missing from the sparsity graph.
bool ScatterRange(SparseMatrixType* pA, SystemVectorType* pB, const LocalSystems& rLocal, std::size_t count,
                  std::size_t size, std::size_t first, std::size_t last) {
    bool complete = true;
    for (std::size_t k = 0; k < count; ++k) {
        const EquationIdVectorType& ids = rLocal.ids[k];
        const std::size_t n = ids.size();
        if (pB != nullptr && rLocal.rhs[k].size() != 0)
            for (std::size_t a = 0; a < n; ++a)
                if (ids[a] >= first && ids[a] < last)
                    (*pB)[static_cast<Eigen::Index>(ids[a])] += rLocal.rhs[k][static_cast<Eigen::Index>(a)];
        if (pA == nullptr || rLocal.lhs[k].size() == 0) continue;
        const Matrix& lhs = rLocal.lhs[k];
        for (std::size_t b = 0; b < n; ++b) {
            if (ids[b] < first || ids[b] >= last) continue;
            for (std::size_t a = 0; a < n; ++a) {
                if (ids[a] >= size) continue;
                double* entry = FindEntry(*pA, ids[a], ids[b]);
                if (entry == nullptr) complete = false;
                else *entry += lhs(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
            }
        }
    }
    return complete;
}

/// One chunk, entities [begin, begin + count) of @p rEntities, in one parallel region: @p evaluate(entity, slot) for
/// each entity (dynamic schedule), then thread t of T adds the columns and RHS rows [size t / T, size (t + 1) / T) in
/// slot order. Rethrows the exception of the first entity that failed (the one a serial loop stops at), before any
/// scatter. @return the seconds of the scatter (of thread 0).
template <class TEntity, class TEvaluate>
double AssembleChunk(const std::vector<TEntity*>& rEntities, std::size_t begin, std::size_t count,
                     LocalSystems& rLocal, SparseMatrixType* pA, SystemVectorType* pB, std::size_t size,
                     const TEvaluate& evaluate) {
    rLocal.Resize(count);
    const auto n = static_cast<std::ptrdiff_t>(count);
    bool failed = false, complete = true;
    double scatter_seconds = 0.0;
#pragma omp parallel reduction(&& : complete)
    {
#pragma omp for schedule(dynamic, 16) reduction(|| : failed)
        for (std::ptrdiff_t i = 0; i < n; ++i) {
            const auto k = static_cast<std::size_t>(i);
            try {
                evaluate(*rEntities[begin + k], k);
                CheckLocalSizes(rLocal, k, pA != nullptr, pB != nullptr);
            } catch (...) {
                rLocal.errors[k] = std::current_exception();
                failed = true;
            }
        }
        // The reduction of `failed` is complete after the loop's barrier.
        if (!failed) {
#ifdef _OPENMP
            const auto threads = static_cast<std::size_t>(omp_get_num_threads());
            const auto thread = static_cast<std::size_t>(omp_get_thread_num());
#else
            const std::size_t threads = 1, thread = 0;
#endif
            const auto start = std::chrono::steady_clock::now();
            complete = ScatterRange(pA, pB, rLocal, count, size, size * thread / threads,
                                    size * (thread + 1) / threads);
            if (thread == 0)
                scatter_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
    }
    for (std::size_t k = 0; k < count && failed; ++k)
        if (rLocal.errors[k]) std::rethrow_exception(rLocal.errors[k]);
    CONTACT_CHECK(complete, InternalError, "a local system has an entry outside the sparsity graph of the builder");
    return scatter_seconds;
}

}  // namespace

BuilderAndSolver::BuilderAndSolver(LinearSolver::Pointer linear_solver) : mLinearSolver(std::move(linear_solver)) {
    CONTACT_CHECK(mLinearSolver != nullptr, InternalError, "builder-and-solver created without a linear solver");
}

void BuilderAndSolver::SetUpDofSet(Scheme&, ModelPart& rModelPart) {
    ScopedTimer timer(mTimings.setup);
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    DofsArrayType dofs, slaves, masters;
    DofsVectorType local;
    ForEachAssembled(rModelPart, [&](auto& entity) {
        entity.GetDofList(local, info);
        dofs.insert(dofs.end(), local.begin(), local.end());
    });
    for (const auto& constraint : rModelPart.MasterSlaveConstraints()) {
        constraint->GetDofList(slaves, masters, info);
        dofs.insert(dofs.end(), slaves.begin(), slaves.end());
        dofs.insert(dofs.end(), masters.begin(), masters.end());
    }
    mDofSet = SortedDistinctDofs(dofs);
    mDofSetIsInitialized = true;
}

void BuilderAndSolver::ResizeAndInitializeVectors(Scheme& rScheme, SparseMatrixType& rA, SystemVectorType& rDx,
                                                  SystemVectorType& rB, ModelPart& rModelPart) {
    ScopedTimer timer(mTimings.setup);
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    // Every equation keeps its diagonal so Dirichlet rows stay solvable.
    GraphBlocks graph(mEquationSystemSize);
    EquationIdVectorType ids;
    ForEachAssembled(rModelPart, [&](auto& entity) {
        entity.EquationIdVector(ids, info);
        graph.Add(ids, ids);
    });
    for (const auto& contributor : mContributors)
        contributor->AddGraph(rModelPart, info, [&](const EquationIdVectorType& rows, const EquationIdVectorType& cols,
                                                    const Matrix*) { graph.Add(rows, cols); });
    (void)rScheme;
    graph.Compress(rA);
    const auto size = static_cast<Eigen::Index>(mEquationSystemSize);
    rDx.setZero(size);
    rB.setZero(size);
}

void BuilderAndSolver::AssembleEntities(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType* pA,
                                        SystemVectorType* pB, std::size_t size) {
    const ProcessInfo& info = rModelPart.GetProcessInfo();
    LocalSystems local;
    auto assemble = [&](const auto& entities) {
        for (std::size_t begin = 0; begin < entities.size(); begin += kAssemblyChunk) {
            const std::size_t count = std::min(kAssemblyChunk, entities.size() - begin);
            mTimings.scatter += AssembleChunk(entities, begin, count, local, pA, pB, size, [&](auto& entity, std::size_t k) {
                if (pA != nullptr && pB != nullptr)
                    rScheme.CalculateSystemContributions(entity, local.lhs[k], local.rhs[k], local.ids[k], info);
                else if (pA != nullptr)
                    rScheme.CalculateLHSContribution(entity, local.lhs[k], local.ids[k], info);
                else
                    rScheme.CalculateRHSContribution(entity, local.rhs[k], local.ids[k], info);
            });
        }
    };
    assemble(AssembledEntities(rModelPart.Elements()));
    assemble(AssembledEntities(rModelPart.Conditions()));
}

void BuilderAndSolver::Build(Scheme& rScheme, ModelPart& rModelPart, SparseMatrixType& rA, SystemVectorType& rB) {
    ScopedTimer timer(mTimings.build);
    ++mTimings.builds;
    std::fill(rA.valuePtr(), rA.valuePtr() + rA.nonZeros(), 0.0);
    rB.setZero(static_cast<Eigen::Index>(mEquationSystemSize));
    AssembleEntities(rScheme, rModelPart, &rA, &rB, mEquationSystemSize);
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
    ScopedTimer timer(mTimings.build);
    std::fill(rA.valuePtr(), rA.valuePtr() + rA.nonZeros(), 0.0);
    AssembleEntities(rScheme, rModelPart, &rA, nullptr, mEquationSystemSize);
    AssembleContributors(rModelPart, rA);
}

void BuilderAndSolver::AssembleResidual(Scheme& rScheme, ModelPart& rModelPart, SystemVectorType& rResidual,
                                        std::size_t size) {
    ScopedTimer timer(mTimings.build);
    ScopedTimer residual_timer(mTimings.residual);
    ++mTimings.residual_builds;
    rResidual.setZero(static_cast<Eigen::Index>(size));
    AssembleEntities(rScheme, rModelPart, nullptr, &rResidual, size);
}

void BuilderAndSolver::BuildRHS(Scheme& rScheme, ModelPart& rModelPart, SystemVectorType& rB) {
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
