// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/entity.h"

namespace contact_app {

class Element;
extern template class Entity<Element>;

/// A domain element (Kratos Element). The base class is a geometry-only "mesh element"
/// (registered as Element2D3N, Element3D8N, ...); structural elements derive from it.
class Element : public Entity<Element> {
public:
    using Entity<Element>::Entity;

    /// Why the tangent stiffness may change with the displacement, "" if it cannot while the properties stay (the
    /// static condensation factorises such a bulk once: docs/theory/static_condensation.md). The reason completes
    /// "element <id> ...", e.g. "is a TotalLagrangianElement, whose stiffness follows the displacement".
    virtual std::string WhyStiffnessVaries() const;
};

}  // namespace contact_app
