// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/node.h"

#include <algorithm>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

Node::Node(IndexType id, double x, double y, double z)
    : mId(id), mCoordinates(x, y, z), mInitialCoordinates(x, y, z) {}

void Node::SetSolutionStepVariablesList(VariablesList::Pointer variables, std::size_t buffer_size) {
    if (mVariables && mVariables != variables) {
        // A different layout: values cannot be carried over by offset.
        mStepData.clear();
        mStride = 0;
    }
    mVariables = std::move(variables);
    ResizeSolutionStepData(buffer_size);
}

void Node::ResizeSolutionStepData(std::size_t buffer_size) {
    CONTACT_CHECK(buffer_size >= 1, InputError, "node ", mId, ": buffer size must be at least 1, got ", buffer_size);
    const std::size_t stride = mVariables ? mVariables->DataSize() : 0;
    if (stride == mStride && buffer_size == mBufferSize && mStepData.size() == stride * buffer_size) return;
    std::vector<double> data(stride * buffer_size, 0.0);
    // Copy step by step so that step i stays step i; extra new steps start at zero.
    const std::size_t steps = std::min(buffer_size, mBufferSize);
    const std::size_t common = std::min(stride, mStride);
    if (!mStepData.empty()) {
        for (std::size_t step = 0; step < steps; ++step) {
            const double* from = mStepData.data() + ((mCurrentStep + step) % mBufferSize) * mStride;
            std::copy(from, from + common, data.data() + step * stride);
        }
    }
    mStepData = std::move(data);
    mStride = stride;
    mBufferSize = buffer_size;
    mCurrentStep = 0;
}

void Node::CloneSolutionStep() {
    if (mBufferSize < 2 || mStride == 0) return;
    const std::size_t old_current = mCurrentStep;
    mCurrentStep = (mCurrentStep + mBufferSize - 1) % mBufferSize;
    std::copy_n(mStepData.data() + old_current * mStride, mStride, mStepData.data() + mCurrentStep * mStride);
}

void Node::CheckStep(const VariableData& variable, std::size_t step) const {
    if (!mVariables) ThrowNoHistoricalData(variable);
    CONTACT_CHECK(mVariables->Has(variable), InputError, "node ", mId, ": variable ", variable.Name(),
                  " is not a solution-step variable of its model part",
                  "\n  fix: call AddNodalSolutionStepVariable(",
                  variable.IsComponent() ? variable.SourceVariable()->Name() : variable.Name(),
                  ") on the root model part before reading the mesh, or use GetValue/SetValue");
    CONTACT_CHECK(step < mBufferSize, InputError, "node ", mId, ": buffer step ", step, " of variable ",
                  variable.Name(), " is outside the buffer (size ", mBufferSize, ")",
                  "\n  fix: increase the model part's buffer_size");
}

void Node::ThrowNoHistoricalData(const VariableData& variable) const {
    CONTACT_THROW(InputError, "node ", mId, " has no solution-step data, so variable ", variable.Name(),
                  " cannot be read historically",
                  "\n  fix: create the node through a model part (CreateNewNode) that declares ",
                  variable.IsComponent() ? variable.SourceVariable()->Name() : variable.Name(),
                  " with AddNodalSolutionStepVariable");
}

Dof& Node::AddDof(const Variable<double>& variable, const Variable<double>* reaction) {
    if (Dof* existing = FindDof(variable)) {
        if (reaction != nullptr) existing->SetReaction(*reaction);
        return *existing;
    }
    CONTACT_CHECK(SolutionStepsDataHas(variable), InputError, "node ", mId, ": cannot add the DoF ",
                  variable.Name(), " because ",
                  variable.IsComponent() ? variable.SourceVariable()->Name() : variable.Name(),
                  " is not a solution-step variable of its model part",
                  "\n  fix: call AddNodalSolutionStepVariable(",
                  variable.IsComponent() ? variable.SourceVariable()->Name() : variable.Name(),
                  ") before creating the nodes");
    if (reaction != nullptr) {
        CONTACT_CHECK(SolutionStepsDataHas(*reaction), InputError, "node ", mId, ": the reaction variable ",
                      reaction->Name(), " of DoF ", variable.Name(),
                      " is not a solution-step variable of its model part",
                      "\n  fix: call AddNodalSolutionStepVariable(",
                      reaction->IsComponent() ? reaction->SourceVariable()->Name() : reaction->Name(), ")");
    }
    mDofs.push_back(std::make_unique<Dof>(*this, variable, reaction));
    return *mDofs.back();
}

Dof* Node::FindDof(const VariableData& variable) const {
    for (const auto& dof : mDofs)
        if (dof->GetVariable().Key() == variable.Key()) return dof.get();
    return nullptr;
}

Dof* Node::GetDofChecked(const VariableData& variable) const {
    Dof* dof = FindDof(variable);
    if (dof == nullptr) {
        std::string present;
        for (const auto& other : mDofs) present += (present.empty() ? "" : ", ") + other->GetVariable().Name();
        CONTACT_THROW(InputError, "node ", mId, " has no DoF for ", variable.Name(),
                      "\n  present:  ", present.empty() ? std::string("none") : present,
                      "\n  fix:      add it with AddDof(", variable.Name(), ", <reaction>) before building the system");
    }
    return dof;
}

Dof& Node::GetDof(const VariableData& variable) const { return *GetDofChecked(variable); }

}  // namespace contact_app
