// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/model.h"

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/string_utilities.h"

namespace contact_app {

ModelPart& Model::CreateModelPart(const std::string& name, std::size_t buffer_size) {
    const auto dot = name.find('.');
    const std::string root_name = name.substr(0, dot);
    if (dot != std::string::npos) {
        ModelPart& root = HasModelPart(root_name) ? GetModelPart(root_name) : CreateModelPart(root_name, buffer_size);
        ModelPart* parent = &root;
        std::string rest = name.substr(dot + 1);
        while (true) {
            const auto next = rest.find('.');
            const std::string head = rest.substr(0, next);
            if (next == std::string::npos) return parent->CreateSubModelPart(head);
            parent = parent->HasSubModelPart(head) ? &parent->GetSubModelPart(head) : &parent->CreateSubModelPart(head);
            rest = rest.substr(next + 1);
        }
    }
    CONTACT_CHECK(mRoots.count(name) == 0, InputError, "the model already has a model part \"", name, "\"",
                  "\n  fix: use GetModelPart(\"", name, "\") to reach it");
    auto part = std::make_unique<ModelPart>(name, buffer_size, this);
    ModelPart& created = *part;
    mRoots.emplace(name, std::move(part));
    return created;
}

ModelPart& Model::GetModelPart(const std::string& name) {
    const auto dot = name.find('.');
    const std::string root_name = name.substr(0, dot);
    const auto found = mRoots.find(root_name);
    if (found == mRoots.end()) {
        const auto names = GetModelPartNames();
        std::string listing;
        for (const auto& existing : names) listing += (listing.empty() ? "" : ", ") + existing;
        CONTACT_THROW(InputError, "the model has no model part \"", root_name, "\"", DidYouMean(root_name, names),
                      "\n  existing: ", listing.empty() ? std::string("none") : listing);
    }
    if (dot == std::string::npos) return *found->second;
    return found->second->GetSubModelPart(name.substr(dot + 1));
}

bool Model::HasModelPart(const std::string& name) const {
    const auto dot = name.find('.');
    const auto found = mRoots.find(name.substr(0, dot));
    if (found == mRoots.end()) return false;
    return dot == std::string::npos || found->second->HasSubModelPart(name.substr(dot + 1));
}

void Model::DeleteModelPart(const std::string& name) {
    const auto dot = name.find('.');
    if (dot == std::string::npos) {
        CONTACT_CHECK(mRoots.erase(name) == 1, InputError, "the model has no model part \"", name, "\" to delete");
        return;
    }
    const auto last = name.rfind('.');
    GetModelPart(name.substr(0, last)).RemoveSubModelPart(name.substr(last + 1));
}

std::vector<std::string> Model::GetModelPartNames() const {
    std::vector<std::string> names;
    for (const auto& entry : mRoots) names.push_back(entry.first);
    return names;
}

}  // namespace contact_app
