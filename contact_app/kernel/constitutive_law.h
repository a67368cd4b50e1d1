// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

namespace contact_app {

class Geometry;
class Properties;
class ProcessInfo;

/// Base of the constitutive laws (Kratos ConstitutiveLaw). The kernel only needs a clonable,
/// registrable object stored in Properties[CONSTITUTIVE_LAW]; the stress-update interface is
/// added by the structural layer.
class ConstitutiveLaw {
public:
    using Pointer = std::shared_ptr<ConstitutiveLaw>;

    virtual ~ConstitutiveLaw() = default;
    /// An independent copy (one per integration point).
    virtual Pointer Clone() const = 0;
    /// 2 or 3.
    virtual int WorkingSpaceDimension() const = 0;
    /// Number of Voigt strain components (3 plane, 4 axisymmetric, 6 in 3D).
    virtual int GetStrainSize() const = 0;
    /// Verifies the properties the law needs. @throws InputError naming the missing value.
    virtual int Check(const Properties& rMaterialProperties, const Geometry& rElementGeometry,
                      const ProcessInfo& rCurrentProcessInfo) const;
    virtual std::string Info() const { return "ConstitutiveLaw"; }
};

}  // namespace contact_app
