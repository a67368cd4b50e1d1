// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/element.h"
#include "contact_app/structural/elements/solid_element_sizes.h"
#include "contact_app/structural/elements/solid_kinematics.h"

namespace contact_app {

/// Strain size of the plane (3) and 3D (6) solid elements.
template <int TDim>
inline constexpr int kSolidStrainSize = TDim == 2 ? 3 : 6;

/// Common part of the solid elements (Kratos BaseSolidElement). Per integration point g, with stress s of the
/// formulation's measure and tangent D = ∂s/∂strain from one law clone per point:
///   RHS = Σ_g w_g (Nᵀ b − Bᵀ s),   LHS = Σ_g w_g (Bᵀ D B + K_g[s]),   b = ρ (g_prop + Σ_k N_k g_k),
/// plus consistent/lumped mass, Rayleigh damping, DoFs, integration-point results and Check(). The formulations
/// (SmallDisplacementElement, TotalLagrangianElement, UpdatedLagrangianElement and the axisymmetric ones)
/// supply ComputeKinematics(). Conventions (docs/theory/structural.md §1–2): DoFs node by node x, y(, z);
/// RHS = f_ext − f_int; LHS = −∂RHS/∂u; current coordinates = X + u (the solver moves the mesh).
/// Theory and the differences from Kratos: docs/theory/solid_elements.md.
/// @tparam TStrainSize 3 (plane), 4 (axisymmetric, TDim = 2) or 6 (3D). Instantiated for the rows of
/// solid_element_sizes.h only.
template <int TDim, int TNumNodes, int TStrainSize>
class BaseSolidElement : public Element {
public:
    using Kinematics = SolidKinematics<TDim, TNumNodes, TStrainSize>;
    using StressMeasure = ConstitutiveLaw::StressMeasure;
    using ShapeVector = Eigen::Matrix<double, TNumNodes, 1>;
    using NodalMatrix = Eigen::Matrix<double, TNumNodes, TDim>;  ///< one row per node
    using FMatrix = typename Kinematics::FMatrix;
    using StrainVector = typename Kinematics::StrainVector;
    static constexpr int kDofs = TDim * TNumNodes;
    static constexpr bool kAxisymmetric = TStrainSize == 4;

    /// @param[in] id element Id
    /// @param[in] geometry TNumNodes nodes, working and local dimension TDim (shared with the model part)
    /// @param[in] properties shared; may be null until the materials are assigned
    /// @throws InputError if the geometry does not fit the element
    BaseSolidElement(IndexType id, Geometry::Pointer geometry, Properties::Pointer properties = nullptr);

    using Element::CalculateOnIntegrationPoints;
    using Element::Create;

    /// @brief Selects the rule (Properties INTEGRATION_ORDER 1..5, else the geometry default), caches the
    ///        reference shape-function data and clones the law once per integration point.
    /// @throws InputError for a missing or incompatible law, a bad INTEGRATION_ORDER or an inverted element
    void Initialize(const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Calls InitializeMaterialResponse of every law clone.
    void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Calls FinalizeMaterialResponse of every law clone.
    void FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo) override;

    /// @param[out] rLeftHandSideMatrix kDofs × kDofs tangent −∂RHS/∂u, resized here
    /// @param[out] rRightHandSideVector kDofs, f_ext − f_int, resized here
    /// @param[in] rCurrentProcessInfo handed to the constitutive law; its TIME goes into error messages
    /// @throws InputError if the element was not initialized
    void CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                              const ProcessInfo& rCurrentProcessInfo) override;
    /// @param[out] rLeftHandSideMatrix kDofs × kDofs tangent, resized here
    /// @param[in] rCurrentProcessInfo handed to the constitutive law; its TIME goes into error messages
    void CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    /// @param[out] rRightHandSideVector kDofs residual f_ext − f_int, resized here
    /// @param[in] rCurrentProcessInfo handed to the constitutive law; its TIME goes into error messages
    void CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Consistent mass (one-order-higher rule, initial configuration) or, if Properties
    ///        COMPUTE_LUMPED_MASS_MATRIX is true, row-sum lumped mass; ρ = DENSITY × MASS_FACTOR (element value
    ///        first, then Properties; 1 if absent).
    /// @param[out] rMassMatrix kDofs × kDofs, resized here
    /// @param[in] rCurrentProcessInfo not read (the Kratos signature)
    /// @throws InputError if the properties have no DENSITY
    void CalculateMassMatrix(Matrix& rMassMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief Rayleigh damping C = α M + β K_t, α/β from Properties RAYLEIGH_ALPHA/BETA, else the ProcessInfo,
    ///        else 0 (a zero coefficient skips its term).
    /// @param[out] rDampingMatrix kDofs × kDofs, resized here
    /// @param[in] rCurrentProcessInfo RAYLEIGH_ALPHA/BETA when the properties have none; handed on to the tangent
    void CalculateDampingMatrix(Matrix& rDampingMatrix, const ProcessInfo& rCurrentProcessInfo) override;
    /// @param[out] rResult equation ids of DISPLACEMENT_X, _Y(, _Z) node by node
    /// @param[in] rCurrentProcessInfo not read (the Kratos signature)
    /// @throws InputError naming the node if a DoF is missing
    void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo& rCurrentProcessInfo) const override;
    /// @param[out] rElementalDofList DISPLACEMENT_X, _Y(, _Z) DoFs node by node (owned by the nodes)
    /// @param[in] rCurrentProcessInfo not read (the Kratos signature)
    void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const override;
    /// @param[out] rValues DISPLACEMENT at buffer step @p Step, kDofs, in DoF order
    /// @param[in] Step buffer step: 0 the current solution step, 1 the previous one
    void GetValuesVector(Vector& rValues, int Step = 0) const override;
    /// @param[out] rValues VELOCITY at buffer step @p Step, kDofs, in DoF order
    /// @param[in] Step buffer step: 0 the current solution step, 1 the previous one
    void GetFirstDerivativesVector(Vector& rValues, int Step = 0) const override;
    /// @param[out] rValues ACCELERATION at buffer step @p Step, kDofs, in DoF order
    /// @param[in] Step buffer step: 0 the current solution step, 1 the previous one
    void GetSecondDerivativesVector(Vector& rValues, int Step = 0) const override;

    /// @brief VON_MISES_STRESS (of the Cauchy stress; plane elements take σ_zz = 0) or STRAIN_ENERGY (density
    ///        per unit reference volume, from the law).
    /// @param[in] rVariable the result asked for, one of those above
    /// @param[out] rOutput one value per integration point
    /// @param[in] rCurrentProcessInfo handed to the constitutive law; its TIME goes into error messages
    /// @throws InputError for other variables
    void CalculateOnIntegrationPoints(const Variable<double>& rVariable, std::vector<double>& rOutput,
                                      const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief CAUCHY_STRESS_VECTOR, PK2_STRESS_VECTOR or GREEN_LAGRANGE_STRAIN_VECTOR (small strain for the
    ///        small-displacement elements), Voigt of size TStrainSize.
    /// @param[in] rVariable the result asked for, one of those above
    /// @param[out] rOutput one vector per integration point
    /// @param[in] rCurrentProcessInfo handed to the constitutive law; its TIME goes into error messages
    /// @throws InputError for other variables
    void CalculateOnIntegrationPoints(const Variable<Vector>& rVariable, std::vector<Vector>& rOutput,
                                      const ProcessInfo& rCurrentProcessInfo) override;
    /// @brief CAUCHY_STRESS_TENSOR, PK2_STRESS_TENSOR (2×2 plane, 3×3 axisymmetric and 3D) or
    ///        DEFORMATION_GRADIENT (the F handed to the law; I + ε for small displacements).
    /// @param[in] rVariable the result asked for, one of those above
    /// @param[out] rOutput one matrix per integration point
    /// @param[in] rCurrentProcessInfo handed to the constitutive law; its TIME goes into error messages
    /// @throws InputError for other variables
    void CalculateOnIntegrationPoints(const Variable<Matrix>& rVariable, std::vector<Matrix>& rOutput,
                                      const ProcessInfo& rCurrentProcessInfo) override;

    /// @brief Checks properties, law (dimension, strain size, its own Check), INTEGRATION_ORDER, nodal
    ///        DISPLACEMENT and its DoFs, and det J > 0 (and R > 0 in axisymmetry) at every integration point.
    /// @return 0; @throws InputError naming the element, the item and the fix
    int Check(const ProcessInfo& rCurrentProcessInfo) const override;
    /// @brief e.g. "TotalLagrangianElement2D4N #3 (Quadrilateral2D4)".
    std::string Info() const override;
    /// @brief "" for kinematics on the initial configuration with a linear law (IsLinear); then the element keeps
    ///        its stiffness from its first evaluation in a solution step to the next InitializeSolutionStep.
    std::string WhyStiffnessVaries() const override;

    // What a formulation's kinematics read (ComputeSolidKinematics, solid_element.h).
    /// @brief The reference data of integration point @p point (0 ≤ point < its count).
    const auto& GetReferencePoint(std::size_t point) const { return mReferencePoints[point]; }
    /// @brief Node coordinates, one row per node (first TDim components).
    NodalMatrix NodalCoordinates(Geometry::Configuration configuration) const;
    /// @brief Nodal DISPLACEMENT at buffer step @p step, one row per node.
    NodalMatrix NodalDisplacements(std::size_t step) const;
    /// @brief THICKNESS in 2D (1 if absent), 1 in 3D.
    double ThicknessFactor() const;

protected:
    /// Reference data of one integration point of the stiffness rule, cached by Initialize().
    struct ReferencePoint {
        ShapeVector N;
        NodalMatrix DN_De;   ///< ∂N/∂ξ
        NodalMatrix DN_DX0;  ///< ∂N/∂X, initial configuration
        double weight;       ///< Gauss weight w_g
        double detJ0;        ///< det ∂X/∂ξ
    };

    /// Registered family name without the size suffix, e.g. "SmallDisplacementElement".
    virtual const char* FamilyName() const = 0;
    /// Stress measure of the residual: PK2, or Cauchy for the updated-Lagrangian element.
    virtual StressMeasure GetStressMeasure() const = 0;
    /// True if the element computes the strain handed to the law (USE_ELEMENT_PROVIDED_STRAIN).
    virtual bool UseElementProvidedStrain() const = 0;
    /// True for the finite-strain formulations (adds the geometric stiffness K_g).
    virtual bool UsesGeometricStiffness() const = 0;
    /// True if B and the weights depend on the initial configuration only (the small-displacement formulations).
    virtual bool HasConstantKinematics() const = 0;
    /// @brief Kinematics at integration point @p point from the current nodal state.
    /// @param[in] point index of the integration point, 0 ≤ point < NumberOfIntegrationPoints()
    /// @param[out] rKinematics every field, including weight and body_weight
    virtual void ComputeKinematics(std::size_t point, Kinematics& rKinematics) const = 0;

    std::size_t NumberOfIntegrationPoints() const { return mReferencePoints.size(); }
    /// @brief Reference-volume factor per unit reference measure: 2πR (axisymmetric, R = Σ N_k X_k) or
    ///        ThicknessFactor().
    double ReferenceVolumeFactor(const ShapeVector& N) const;
    /// @brief Throws for det J ≤ 0: InputError in the initial configuration, InvertedElementError (a
    ///        ConvergenceError: the iterate, not the input, is wrong) in the current one.
    [[noreturn]] void ThrowInverted(std::size_t point, double det_j, bool current_configuration) const;

private:
    /// Body-force data of one evaluation: ρ, Properties VOLUME_ACCELERATION, nodal VOLUME_ACCELERATION.
    struct BodyForce {
        double density = 0.0;
        Eigen::Matrix<double, 1, TDim> constant;
        NodalMatrix nodal;
    };

    void CalculateAll(Matrix* pLeftHandSide, Vector* pRightHandSide, const ProcessInfo& rCurrentProcessInfo);
    /// LHS = K and RHS = f_body − K u from the kept K (computed here on the first call of the step): the local
    /// system of constant kinematics with linear laws, without a law evaluation (docs/theory/solid_elements.md).
    void CalculateFromKeptStiffness(Matrix* pLeftHandSide, Vector* pRightHandSide,
                                    const ProcessInfo& rCurrentProcessInfo);
    void EvaluateLaw(std::size_t point, const Kinematics& rKinematics, StressMeasure measure,
                     ConstitutiveLaw::Parameters& rValues) const;
    /// Kinematics and law response at @p point; an InvertedElementError leaves with this element's id and TIME.
    void PointResponse(std::size_t point, StressMeasure measure, const ProcessInfo& rCurrentProcessInfo,
                       Kinematics& rKinematics, ConstitutiveLaw::Parameters& rValues) const;
    ConstitutiveLaw::Parameters LawParameters(const ProcessInfo& rCurrentProcessInfo) const;
    /// Stress tensors per point in @p measure, with the kinematics (for results).
    template <class TVisit>
    void ForEachPointResponse(StressMeasure measure, const ProcessInfo& rCurrentProcessInfo, TVisit&& visit);
    BodyForce ComputeBodyForce() const;
    /// RHS += Σ_i body_weight N_i b at one integration point (nothing when ρ = 0).
    static void AddBodyForce(const BodyForce& body, const Kinematics& rKinematics,
                             Eigen::Matrix<double, kDofs, 1>& rRightHandSide);
    static void AddGeometricStiffness(const Kinematics& rKinematics, const StrainVector& stress,
                                      Eigen::Matrix<double, kDofs, kDofs>& rLeftHandSide);
    Eigen::Matrix<double, TNumNodes, TNumNodes> ConsistentNodalMass() const;
    ShapeVector LumpedNodalMass() const;
    double MassFactor() const;
    double RayleighCoefficient(const Variable<double>& variable, const ProcessInfo& rCurrentProcessInfo) const;
    void FillNodalVector(const Variable<Array3>& variable, int step, Vector& rValues) const;
    /// The Properties law, checked against TDim and TStrainSize. @throws InputError
    ConstitutiveLaw::Pointer CheckedLaw() const;
    /// Properties INTEGRATION_ORDER or the geometry default. @throws InputError if outside 1..5
    int IntegrationOrder() const;
    /// det J0 > 0 (and R > 0 in axisymmetry) at the integration points. @throws InputError
    void CheckReferenceConfiguration() const;
    void CheckInitialized() const;

    std::vector<ReferencePoint> mReferencePoints;
    std::vector<ConstitutiveLaw::Pointer> mLaws;  ///< one clone per integration point, owned
    bool mKeepsStiffness = false;  ///< constant kinematics and linear laws (set by Initialize)
    /// The kept stiffness, upper triangle packed column by column (kDofs(kDofs + 1)/2 values; 2D Q4: 288 B, 3D
    /// hexahedron: 2.4 kB); empty until the first evaluation of a step, emptied by InitializeSolutionStep.
    std::vector<double> mKeptStiffness;
};

#define CONTACT_APP_BASE_SOLID_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class BaseSolidElement<TDim, TNumNodes, kSolidStrainSize<TDim>>;
#define CONTACT_APP_BASE_AXISYM_EXTERN(TDim, TNumNodes, Geometry, Suffix) \
    extern template class BaseSolidElement<TDim, TNumNodes, 4>;
CONTACT_APP_SOLID_ELEMENT_SIZES(CONTACT_APP_BASE_SOLID_EXTERN)
CONTACT_APP_AXISYM_SOLID_ELEMENT_SIZES(CONTACT_APP_BASE_AXISYM_EXTERN)
#undef CONTACT_APP_BASE_SOLID_EXTERN
#undef CONTACT_APP_BASE_AXISYM_EXTERN

}  // namespace contact_app
