// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/variables_list.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/variable_registry.h"

namespace contact_app {

void VariablesList::Add(const VariableData& variable) {
    const VariableData& stored = variable.IsComponent() ? *variable.SourceVariable() : variable;
    if (Has(stored)) return;
    const std::size_t size = stored.HistoricalSize();
    CONTACT_CHECK(size > 0, InputError, "variable ", stored.Name(), " of type ",
                  VariableTypeName(stored.Type()), " cannot be a solution-step (historical) variable",
                  "\n  expected: a Double or Array (3-vector) variable",
                  "\n  fix:      store it as a non-historical value with SetValue/GetValue");
    const std::size_t registry_size = VariableRegistry::Instance().Size();
    if (mOffsets.size() < registry_size) mOffsets.resize(registry_size, -1);
    mOffsets[stored.Key()] = static_cast<long>(mDataSize);
    // The components of a 3-vector share its storage.
    const auto& registry = VariableRegistry::Instance();
    for (std::size_t key = 0; key < registry.Size(); ++key) {
        const VariableData& candidate = registry.ByKey(key);
        if (candidate.SourceVariable() == &stored)
            mOffsets[key] = static_cast<long>(mDataSize) + candidate.ComponentIndex();
    }
    mVariables.push_back(&stored);
    mDataSize += size;
}

bool VariablesList::Has(const VariableData& variable) const {
    const std::size_t key = variable.Key();
    return key < mOffsets.size() && mOffsets[key] >= 0;
}

std::size_t VariablesList::MissingOffset(const VariableData& variable) const {
    const VariableData& stored = variable.IsComponent() ? *variable.SourceVariable() : variable;
    CONTACT_THROW(InputError, "variable ", variable.Name(), " is not a solution-step variable of this model part",
                  "\n  fix: call AddNodalSolutionStepVariable(", stored.Name(),
                  ") on the root model part (before reading the mesh), or use the non-historical GetValue/SetValue");
}

}  // namespace contact_app
