// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "contact_app/kernel/types.h"
#include "contact_app/kernel/variable_data.h"

namespace contact_app {

class Geometry;
class Properties;
class ProcessInfo;

/// Base of the constitutive laws (Kratos ConstitutiveLaw): given the kinematics of an integration
/// point, returns a stress vector and its tangent in Voigt notation.
///
/// Voigt orders (engineering shear strains γ = 2ε, plain shear stresses):
/// plane [xx, yy, xy] (size 3), axisymmetric [rr, zz, θθ, rz] (size 4),
/// 3D [xx, yy, zz, xy, yz, xz] (size 6). See docs/theory/structural.md §1, §4.
class ConstitutiveLaw {
public:
    using Pointer = std::shared_ptr<ConstitutiveLaw>;

    enum class StressMeasure { PK1, PK2, Kirchhoff, Cauchy };

    /// Inputs and outputs of one material evaluation (Kratos ConstitutiveLaw::Parameters).
    struct Parameters {
        /// If true, StrainVector is an input (small-displacement elements); otherwise the law
        /// computes the strain measure matching the requested stress from F and writes it here.
        bool use_element_provided_strain = false;
        bool compute_stress = true;
        bool compute_constitutive_tensor = true;
        /// Deformation gradient, dim × dim (2×2 for plane and axisymmetric laws use the in-plane block;
        /// axisymmetric laws may receive 3×3 with F(2,2) = hoop stretch).
        Matrix deformation_gradient = Matrix::Identity(3, 3);
        double determinant_f = 1.0;
        Vector strain_vector;        ///< [in or out] Voigt strain (size GetStrainSize())
        Vector stress_vector;        ///< [out] Voigt stress
        Matrix constitutive_matrix;  ///< [out] Voigt tangent dS/dE (or the spatial tangent for Cauchy/Kirchhoff)
        const Properties* material_properties = nullptr;  ///< not owned; required
        const Geometry* element_geometry = nullptr;       ///< not owned; may be null
        const ProcessInfo* process_info = nullptr;        ///< not owned; may be null
    };

    virtual ~ConstitutiveLaw() = default;
    /// An independent copy (one per integration point).
    virtual Pointer Clone() const = 0;
    /// 2 or 3.
    virtual int WorkingSpaceDimension() const = 0;
    /// Number of Voigt strain components (3 plane, 4 axisymmetric, 6 in 3D).
    virtual int GetStrainSize() const = 0;
    /// Computes the stress (and tangent, if requested) in @p measure. @throws InputError for
    /// missing properties or an inverted deformation (det F ≤ 0) where the law needs it positive.
    virtual void CalculateMaterialResponse(Parameters& rValues, StressMeasure measure) = 0;
    /// Scalar results such as STRAIN_ENERGY; the base returns 0 and sets nothing.
    virtual double CalculateValue(Parameters& rValues, const Variable<double>& rThisVariable);
    /// Called once per integration point at element initialisation / per step (elastic laws: no-ops).
    virtual void InitializeMaterial(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
                                    const Vector& rShapeFunctionsValues);
    virtual void InitializeMaterialResponse(Parameters& rValues, StressMeasure measure);
    virtual void FinalizeMaterialResponse(Parameters& rValues, StressMeasure measure);
    /// Verifies the properties the law needs. @throws InputError naming the missing or bad value.
    virtual int Check(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
                      const ProcessInfo& rCurrentProcessInfo) const;
    virtual std::string Info() const { return "ConstitutiveLaw"; }
    /// True if the stress is D ε with D fixed by the properties and the law keeps no state: an element on constant
    /// kinematics may then keep its stiffness within a solution step (docs/theory/solid_elements.md).
    virtual bool IsLinear() const { return false; }
};

}  // namespace contact_app
