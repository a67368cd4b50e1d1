// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_types.h"

namespace contact_app {

/// Mortar mesh tying with dual Lagrange multipliers (Kratos MeshTyingMortarCondition; docs/theory/contact_residuals.md
/// §10,
/// docs/registered_conditions.md). The tied variable is the TYING_VARIABLE property (default "DISPLACEMENT"): a double
/// variable is tied with SCALAR_LAGRANGE_MULTIPLIER, a 3-vector variable component by component (its _X, _Y(, _Z))
/// with VECTOR_LAGRANGE_MULTIPLIER_X/Y(/Z). D and M (dual basis when Ae succeeds) are integrated once, in
/// Initialize, with the coordinates of that moment, and cached: the operators of a tied interface are constant.
/// With k = SCALE_FACTOR (ProcessInfo), else BUILD_SCALE_FACTOR, else 1, and q = [u2, u1, λ] (node-major,
/// component-minor, dof_size components per node) the local system is, per component,
///   K = [[0, 0, −k Mᵀ], [0, 0, k Dᵀ], [−k M, k D, 0]],  RHS = [k Mᵀλ; −k Dᵀλ; −k (D u1 − M u2)],
/// K = −∂RHS/∂q, values of the tied variable at step 0. Converged state: D u1 = M u2.
/// Registers MeshTyingMortarCondition{2D2N,3D3N,3D4N,3D3N4N,3D4N3N}; no NV variant.
template <int TDim, int TNumNodes, int TNumNodesMaster = TNumNodes>
class MeshTyingMortarCondition : public PairedCondition {
public:
    /// A pair whose overlap / slave measure is at most this ratio is deactivated (ACTIVE = false). The reference
    /// compares the overlap with 1e−3·(slave area)², which depends on the length unit ([BUG?] B5); this is the
    /// dimensionless version of the same 1e−3.
    static constexpr double MinimumOverlapRatio = 1.0e-3;
    using Operators = MortarOperators<double, TNumNodes, TNumNodesMaster>;

    using PairedCondition::PairedCondition;
    using PairedCondition::Create;
    Condition::Pointer Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                              Geometry::Pointer master) const override;

    /// Resolves TYING_VARIABLE, integrates and caches D, M; ACTIVE = false when the pair does not overlap. On the
    /// first call after Load only the variable is resolved: the operators stay those of the saving run.
    /// @throws InputError for an unknown variable or one that is neither double nor a 3-vector
    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    /// [master tied components, slave tied components, slave multipliers], node-major.
    /// @throws InputError if a DoF is missing
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const override;
    /// @throws InputError: unpaired, wrong node counts, a bad TYING_VARIABLE, or a node lacking the tied variable
    ///         (historical) or its DoFs, or (slave) the multiplier variable or its DoFs
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;
    std::string Info() const override;
    /// Base state plus the cached operators (integrated once, on the coordinates of the first Initialize).
    void Save(Serializer& rSerializer) const override;
    void Load(Serializer& rSerializer) override;

    /// The cached operators (zero before Initialize or for a deactivated pair).
    const Operators& GetMortarOperators() const { return mOperators; }
    /// Whether the cached operators use the dual basis.
    bool IsDualBasis() const { return mDual; }
    /// Number of tied components per node (1 for a double variable, TDim for a 3-vector).
    int DofSize() const { return static_cast<int>(TiedVariables().size()); }
    /// dof_size·(2 n_s + n_m).
    int LocalSize() const { return DofSize() * (2 * TNumNodes + TNumNodesMaster); }

protected:
    /// @param[out] pLhs, pRhs dof_size·(2 n_s + n_m) (either may be null); zero for a deactivated pair
    /// @param[in] rCurrentProcessInfo SCALE_FACTOR (else BUILD_SCALE_FACTOR, else 1) scales the multiplier rows
    void CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo& rCurrentProcessInfo) override;

private:
    struct TyingVariables {
        std::vector<const Variable<double>*> dofs;  ///< tied components
        std::vector<const Variable<double>*> multipliers;
        const VariableData* variable = nullptr;     ///< TYING_VARIABLE itself (historical storage check)
        const VariableData* multiplier = nullptr;   ///< SCALAR_ / VECTOR_LAGRANGE_MULTIPLIER
    };
    /// TYING_VARIABLE of the properties resolved to components. @throws InputError (see Initialize)
    TyingVariables ResolveTyingVariables() const;
    /// The resolved components (from Initialize, or resolved now before it).
    const std::vector<const Variable<double>*>& TiedVariables() const;

    Operators mOperators;
    bool mDual = false;
    bool mInitialized = false;
    bool mRestored = false;  ///< set by Load, consumed by the next Initialize
    mutable TyingVariables mTying;
};

}  // namespace contact_app
