// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

/// The memory the system can give this process now without swapping (MemAvailable of /proc/meminfo), in bytes;
/// negative where it cannot be read (not Linux). The direct solvers compare their factors' expected size with it to
/// decide whether to keep them out of core (docs/architecture.md, "Solving layer").
double AvailableMemoryBytes();

}  // namespace contact_app
