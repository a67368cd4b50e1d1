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
};

}  // namespace contact_app
