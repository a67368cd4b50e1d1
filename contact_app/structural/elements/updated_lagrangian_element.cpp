// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/updated_lagrangian_element.h"

#include <memory>

#include <Eigen/Dense>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/serializer.h"

namespace contact_app {

template <int TDim, int TNumNodes>
Element::Pointer UpdatedLagrangianElement<TDim, TNumNodes>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                                   Properties::Pointer properties) const {
    return std::make_shared<UpdatedLagrangianElement>(new_id, std::move(geometry), std::move(properties));
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::CheckBufferSize() const {
    const Geometry& geometry = this->GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i)
        CONTACT_CHECK(geometry[i].GetBufferSize() >= 2, InputError, this->Info(), ": node ", geometry[i].Id(),
                      " has a solution-step buffer of size ", geometry[i].GetBufferSize(),
                      "\n  expected: buffer size >= 2 (the element reads the DISPLACEMENT of the previous step)",
                      "\n  fix: create the model part with buffer_size 2 or more (the structural solvers do)");
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    CheckBufferSize();
    BaseType::Initialize(rCurrentProcessInfo);
    const std::size_t n = this->NumberOfIntegrationPoints();
    if (mRestored && mF0.size() == n) return;
    mF0.assign(n, TensorType::Identity());
    mDetF0.assign(n, 1.0);
    mF0Next = mF0;
    mDetF0Next = mDetF0;
    mHasF0Next = false;
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::Save(Serializer& rSerializer) const {
    BaseType::Save(rSerializer);
    rSerializer.Save("UpdatedLagrangianPoints", mF0.size());
    for (std::size_t g = 0; g < mF0.size(); ++g) {
        rSerializer.Save("F0", mF0[g]);
        rSerializer.Save("DetF0", mDetF0[g]);
        rSerializer.Save("F0Next", mF0Next[g]);
        rSerializer.Save("DetF0Next", mDetF0Next[g]);
    }
    rSerializer.Save("HasF0Next", mHasF0Next);
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::Load(Serializer& rSerializer) {
    BaseType::Load(rSerializer);
    std::size_t n = 0;
    rSerializer.Load("UpdatedLagrangianPoints", n);
    mF0.resize(n);
    mDetF0.resize(n);
    mF0Next.resize(n);
    mDetF0Next.resize(n);
    for (std::size_t g = 0; g < n; ++g) {
        rSerializer.Load("F0", mF0[g]);
        rSerializer.Load("DetF0", mDetF0[g]);
        rSerializer.Load("F0Next", mF0Next[g]);
        rSerializer.Load("DetF0Next", mDetF0Next[g]);
    }
    rSerializer.Load("HasF0Next", mHasF0Next);
    mRestored = n > 0;
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    // docs/theory/structural.md §8 D6: Kratos makes F read as ΔF alone between FinalizeSolutionStep and the next
    // InitializeSolutionStep; applying the stored F here keeps F = ΔF F0 the total F in every window.
    if (mHasF0Next) {
        mF0 = mF0Next;
        mDetF0 = mDetF0Next;
        mHasF0Next = false;
    }
    BaseType::InitializeSolutionStep(rCurrentProcessInfo);
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    BaseType::FinalizeSolutionStep(rCurrentProcessInfo);
    Kinematics kinematics;
    for (std::size_t g = 0; g < this->NumberOfIntegrationPoints(); ++g) {
        ComputeKinematics(g, kinematics);
        mF0Next[g] = kinematics.F;
        mDetF0Next[g] = kinematics.detF;
    }
    mHasF0Next = true;
}

template <int TDim, int TNumNodes>
int UpdatedLagrangianElement<TDim, TNumNodes>::Check(const ProcessInfo& rCurrentProcessInfo) const {
    CheckBufferSize();
    return BaseType::Check(rCurrentProcessInfo);
}

template <int TDim, int TNumNodes>
void UpdatedLagrangianElement<TDim, TNumNodes>::ComputeKinematics(std::size_t point, Kinematics& rKinematics) const {
    using NodalMatrix = typename BaseType::NodalMatrix;
    const auto& reference = this->GetReferencePoint(point);
    const NodalMatrix x = this->NodalCoordinates(Geometry::Configuration::Current);
    const NodalMatrix x_n = x - (this->NodalDisplacements(0) - this->NodalDisplacements(1));
    const TensorType J = x.transpose() * reference.DN_De;
    const TensorType J_n = x_n.transpose() * reference.DN_De;
    const double det_j = J.determinant();
    if (!(det_j > 0.0)) this->ThrowInverted(point, det_j, true);
    rKinematics.N = reference.N;
    rKinematics.DN_DX = reference.DN_De * J.inverse();
    rKinematics.F.setIdentity();
    FillStrainDisplacementMatrix(rKinematics);  // linear B in ∂N/∂x
    rKinematics.F = J * J_n.inverse() * mF0[point];
    rKinematics.detF = det_j / J_n.determinant() * mDetF0[point];
    rKinematics.strain = GreenLagrangeStrain<kSolidStrainSize<TDim>>(rKinematics.F);
    rKinematics.weight = reference.weight * det_j * this->ThicknessFactor();
    // docs/theory/structural.md §8 D5: Kratos integrates ρ0 b over the current volume; ρ0 b dV0 = ρ0 b dv / J is the
    // correct load.
    rKinematics.body_weight = rKinematics.weight / rKinematics.detF;
}

#define CONTACT_APP_UPDATED_LAGRANGIAN_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class UpdatedLagrangianElement<TDim, TNumNodes>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_UPDATED_LAGRANGIAN_INSTANTIATE)

}  // namespace contact_app
