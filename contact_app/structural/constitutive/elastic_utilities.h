// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact_app/kernel/constitutive_law.h"
#include "contact_app/kernel/types.h"

namespace contact_app {

class Properties;

namespace detail {

/// Kinematic model of an elastic law: selects the Voigt layout and the linear-elastic D.
enum class ElasticModel { ThreeDimensional, PlaneStrain, PlaneStress, Axisymmetric };

/// Voigt component → tensor index pair (i, j), i ≤ j, in the orders of docs/theory/structural.md §1:
/// 3D [xx, yy, zz, xy, yz, xz]; plane [xx, yy, xy]; axisymmetric [rr, zz, θθ, rz].
using VoigtPair = std::array<int, 2>;

/// E, ν and the Lamé constants λ = Eν/((1+ν)(1−2ν)), μ = E/(2(1+ν)) (3D values in every model).
struct ElasticConstants {
    double young;
    double poisson;
    double lambda;
    double mu;
};

/// @brief Voigt strain size: 6 (3D), 3 (plane strain/stress), 4 (axisymmetric).
int StrainSize(ElasticModel model);
/// @brief Dimension of the strain tensor the model works with: 2 (plane), 3 (3D, axisymmetric).
int TensorDimension(ElasticModel model);
/// @brief The Voigt index pairs for @p strain_size ∈ {3, 4, 6}. @throws InternalError for other sizes.
const std::vector<VoigtPair>& VoigtPairs(int strain_size);

/// @brief E, ν and Lamé constants from the law's properties.
/// @param[in] values must carry material_properties; @param[in] law_name for the messages
/// @throws InputError if YOUNG_MODULUS or POISSON_RATIO is missing; InternalError without properties
ElasticConstants ReadElasticConstants(const ConstitutiveLaw::Parameters& values, const std::string& law_name);
/// @brief Shared Check of the elastic laws: YOUNG_MODULUS present and > 0, POISSON_RATIO present and
///        within [−0.999, 0.499] (docs/theory/structural.md §4), DENSITY ≥ 0 if present.
/// @throws InputError naming the law, the property id, the variable and the fix
void CheckElasticProperties(const Properties& properties, const std::string& law_name);

/// @brief Isotropic linear-elastic D (strain_size²) of the model, docs/theory/structural.md §4 (engineering shear).
Matrix LinearElasticMatrix(ElasticModel model, double young, double poisson);

/// @brief Symmetric strain tensor → Voigt vector, shear components doubled (γ = 2ε).
/// @param[in] tensor d×d with d ≥ max index of the pairs; @param[in] strain_size 3, 4 or 6
Vector StrainTensorToVector(const Matrix& tensor, int strain_size);
/// @brief Symmetric stress tensor → Voigt vector, shear components as they are.
Vector StressTensorToVector(const Matrix& tensor, int strain_size);
/// @brief Voigt strain → symmetric tensor (halves the shear). Size 3 → 2×2, 4 and 6 → 3×3.
Matrix StrainVectorToTensor(const Vector& voigt);
/// @brief Voigt stress → symmetric tensor. Size 3 → 2×2, 4 and 6 → 3×3.
Matrix StressVectorToTensor(const Vector& voigt);

/// @brief The deformation gradient of @p values as a @p dim × @p dim matrix: the in-plane block of a
///        larger F, or a 2×2 F padded with F₃₃ = 1 when @p allow_padding (axisymmetric without hoop data).
/// @throws InputError if F is smaller than needed and cannot be padded, or not square
Matrix DeformationGradient(const ConstitutiveLaw::Parameters& values, int dim, bool allow_padding,
                           const std::string& law_name);
/// @brief Green–Lagrange strain E = ½(FᵀF − I) in Voigt form (engineering shear).
Vector GreenLagrangeStrainVector(const Matrix& F, int strain_size);
/// @brief Almansi strain e = ½(I − (FFᵀ)⁻¹) in Voigt form (engineering shear).
Vector AlmansiStrainVector(const Matrix& F, int strain_size);

/// @brief Voigt matrix Q with (F S Fᵀ)_a = Σ_A Q(a, A) S_A for symmetric S (stress-like Voigt vectors).
///        The push-forward of a material tangent is then c = Q D Qᵀ.
Matrix PushForwardMatrix(const Matrix& F, int strain_size);

/// @brief Voigt matrix D(a, b) = ℂ_{i j k l} with (i, j), (k, l) the pairs of a and b (consistent with
///        engineering shear strains). @p tangent is callable as tangent(i, j, k, l).
template <class TTangent>
Matrix VoigtTangent(int strain_size, const TTangent& tangent) {
    const auto& pairs = VoigtPairs(strain_size);
    Matrix result(strain_size, strain_size);
    for (int a = 0; a < strain_size; ++a)
        for (int b = 0; b < strain_size; ++b) result(a, b) = tangent(pairs[a][0], pairs[a][1], pairs[b][0], pairs[b][1]);
    return result;
}

/// @brief The Green–Lagrange strain the law works with: the element's strain_vector when
///        use_element_provided_strain (size-checked), else E(F) of the model's tensor dimension.
/// @throws InputError for a wrong strain size or an unusable F
Vector MaterialStrain(const ConstitutiveLaw::Parameters& values, ElasticModel model, const std::string& law_name);

/// @brief Checks an element-provided strain vector has the law's size.
/// @throws InputError naming the law, the sizes and the fix
void CheckStrainVectorSize(const Vector& strain, int strain_size, const std::string& law_name);
/// @brief Checks det F > 0 (needed by ln J and by the /J of Cauchy measures).
/// @throws InvertedElementError naming the law, the value and, if known, the element nodes
void CheckPositiveDeterminant(const ConstitutiveLaw::Parameters& values, const std::string& law_name);
/// @brief Rejects StressMeasure::PK1 for finite-strain laws (P is unsymmetric and has no Voigt form here).
/// @throws ConfigurationError naming the law and the measures it supports
void ThrowUnsupportedPK1(const std::string& law_name);

}  // namespace detail
}  // namespace contact_app
