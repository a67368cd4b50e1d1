// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/kernel/model_part.h"

namespace contact_app {

/// Owner of the root model parts, addressed by name or dotted path (Kratos Model).
class Model {
public:
    Model() = default;
    Model(const Model&) = delete;
    Model& operator=(const Model&) = delete;

    /// Creates a root model part; a dotted name "A.B" creates B below A (and A if missing).
    /// @throws InputError if the model part exists.
    ModelPart& CreateModelPart(const std::string& name, std::size_t buffer_size = 1);
    /// @param name root name or dotted path ("Structure.Contact_Part").
    /// @throws InputError listing the existing model parts, with a suggestion.
    ModelPart& GetModelPart(const std::string& name);
    bool HasModelPart(const std::string& name) const;
    void DeleteModelPart(const std::string& name);
    /// Names of the root model parts, sorted.
    std::vector<std::string> GetModelPartNames() const;

private:
    std::map<std::string, std::unique_ptr<ModelPart>> mRoots;
};

}  // namespace contact_app
