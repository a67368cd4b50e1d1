// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

/// Registers the structural layer: constitutive laws, solid elements and load conditions
/// (Kratos StructuralMechanicsApplication names). Idempotent.
void RegisterStructuralMechanics();

/// Registers the constitutive laws (structural/constitutive/constitutive_law_registration.cpp).
void RegisterConstitutiveLaws();

/// Registers the solid elements SmallDisplacementElement, TotalLagrangianElement, UpdatedLagrangianElement
/// {2D3N,2D4N,2D6N,3D4N,3D8N,3D10N}, AxisymSmallDisplacementElement and AxisymTotalLagrangianElement {2D3N,2D4N}
/// (aliases SmallDisplacementAxisymElement…, TotalLagrangianAxisymElement…)
/// (structural/elements/element_registration.cpp). Idempotent.
void RegisterSolidElements();

/// Registers the load conditions PointLoadCondition2D1N/3D1N, LineLoadCondition2D2N,
/// AxisymLineLoadCondition2D2N, SurfaceLoadCondition3D3N/4N
/// (structural/conditions/condition_registration.cpp). Idempotent.
void RegisterLoadConditions();

}  // namespace contact_app
