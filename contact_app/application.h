// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

/// Registers everything the package adds to the kernel's registries, in one place: the kernel's variables and
/// entities, the structural laws, elements and loads, the contact variables, the contact conditions, the contact
/// master-slave constraint and the restart codecs of the contact state. Idempotent; called when
/// `contact_app._core` loads.
void RegisterContactApplication();

}  // namespace contact_app
