// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include "contact_app/kernel/entity.h"

namespace contact_app {

class Condition;
extern template class Entity<Condition>;

/// A boundary or interface condition (Kratos Condition). The base class is a geometry-only
/// "mesh condition" (LineCondition2D2N, SurfaceCondition3D3N, ...); load and contact
/// conditions derive from it.
class Condition : public Entity<Condition> {
public:
    using Entity<Condition>::Entity;
};

}  // namespace contact_app
