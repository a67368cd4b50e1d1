// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>

#include "contact_app/kernel/data_value_holder.h"
#include "contact_app/kernel/flags.h"

namespace contact_app {

/// Global values of an analysis (Kratos ProcessInfo): TIME, DELTA_TIME, STEP, solver switches.
/// One instance per root model part, shared by its sub model parts.
class ProcessInfo : public Flags, public DataValueHolder {
public:
    using Pointer = std::shared_ptr<ProcessInfo>;
};

}  // namespace contact_app
