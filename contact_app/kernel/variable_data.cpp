// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/variable_data.h"

#include "contact_app/kernel/variable_registry.h"

namespace contact_app {

const char* VariableTypeName(VariableType type) {
    switch (type) {
        case VariableType::Bool: return "Bool";
        case VariableType::Integer: return "Integer";
        case VariableType::Double: return "Double";
        case VariableType::Array: return "Array";
        case VariableType::Vector: return "Vector";
        case VariableType::Matrix: return "Matrix";
        case VariableType::String: return "String";
        case VariableType::Component: return "Component";
        case VariableType::Pointer: return "Pointer";
    }
    return "Unknown";
}

VariableData::VariableData(std::string name, VariableType type, const VariableData* source, int component)
    : mName(std::move(name)), mKey(0), mType(type), mSource(source), mComponent(component) {
    mKey = VariableRegistry::Instance().Add(*this);
}

std::size_t VariableData::HistoricalSize() const {
    switch (mType) {
        case VariableType::Double: return 1;
        case VariableType::Array: return 3;
        default: return 0;
    }
}

}  // namespace contact_app
