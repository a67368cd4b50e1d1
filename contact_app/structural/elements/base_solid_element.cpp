// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/elements/base_solid_element.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/inverted_element_error.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/properties.h"
#include "contact_app/kernel/variables.h"

namespace contact_app {

namespace {

const Variable<double>* const kDisplacementComponents[3] = {&DISPLACEMENT_X, &DISPLACEMENT_Y, &DISPLACEMENT_Z};
const Variable<double>* const kReactionComponents[3] = {&REACTION_X, &REACTION_Y, &REACTION_Z};

/// TIME of the ProcessInfo, NaN when it has none (an element evaluated outside an analysis).
double TimeOf(const ProcessInfo& rCurrentProcessInfo) {
    return rCurrentProcessInfo.Has(TIME) ? rCurrentProcessInfo.GetValue(TIME) : std::nan("");
}

/// Laws that fit a strain size, for messages.
const char* LawExamples(int strain_size) {
    if (strain_size == 4) return "LinearElasticAxisym2DLaw";
    return strain_size == 3 ? "LinearElasticPlaneStrain2DLaw, LinearElasticPlaneStress2DLaw, "
                              "HyperElasticPlaneStrain2DLaw or KirchhoffSaintVenantPlaneStrain2DLaw"
                            : "LinearElastic3DLaw, HyperElastic3DLaw or KirchhoffSaintVenant3DLaw";
}

}  // namespace

template <int TDim, int TNumNodes, int TStrainSize>
BaseSolidElement<TDim, TNumNodes, TStrainSize>::BaseSolidElement(IndexType id, Geometry::Pointer geometry,
                                                                 Properties::Pointer properties)
    : Element(id, std::move(geometry), std::move(properties)) {
    const Geometry& g = GetGeometry();
    CONTACT_CHECK(g.PointsNumber() == TNumNodes && g.WorkingSpaceDimension() == TDim && g.LocalSpaceDimension() == TDim,
                  InputError, "solid element #", id, ": a ", g.Name(), " geometry (", g.PointsNumber(),
                  " nodes) cannot carry a ", TDim, "D element with ", TNumNodes, " nodes", "\n  expected: a ", TDim,
                  "D solid geometry with ", TNumNodes, " nodes",
                  "\n  fix: use the element name whose suffix matches the geometry (…2D4N for Quadrilateral2D4)");
}

template <int TDim, int TNumNodes, int TStrainSize>
std::string BaseSolidElement<TDim, TNumNodes, TStrainSize>::Info() const {
    return std::string(FamilyName()) + std::to_string(TDim) + "D" + std::to_string(TNumNodes) + "N #" +
           std::to_string(Id()) + " (" + GetGeometry().Name() + ")";
}

// -- Life cycle --

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::Initialize(const ProcessInfo&) {
    const Geometry& geometry = GetGeometry();
    const Properties& properties = GetProperties();
    const ConstitutiveLaw::Pointer law = CheckedLaw();
    CheckReferenceConfiguration();
    const NodalMatrix X0 = NodalCoordinates(Geometry::Configuration::Initial);
    mReferencePoints.clear();
    mLaws.clear();
    Vector N;
    Matrix DN;
    for (const IntegrationPoint& point : geometry.IntegrationPoints(IntegrationOrder())) {
        geometry.ShapeFunctionsValues(N, point.local);
        geometry.ShapeFunctionsLocalGradients(DN, point.local);
        ReferencePoint reference;
        reference.N = N;
        reference.DN_De = DN;
        reference.weight = point.weight;
        const Eigen::Matrix<double, TDim, TDim> J0 = X0.transpose() * reference.DN_De;
        reference.detJ0 = J0.determinant();
        reference.DN_DX0 = reference.DN_De * J0.inverse();
        mReferencePoints.push_back(reference);
        mLaws.push_back(law->Clone());
        mLaws.back()->InitializeMaterial(properties, geometry, N);
    }
    mKeepsStiffness = HasConstantKinematics() && law->IsLinear();
    mKeptStiffness.clear();
}

template <int TDim, int TNumNodes, int TStrainSize>
std::string BaseSolidElement<TDim, TNumNodes, TStrainSize>::WhyStiffnessVaries() const {
    if (!HasConstantKinematics())
        return std::string("is a ") + FamilyName() + ", whose stiffness follows the displacement";
    const Properties& properties = GetProperties();
    const ConstitutiveLaw::Pointer law =
        properties.Has(CONSTITUTIVE_LAW) ? properties.GetValue(CONSTITUTIVE_LAW) : nullptr;
    if (law == nullptr) return "has no constitutive law";
    if (!law->IsLinear()) return "has " + law->Info() + ", not a linear elastic law";
    return "";
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    mKeptStiffness.clear();  // the properties may have changed since the last step
    if (mKeepsStiffness) return;  // linear laws keep no state
    ForEachPointResponse(GetStressMeasure(), rCurrentProcessInfo,
                         [&](std::size_t g, const Kinematics&, ConstitutiveLaw::Parameters& values) {
                             mLaws[g]->InitializeMaterialResponse(values, GetStressMeasure());
                         });
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    if (mKeepsStiffness) return;  // linear laws keep no state
    ForEachPointResponse(GetStressMeasure(), rCurrentProcessInfo,
                         [&](std::size_t g, const Kinematics&, ConstitutiveLaw::Parameters& values) {
                             mLaws[g]->FinalizeMaterialResponse(values, GetStressMeasure());
                         });
}

// -- Local system --

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateLocalSystem(Matrix& rLeftHandSideMatrix,
                                                                          Vector& rRightHandSideVector,
                                                                          const ProcessInfo& rCurrentProcessInfo) {
    CalculateAll(&rLeftHandSideMatrix, &rRightHandSideVector, rCurrentProcessInfo);
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateLeftHandSide(Matrix& rLeftHandSideMatrix,
                                                                           const ProcessInfo& rCurrentProcessInfo) {
    CalculateAll(&rLeftHandSideMatrix, nullptr, rCurrentProcessInfo);
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateRightHandSide(Vector& rRightHandSideVector,
                                                                            const ProcessInfo& rCurrentProcessInfo) {
    CalculateAll(nullptr, &rRightHandSideVector, rCurrentProcessInfo);
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateAll(Matrix* pLeftHandSide, Vector* pRightHandSide,
                                                                  const ProcessInfo& rCurrentProcessInfo) {
    CheckInitialized();
    if (mKeepsStiffness) return CalculateFromKeptStiffness(pLeftHandSide, pRightHandSide, rCurrentProcessInfo);
    Eigen::Matrix<double, kDofs, kDofs> lhs = Eigen::Matrix<double, kDofs, kDofs>::Zero();
    Eigen::Matrix<double, kDofs, 1> rhs = Eigen::Matrix<double, kDofs, 1>::Zero();
    const BodyForce body = pRightHandSide ? ComputeBodyForce() : BodyForce{};
    ConstitutiveLaw::Parameters values = LawParameters(rCurrentProcessInfo);
    values.compute_constitutive_tensor = pLeftHandSide != nullptr;
    Kinematics k;
    for (std::size_t g = 0; g < NumberOfIntegrationPoints(); ++g) {
        PointResponse(g, GetStressMeasure(), rCurrentProcessInfo, k, values);
        const StrainVector stress = values.stress_vector;
        if (pRightHandSide) {
            rhs.noalias() -= k.weight * (k.B.transpose() * stress);
            AddBodyForce(body, k, rhs);
        }
        if (pLeftHandSide) {
            const Eigen::Matrix<double, TStrainSize, TStrainSize> D = values.constitutive_matrix;
            lhs.noalias() += k.weight * (k.B.transpose() * D * k.B);
            if (UsesGeometricStiffness()) AddGeometricStiffness(k, stress, lhs);
        }
    }
    if (pLeftHandSide) *pLeftHandSide = lhs;
    if (pRightHandSide) *pRightHandSide = rhs;
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateFromKeptStiffness(Matrix* pLeftHandSide,
                                                                                Vector* pRightHandSide,
                                                                                const ProcessInfo& rCurrentProcessInfo) {
    using DofMatrix = Eigen::Matrix<double, kDofs, kDofs>;
    constexpr std::size_t packed_size = kDofs * (kDofs + 1) / 2;
    if (mKeptStiffness.empty()) {
        DofMatrix K = DofMatrix::Zero();
        ConstitutiveLaw::Parameters values = LawParameters(rCurrentProcessInfo);
        values.compute_constitutive_tensor = true;
        Kinematics k;
        for (std::size_t g = 0; g < NumberOfIntegrationPoints(); ++g) {
            PointResponse(g, GetStressMeasure(), rCurrentProcessInfo, k, values);
            const Eigen::Matrix<double, TStrainSize, TStrainSize> D = values.constitutive_matrix;
            K.noalias() += k.weight * (k.B.transpose() * D * k.B);
        }
        mKeptStiffness.resize(packed_size);
        std::size_t entry = 0;
        for (int j = 0; j < kDofs; ++j)  // the mean of the two triangles: symmetric to the last bit
            for (int i = 0; i <= j; ++i) mKeptStiffness[entry++] = 0.5 * (K(i, j) + K(j, i));
    }
    DofMatrix K;
    std::size_t entry = 0;
    for (int j = 0; j < kDofs; ++j)
        for (int i = 0; i <= j; ++i) K(i, j) = K(j, i) = mKeptStiffness[entry++];
    if (pLeftHandSide) *pLeftHandSide = K;
    if (pRightHandSide == nullptr) return;
    const NodalMatrix displacement = NodalDisplacements(0);
    Eigen::Matrix<double, kDofs, 1> u;
    for (int i = 0; i < TNumNodes; ++i) u.template segment<TDim>(i * TDim) = displacement.row(i).transpose();
    Eigen::Matrix<double, kDofs, 1> rhs = -(K * u);
    const BodyForce body = ComputeBodyForce();
    if (body.density != 0.0 && !(body.constant.isZero(0.0) && body.nodal.isZero(0.0))) {
        Kinematics k;
        for (std::size_t g = 0; g < NumberOfIntegrationPoints(); ++g) {
            ComputeKinematics(g, k);
            AddBodyForce(body, k, rhs);
        }
    }
    *pRightHandSide = rhs;
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::AddBodyForce(const BodyForce& body, const Kinematics& rKinematics,
                                                                  Eigen::Matrix<double, kDofs, 1>& rRightHandSide) {
    if (body.density == 0.0) return;
    const Eigen::Matrix<double, 1, TDim> b =
        body.density * (body.constant + rKinematics.N.transpose() * body.nodal);
    for (int i = 0; i < TNumNodes; ++i)
        rRightHandSide.template segment<TDim>(i * TDim) += (rKinematics.body_weight * rKinematics.N[i]) * b.transpose();
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::AddGeometricStiffness(
    const Kinematics& rKinematics, const StrainVector& stress, Eigen::Matrix<double, kDofs, kDofs>& rLeftHandSide) {
    const FMatrix sigma = VoigtToSymmetricTensor<Kinematics::kFSize>(stress);
    const Eigen::Matrix<double, TNumNodes, TNumNodes> G =
        rKinematics.weight *
        (rKinematics.DN_DX * sigma.template topLeftCorner<TDim, TDim>() * rKinematics.DN_DX.transpose());
    for (int i = 0; i < TNumNodes; ++i) {
        for (int j = 0; j < TNumNodes; ++j) {
            for (int a = 0; a < TDim; ++a) rLeftHandSide(i * TDim + a, j * TDim + a) += G(i, j);
            // Hoop term of δ(ΔE_θθ) = (N_i/R)(N_j/R) on the radial DoFs, weighted by S_θθ.
            if constexpr (kAxisymmetric)
                rLeftHandSide(i * TDim, j * TDim) +=
                    rKinematics.weight * sigma(2, 2) * rKinematics.hoop[i] * rKinematics.hoop[j];
        }
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
ConstitutiveLaw::Parameters BaseSolidElement<TDim, TNumNodes, TStrainSize>::LawParameters(
    const ProcessInfo& rCurrentProcessInfo) const {
    ConstitutiveLaw::Parameters values;
    values.use_element_provided_strain = UseElementProvidedStrain();
    values.compute_stress = true;
    values.compute_constitutive_tensor = false;
    values.material_properties = &GetProperties();
    values.element_geometry = &GetGeometry();
    values.process_info = &rCurrentProcessInfo;
    values.strain_vector.setZero(TStrainSize);
    values.stress_vector.setZero(TStrainSize);
    return values;
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::PointResponse(std::size_t point, StressMeasure measure,
                                                                   const ProcessInfo& rCurrentProcessInfo,
                                                                   Kinematics& rKinematics,
                                                                   ConstitutiveLaw::Parameters& rValues) const {
    try {
        ComputeKinematics(point, rKinematics);
        EvaluateLaw(point, rKinematics, measure, rValues);
    } catch (const InvertedElementError& error) {
        // The law knows neither the element nor TIME; the Newton iteration's caller reports both.
        throw error.Located(Id(), Info(), TimeOf(rCurrentProcessInfo));
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::EvaluateLaw(std::size_t point, const Kinematics& rKinematics,
                                                                 StressMeasure measure,
                                                                 ConstitutiveLaw::Parameters& rValues) const {
    rValues.deformation_gradient = rKinematics.F;
    rValues.determinant_f = rKinematics.detF;
    if (rValues.use_element_provided_strain) rValues.strain_vector = rKinematics.strain;
    mLaws[point]->CalculateMaterialResponse(rValues, measure);
    const bool tangent_ok =
        !rValues.compute_constitutive_tensor ||
        (rValues.constitutive_matrix.rows() == TStrainSize && rValues.constitutive_matrix.cols() == TStrainSize);
    CONTACT_CHECK(rValues.stress_vector.size() == TStrainSize && tangent_ok, InternalError, Info(), ": law ",
                  mLaws[point]->Info(), " returned a stress of size ", rValues.stress_vector.size(),
                  " and a tangent of size ", rValues.constitutive_matrix.rows(), "×",
                  rValues.constitutive_matrix.cols(), " for strain size ", TStrainSize);
}

template <int TDim, int TNumNodes, int TStrainSize>
typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::BodyForce
BaseSolidElement<TDim, TNumNodes, TStrainSize>::ComputeBodyForce() const {
    const Properties& properties = GetProperties();
    BodyForce body;
    body.density = properties.Has(DENSITY) ? properties.GetValue(DENSITY) : 0.0;
    body.constant.setZero();
    body.nodal.setZero();
    if (body.density == 0.0) return body;  // no body force whatever the accelerations
    if (properties.Has(VOLUME_ACCELERATION))
        body.constant = properties.GetValue(VOLUME_ACCELERATION).template head<TDim>().transpose();
    const Geometry& geometry = GetGeometry();
    for (int i = 0; i < TNumNodes; ++i) {
        const Node& node = geometry[i];
        if (node.SolutionStepsDataHas(VOLUME_ACCELERATION))
            body.nodal.row(i) = node.GetSolutionStepValue(VOLUME_ACCELERATION).template head<TDim>().transpose();
    }
    return body;
}

// -- Kinematics helpers --

template <int TDim, int TNumNodes, int TStrainSize>
typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalMatrix
BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalCoordinates(Geometry::Configuration configuration) const {
    const Geometry& geometry = GetGeometry();
    NodalMatrix x;
    for (int i = 0; i < TNumNodes; ++i) {
        const Node& node = geometry[i];
        const Array3& xi =
            configuration == Geometry::Configuration::Initial ? node.InitialCoordinates() : node.Coordinates();
        x.row(i) = xi.template head<TDim>().transpose();
    }
    return x;
}

template <int TDim, int TNumNodes, int TStrainSize>
typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalMatrix
BaseSolidElement<TDim, TNumNodes, TStrainSize>::NodalDisplacements(std::size_t step) const {
    const Geometry& geometry = GetGeometry();
    NodalMatrix u;
    for (int i = 0; i < TNumNodes; ++i)
        u.row(i) = geometry[i].GetSolutionStepValue(DISPLACEMENT, step).template head<TDim>().transpose();
    return u;
}

template <int TDim, int TNumNodes, int TStrainSize>
double BaseSolidElement<TDim, TNumNodes, TStrainSize>::ThicknessFactor() const {
    if constexpr (TDim == 2) {
        const Properties& properties = GetProperties();
        return properties.Has(THICKNESS) ? properties.GetValue(THICKNESS) : 1.0;
    } else {
        return 1.0;
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
double BaseSolidElement<TDim, TNumNodes, TStrainSize>::ReferenceVolumeFactor(const ShapeVector& N) const {
    if constexpr (kAxisymmetric) {
        const NodalMatrix X0 = NodalCoordinates(Geometry::Configuration::Initial);
        return 2.0 * M_PI * N.dot(X0.col(0));
    } else {
        return ThicknessFactor();
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::ThrowInverted(std::size_t point, double det_j,
                                                                   bool current_configuration) const {
    if (current_configuration) {
        throw InvertedElementError(
            detail::Concat(Info(), " is inverted in the current configuration: det J = ", det_j,
                           " at integration point ", point, " (nodes ", GetGeometry().NodeIdsString(), ")",
                           "\n  expected: det J > 0 at every integration point",
                           "\n  fix: apply the load in smaller increments (more time steps, or step cutting: "
                           "contact_settings.adaptative_strategy) or refine the mesh there"),
            Id(), "det J", det_j, std::nan(""));
    }
    CONTACT_THROW(InputError, Info(), " is inverted or degenerate: det J = ", det_j, " at integration point ", point,
                  " of the initial configuration (nodes ", GetGeometry().NodeIdsString(), ")",
                  "\n  expected: det J > 0 at every integration point",
                  "\n  fix: order the nodes counter-clockwise in 2D (Kratos/GiD order in 3D) and remove coincident "
                  "or collinear nodes");
}

// -- Checks --

template <int TDim, int TNumNodes, int TStrainSize>
ConstitutiveLaw::Pointer BaseSolidElement<TDim, TNumNodes, TStrainSize>::CheckedLaw() const {
    const Properties& properties = GetProperties();
    const ConstitutiveLaw::Pointer law =
        properties.Has(CONSTITUTIVE_LAW) ? properties.GetValue(CONSTITUTIVE_LAW) : nullptr;
    CONTACT_CHECK(law != nullptr, InputError, Info(), ": properties ", properties.Id(), " have no CONSTITUTIVE_LAW",
                  "\n  expected: a ", TDim, "D law with strain size ", TStrainSize, " (", LawExamples(TStrainSize), ")",
                  "\n  fix: set \"constitutive_law\": {\"name\": ...} for properties ", properties.Id(),
                  " in the materials file");
    CONTACT_CHECK(law->WorkingSpaceDimension() == TDim && law->GetStrainSize() == TStrainSize, InputError, Info(),
                  ": constitutive law ", law->Info(), " of properties ", properties.Id(), " has dimension ",
                  law->WorkingSpaceDimension(), " and strain size ", law->GetStrainSize(), "\n  expected: dimension ",
                  TDim, " and strain size ", TStrainSize, " (", LawExamples(TStrainSize), ")",
                  "\n  fix: choose a law that matches the element (or an element that matches the law)");
    return law;
}

template <int TDim, int TNumNodes, int TStrainSize>
int BaseSolidElement<TDim, TNumNodes, TStrainSize>::IntegrationOrder() const {
    const Properties& properties = GetProperties();
    if (!properties.Has(INTEGRATION_ORDER)) return GetGeometry().DefaultIntegrationOrder();
    const int order = properties.GetValue(INTEGRATION_ORDER);
    CONTACT_CHECK(order >= 1 && order <= 5, InputError, Info(), ": INTEGRATION_ORDER = ", order, " in properties ",
                  properties.Id(), " is out of range\n  expected: 1..5 (Kratos GI_GAUSS_1..5)",
                  "\n  fix: remove INTEGRATION_ORDER to use the geometry default (",
                  GetGeometry().DefaultIntegrationOrder(), ")");
    return order;
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CheckReferenceConfiguration() const {
    const Geometry& geometry = GetGeometry();
    const NodalMatrix X0 = NodalCoordinates(Geometry::Configuration::Initial);
    Vector N;
    Matrix DN;
    std::size_t g = 0;
    for (const IntegrationPoint& point : geometry.IntegrationPoints(IntegrationOrder())) {
        geometry.ShapeFunctionsLocalGradients(DN, point.local);
        const Eigen::Matrix<double, TDim, TDim> J0 = X0.transpose() * NodalMatrix(DN);
        const double det_j0 = J0.determinant();
        if (!(det_j0 > 0.0)) ThrowInverted(g, det_j0, false);
        if constexpr (kAxisymmetric) {
            geometry.ShapeFunctionsValues(N, point.local);
            const double radius = N.dot(Vector(X0.col(0)));
            CONTACT_CHECK(radius > 0.0, InputError, Info(), ": integration point ", g, " lies at radius R = ", radius,
                          " (nodes ", geometry.NodeIdsString(),
                          ")\n  expected: R = x > 0 (x is the radius, y the axis)",
                          "\n  fix: place the axisymmetric mesh in x >= 0 with the axis of symmetry on x = 0");
        }
        ++g;
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CheckInitialized() const {
    CONTACT_CHECK(!mLaws.empty(), InputError, Info(), " was not initialized",
                  "\n  expected: Initialize() before any local system, result or step hook",
                  "\n  fix: initialize the model part (the solver's Initialize() does it) before solving");
}

template <int TDim, int TNumNodes, int TStrainSize>
int BaseSolidElement<TDim, TNumNodes, TStrainSize>::Check(const ProcessInfo& rCurrentProcessInfo) const {
    const Properties& properties = GetProperties();
    const ConstitutiveLaw::Pointer law = CheckedLaw();
    law->Check(properties, GetGeometry(), rCurrentProcessInfo);
    const Geometry& geometry = GetGeometry();
    for (std::size_t i = 0; i < geometry.PointsNumber(); ++i) {
        const Node& node = geometry[i];
        CONTACT_CHECK(node.SolutionStepsDataHas(DISPLACEMENT), InputError, Info(), ": node ", node.Id(),
                      " has no historical DISPLACEMENT\n  expected: DISPLACEMENT in the nodal solution-step data",
                      "\n  fix: AddNodalSolutionStepVariable(DISPLACEMENT) before reading the mesh");
        for (int a = 0; a < TDim; ++a)
            CONTACT_CHECK(node.HasDofFor(*kDisplacementComponents[a]), InputError, Info(), ": node ", node.Id(),
                          " has no DoF ", kDisplacementComponents[a]->Name(), "\n  expected: DoFs DISPLACEMENT_X, _Y",
                          (TDim == 3 ? ", _Z" : ""), " on every node", "\n  fix: AddDof(",
                          kDisplacementComponents[a]->Name(), ", ", kReactionComponents[a]->Name(),
                          ") on the nodes (the solver's AddDofs() does it)");
    }
    CheckReferenceConfiguration();
    return Element::Check(rCurrentProcessInfo);
}

// -- DoFs and values --

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::EquationIdVector(EquationIdVectorType& rResult,
                                                                      const ProcessInfo&) const {
    const Geometry& geometry = GetGeometry();
    rResult.resize(kDofs);
    for (int i = 0; i < TNumNodes; ++i)
        for (int a = 0; a < TDim; ++a)
            rResult[i * TDim + a] = geometry[i].GetDof(*kDisplacementComponents[a]).EquationId();
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::GetDofList(DofsVectorType& rElementalDofList,
                                                                const ProcessInfo&) const {
    const Geometry& geometry = GetGeometry();
    rElementalDofList.resize(kDofs);
    for (int i = 0; i < TNumNodes; ++i)
        for (int a = 0; a < TDim; ++a)
            rElementalDofList[i * TDim + a] = &geometry[i].GetDof(*kDisplacementComponents[a]);
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::FillNodalVector(const Variable<Array3>& variable, int step,
                                                                     Vector& rValues) const {
    const Geometry& geometry = GetGeometry();
    rValues.resize(kDofs);
    for (int i = 0; i < TNumNodes; ++i)
        rValues.segment<TDim>(i * TDim) =
            geometry[i].GetSolutionStepValue(variable, static_cast<std::size_t>(step)).template head<TDim>();
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::GetValuesVector(Vector& rValues, int Step) const {
    FillNodalVector(DISPLACEMENT, Step, rValues);
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::GetFirstDerivativesVector(Vector& rValues, int Step) const {
    FillNodalVector(VELOCITY, Step, rValues);
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::GetSecondDerivativesVector(Vector& rValues, int Step) const {
    FillNodalVector(ACCELERATION, Step, rValues);
}

// -- Mass and damping --

template <int TDim, int TNumNodes, int TStrainSize>
double BaseSolidElement<TDim, TNumNodes, TStrainSize>::MassFactor() const {
    if (Has(MASS_FACTOR)) return GetValue(MASS_FACTOR);
    const Properties& properties = GetProperties();
    return properties.Has(MASS_FACTOR) ? properties.GetValue(MASS_FACTOR) : 1.0;
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateMassMatrix(Matrix& rMassMatrix, const ProcessInfo&) {
    const Properties& properties = GetProperties();
    CONTACT_CHECK(properties.Has(DENSITY), InputError, Info(), ": properties ", properties.Id(), " have no DENSITY",
                  "\n  expected: DENSITY for the mass matrix (dynamic analyses)",
                  "\n  fix: add DENSITY to the material of properties ", properties.Id());
    const double density = properties.GetValue(DENSITY) * MassFactor();
    const bool lumped = properties.Has(COMPUTE_LUMPED_MASS_MATRIX) && properties.GetValue(COMPUTE_LUMPED_MASS_MATRIX);
    Eigen::Matrix<double, TNumNodes, TNumNodes> nodal_mass;
    if (lumped)
        nodal_mass = LumpedNodalMass().asDiagonal();
    else
        nodal_mass = ConsistentNodalMass();
    rMassMatrix.setZero(kDofs, kDofs);
    for (int i = 0; i < TNumNodes; ++i)
        for (int j = 0; j < TNumNodes; ++j)
            for (int a = 0; a < TDim; ++a) rMassMatrix(i * TDim + a, j * TDim + a) = density * nodal_mass(i, j);
}

template <int TDim, int TNumNodes, int TStrainSize>
Eigen::Matrix<double, TNumNodes, TNumNodes> BaseSolidElement<TDim, TNumNodes, TStrainSize>::ConsistentNodalMass()
    const {
    // ∫ N Nᵀ dV0 with the one-order-higher rule (Kratos GetIntegrationMethodForExactMassMatrixEvaluation).
    const Geometry& geometry = GetGeometry();
    const int order = std::min(geometry.DefaultIntegrationOrder() + 1, 5);
    const NodalMatrix X0 = NodalCoordinates(Geometry::Configuration::Initial);
    Eigen::Matrix<double, TNumNodes, TNumNodes> mass = Eigen::Matrix<double, TNumNodes, TNumNodes>::Zero();
    Vector N;
    Matrix DN;
    for (const IntegrationPoint& point : geometry.IntegrationPoints(order)) {
        geometry.ShapeFunctionsValues(N, point.local);
        geometry.ShapeFunctionsLocalGradients(DN, point.local);
        const ShapeVector n = N;
        const double det_j0 = (X0.transpose() * NodalMatrix(DN)).determinant();
        mass.noalias() += (point.weight * det_j0 * ReferenceVolumeFactor(n)) * (n * n.transpose());
    }
    return mass;
}

template <int TDim, int TNumNodes, int TStrainSize>
typename BaseSolidElement<TDim, TNumNodes, TStrainSize>::ShapeVector
BaseSolidElement<TDim, TNumNodes, TStrainSize>::LumpedNodalMass() const {
    // Row-sum lumping factors of the default rule times the current measure (docs/theory/structural.md §2).
    const Geometry& geometry = GetGeometry();
    const NodalMatrix x = NodalCoordinates(Geometry::Configuration::Current);
    ShapeVector row_sum = ShapeVector::Zero();
    double total = 0.0;
    Vector N;
    Matrix DN;
    for (const IntegrationPoint& point : geometry.IntegrationPoints(geometry.DefaultIntegrationOrder())) {
        geometry.ShapeFunctionsValues(N, point.local);
        geometry.ShapeFunctionsLocalGradients(DN, point.local);
        const ShapeVector n = N;
        double factor = point.weight * (x.transpose() * NodalMatrix(DN)).determinant();
        // docs/theory/structural.md §8 D2: Kratos leaves 2πr out of the axisymmetric lumped mass; the correct mass
        // includes it.
        if constexpr (kAxisymmetric) factor *= 2.0 * M_PI * n.dot(x.col(0));
        row_sum += factor * n;
        total += factor;
    }
    if constexpr (kAxisymmetric)
        return row_sum;
    else
        return row_sum * (geometry.DomainSize() * ThicknessFactor() / total);
}

template <int TDim, int TNumNodes, int TStrainSize>
double BaseSolidElement<TDim, TNumNodes, TStrainSize>::RayleighCoefficient(
    const Variable<double>& variable, const ProcessInfo& rCurrentProcessInfo) const {
    const Properties& properties = GetProperties();
    if (properties.Has(variable)) return properties.GetValue(variable);
    return rCurrentProcessInfo.Has(variable) ? rCurrentProcessInfo.GetValue(variable) : 0.0;
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateDampingMatrix(Matrix& rDampingMatrix,
                                                                            const ProcessInfo& rCurrentProcessInfo) {
    const double alpha = RayleighCoefficient(RAYLEIGH_ALPHA, rCurrentProcessInfo);
    const double beta = RayleighCoefficient(RAYLEIGH_BETA, rCurrentProcessInfo);
    rDampingMatrix.setZero(kDofs, kDofs);
    if (beta != 0.0) {
        Matrix stiffness;
        CalculateLeftHandSide(stiffness, rCurrentProcessInfo);
        rDampingMatrix += beta * stiffness;
    }
    if (alpha != 0.0) {
        Matrix mass;
        CalculateMassMatrix(mass, rCurrentProcessInfo);
        rDampingMatrix += alpha * mass;
    }
}

// -- Integration-point results --

template <int TDim, int TNumNodes, int TStrainSize>
template <class TVisit>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::ForEachPointResponse(StressMeasure measure,
                                                                          const ProcessInfo& rCurrentProcessInfo,
                                                                          TVisit&& visit) {
    CheckInitialized();
    ConstitutiveLaw::Parameters values = LawParameters(rCurrentProcessInfo);
    Kinematics kinematics;
    for (std::size_t g = 0; g < NumberOfIntegrationPoints(); ++g) {
        PointResponse(g, measure, rCurrentProcessInfo, kinematics, values);
        visit(g, kinematics, values);
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateOnIntegrationPoints(
    const Variable<double>& rVariable, std::vector<double>& rOutput, const ProcessInfo& rCurrentProcessInfo) {
    using Values = ConstitutiveLaw::Parameters;
    rOutput.resize(NumberOfIntegrationPoints());
    if (rVariable == VON_MISES_STRESS) {
        ForEachPointResponse(
            StressMeasure::Cauchy, rCurrentProcessInfo, [&](std::size_t g, const Kinematics&, Values& v) {
                rOutput[g] = VonMisesStress(VoigtToSymmetricTensor<Kinematics::kFSize>(StrainVector(v.stress_vector)));
            });
    } else if (rVariable == STRAIN_ENERGY) {
        ForEachPointResponse(GetStressMeasure(), rCurrentProcessInfo, [&](std::size_t g, const Kinematics&, Values& v) {
            rOutput[g] = mLaws[g]->CalculateValue(v, STRAIN_ENERGY);
        });
    } else {
        Element::CalculateOnIntegrationPoints(rVariable, rOutput, rCurrentProcessInfo);
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateOnIntegrationPoints(
    const Variable<Vector>& rVariable, std::vector<Vector>& rOutput, const ProcessInfo& rCurrentProcessInfo) {
    using Values = ConstitutiveLaw::Parameters;
    rOutput.resize(NumberOfIntegrationPoints());
    const auto store_stress = [&](std::size_t g, const Kinematics&, Values& v) { rOutput[g] = v.stress_vector; };
    if (rVariable == CAUCHY_STRESS_VECTOR) {
        ForEachPointResponse(StressMeasure::Cauchy, rCurrentProcessInfo, store_stress);
    } else if (rVariable == PK2_STRESS_VECTOR) {
        ForEachPointResponse(StressMeasure::PK2, rCurrentProcessInfo, store_stress);
    } else if (rVariable == GREEN_LAGRANGE_STRAIN_VECTOR) {
        CheckInitialized();
        Kinematics kinematics;
        for (std::size_t g = 0; g < NumberOfIntegrationPoints(); ++g) {
            ComputeKinematics(g, kinematics);
            rOutput[g] = kinematics.strain;
        }
    } else {
        Element::CalculateOnIntegrationPoints(rVariable, rOutput, rCurrentProcessInfo);
    }
}

template <int TDim, int TNumNodes, int TStrainSize>
void BaseSolidElement<TDim, TNumNodes, TStrainSize>::CalculateOnIntegrationPoints(
    const Variable<Matrix>& rVariable, std::vector<Matrix>& rOutput, const ProcessInfo& rCurrentProcessInfo) {
    using Values = ConstitutiveLaw::Parameters;
    rOutput.resize(NumberOfIntegrationPoints());
    const auto store_tensor = [&](std::size_t g, const Kinematics&, Values& v) {
        rOutput[g] = VoigtToSymmetricTensor<Kinematics::kFSize>(StrainVector(v.stress_vector));
    };
    if (rVariable == CAUCHY_STRESS_TENSOR) {
        ForEachPointResponse(StressMeasure::Cauchy, rCurrentProcessInfo, store_tensor);
    } else if (rVariable == PK2_STRESS_TENSOR) {
        ForEachPointResponse(StressMeasure::PK2, rCurrentProcessInfo, store_tensor);
    } else if (rVariable == DEFORMATION_GRADIENT) {
        CheckInitialized();
        Kinematics kinematics;
        for (std::size_t g = 0; g < NumberOfIntegrationPoints(); ++g) {
            ComputeKinematics(g, kinematics);
            rOutput[g] = kinematics.F;
        }
    } else {
        Element::CalculateOnIntegrationPoints(rVariable, rOutput, rCurrentProcessInfo);
    }
}

#define CONTACT_APP_BASE_SOLID_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>>;
#define CONTACT_APP_BASE_AXISYM_INSTANTIATE(TDim, TNumNodes, Geometry, Suffix) \
    template class BaseSolidElement<TDim, TNumNodes, 4>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_BASE_SOLID_INSTANTIATE)
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_BASE_AXISYM_INSTANTIATE)

}  // namespace contact_app
