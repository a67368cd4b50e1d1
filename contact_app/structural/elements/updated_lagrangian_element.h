// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <vector>

#include "contact_app/structural/elements/base_solid_element.h"

namespace contact_app {

/// Updated-Lagrangian solid (Kratos UpdatedLagrangian): integrates on the current configuration with the
/// Cauchy stress σ from the law, RHS = ∫_Ωt (Nᵀ b/J − Bᵀ σ) dΩ, LHS = ∫_Ωt (Bᵀ D_σ B + K_g[σ]) dΩ
/// (× THICKNESS in 2D), B linear in ∂N/∂x. F = ΔF F0 with ΔF = ∂x/∂x_n relative to the last converged
/// configuration x_n = x − (u − u_n) and F0 the total F stored per point at the end of each step.
/// Needs a nodal buffer of at least 2 steps. Registers UpdatedLagrangianElement{2D3N,2D4N,2D6N,3D4N,3D8N,3D10N}.
template <int TDim, int TNumNodes>
class UpdatedLagrangianElement : public BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>> {
public:
    using BaseType = BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>>;
    using BaseType::BaseType;
    using BaseType::Create;
    using typename BaseType::Kinematics;
    using typename BaseType::StressMeasure;

    /// @brief A new UpdatedLagrangianElement on @p geometry (shared), with @p properties (shared).
    Element::Pointer Create(IndexType new_id, Geometry::Pointer geometry,
                            Properties::Pointer properties) const override;

    /// @brief Base Initialize, then F0 = I, det F0 = 1 at every point (unless Load restored them). @throws InputError if
    ///        the buffer is < 2
    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Makes the F stored by the last FinalizeSolutionStep the new F0, then the base hook.
    void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Base hook, then stores the converged total F (applied as F0 from the next step on).
    void FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Base checks plus a nodal buffer of at least 2 steps. @throws InputError
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;
    /// @brief Base state, then F0 and the F stored for the next step at every point: without them a restarted run
    ///        would measure its strains from the restart configuration (F0 = I).
    void Save(Serializer& rSerializer) const override;
    /// @brief As Save wrote it; the Initialize that follows a restart keeps the loaded F0.
    void Load(Serializer& rSerializer) override;

protected:
    const char* FamilyName() const override { return "UpdatedLagrangianElement"; }
    StressMeasure GetStressMeasure() const override { return StressMeasure::Cauchy; }
    bool UseElementProvidedStrain() const override { return false; }
    bool UsesGeometricStiffness() const override { return true; }
    bool HasConstantKinematics() const override { return false; }
    /// @throws ConvergenceError if the element is inverted in the current configuration
    void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const override;

private:
    using TensorType = Eigen::Matrix<double, TDim, TDim>;

    void CheckBufferSize() const;

    std::vector<TensorType> mF0;      ///< total F at the end of the last converged step, per point
    std::vector<double> mDetF0;       ///< det mF0
    std::vector<TensorType> mF0Next;  ///< F stored by FinalizeSolutionStep, applied at InitializeSolutionStep
    std::vector<double> mDetF0Next;
    bool mHasF0Next = false;
    bool mRestored = false;  ///< F0 came from Load (a restart), not from the undeformed configuration
};

#define CONTACT_APP_UPDATED_LAGRANGIAN_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class UpdatedLagrangianElement<TDim, TNumNodes>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_UPDATED_LAGRANGIAN_EXTERN)
#undef CONTACT_APP_UPDATED_LAGRANGIAN_EXTERN

}  // namespace contact_app
