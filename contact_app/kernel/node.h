// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <vector>

#include "contact_app/kernel/data_value_holder.h"
#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/flags.h"
#include "contact_app/kernel/types.h"
#include "contact_app/kernel/variables_list.h"

namespace contact_app {

/// A mesh node (Kratos Node): id, initial and current coordinates, flags, historical data,
/// non-historical data and DoFs.
///
/// Historical data is one contiguous block of `buffer_size × VariablesList::DataSize()` doubles,
/// used as a ring: step 0 is the current step, step 1 the previous one, and so on.
/// CloneSolutionStep() moves the ring by one step and copies the old current values forward.
class Node : public Flags, public DataValueHolder {
public:
    using Pointer = std::shared_ptr<Node>;

    /// A node with initial = current coordinates and no historical data.
    Node(IndexType id, double x, double y, double z);
    Node(const Node&) = delete;
    Node& operator=(const Node&) = delete;

    IndexType Id() const { return mId; }
    void SetId(IndexType id) { mId = id; }

    const Array3& Coordinates() const { return mCoordinates; }
    Array3& Coordinates() { return mCoordinates; }
    const Array3& InitialCoordinates() const { return mInitialCoordinates; }
    Array3& InitialCoordinates() { return mInitialCoordinates; }
    double X() const { return mCoordinates[0]; }
    double Y() const { return mCoordinates[1]; }
    double Z() const { return mCoordinates[2]; }
    double X0() const { return mInitialCoordinates[0]; }
    double Y0() const { return mInitialCoordinates[1]; }
    double Z0() const { return mInitialCoordinates[2]; }

    // -- Historical (solution-step) data --

    /// Attaches the layout and allocates zeroed storage for @p buffer_size steps
    /// (keeps the existing values of variables already stored).
    void SetSolutionStepVariablesList(VariablesList::Pointer variables, std::size_t buffer_size);
    /// Re-allocates after the shared layout grew or the buffer size changed; keeps the values.
    void ResizeSolutionStepData(std::size_t buffer_size);
    const VariablesList::Pointer& pGetVariablesList() const { return mVariables; }
    std::size_t GetBufferSize() const { return mBufferSize; }
    bool SolutionStepsDataHas(const VariableData& variable) const {
        return mVariables && mVariables->Has(variable);
    }

    /// Value at buffer step @p step, no checks beyond the variable lookup (hot path).
    double& FastGetSolutionStepValue(const Variable<double>& variable, std::size_t step = 0) {
        return *StepPointer(variable, step);
    }
    Array3& FastGetSolutionStepValue(const Variable<Array3>& variable, std::size_t step = 0) {
        return *reinterpret_cast<Array3*>(StepPointer(variable, step));
    }
    double FastGetSolutionStepValue(const Variable<double>& variable, std::size_t step = 0) const {
        return *const_cast<Node*>(this)->StepPointer(variable, step);
    }
    const Array3& FastGetSolutionStepValue(const Variable<Array3>& variable, std::size_t step = 0) const {
        return *reinterpret_cast<const Array3*>(const_cast<Node*>(this)->StepPointer(variable, step));
    }
    /// As FastGetSolutionStepValue, with the step checked against the buffer size.
    /// @throws InputError for a missing variable or a step outside the buffer.
    template <class T>
    T& GetSolutionStepValue(const Variable<T>& variable, std::size_t step = 0) {
        CheckStep(variable, step);
        return FastGetSolutionStepValue(variable, step);
    }
    template <class T>
    const T& GetSolutionStepValue(const Variable<T>& variable, std::size_t step = 0) const {
        CheckStep(variable, step);
        return const_cast<Node*>(this)->FastGetSolutionStepValue(variable, step);
    }
    /// Shifts the ring by one step: the old step 0 becomes step 1 and is copied into the new step 0.
    void CloneSolutionStep();

    // -- Degrees of freedom --

    /// Adds (or returns the existing) DoF of @p variable; sets its reaction variable if given.
    /// @throws InputError if @p variable is not a solution-step variable of this node.
    Dof& AddDof(const Variable<double>& variable, const Variable<double>* reaction = nullptr);
    Dof& AddDof(const Variable<double>& variable, const Variable<double>& reaction) {
        return AddDof(variable, &reaction);
    }
    bool HasDofFor(const VariableData& variable) const { return FindDof(variable) != nullptr; }
    /// @throws InputError naming the node and the variable if there is no such DoF.
    Dof& GetDof(const VariableData& variable) const;
    Dof* pGetDof(const VariableData& variable) const { return GetDofChecked(variable); }
    /// Fixes the DoF of @p variable, adding it first if needed (as Kratos does for mdpa fixity).
    void Fix(const Variable<double>& variable) { AddDof(variable).FixDof(); }
    /// @throws InputError if there is no such DoF.
    void Free(const VariableData& variable) { GetDof(variable).FreeDof(); }
    bool IsFixed(const VariableData& variable) const {
        const Dof* dof = FindDof(variable);
        return dof != nullptr && dof->IsFixed();
    }
    const std::vector<std::unique_ptr<Dof>>& GetDofs() const { return mDofs; }

private:
    double* StepPointer(const VariableData& variable, std::size_t step) {
        if (!mVariables) ThrowNoHistoricalData(variable);
        const std::size_t position = (mCurrentStep + step) % mBufferSize;
        return mStepData.data() + position * mStride + mVariables->Offset(variable);
    }
    void CheckStep(const VariableData& variable, std::size_t step) const;
    [[noreturn]] void ThrowNoHistoricalData(const VariableData& variable) const;
    Dof* FindDof(const VariableData& variable) const;
    Dof* GetDofChecked(const VariableData& variable) const;

    IndexType mId;
    Array3 mCoordinates;
    Array3 mInitialCoordinates;
    VariablesList::Pointer mVariables;
    std::vector<double> mStepData;
    std::size_t mStride = 0;       // doubles per step block as allocated
    std::size_t mBufferSize = 1;
    std::size_t mCurrentStep = 0;  // ring position of step 0
    std::vector<std::unique_ptr<Dof>> mDofs;
};

}  // namespace contact_app
