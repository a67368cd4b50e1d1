// SPDX-License-Identifier: BSD-3-Clause
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/model_part.h"
#include "custom_processes/aalm_adapt_penalty_value_process.h"
#include "custom_processes/alm_fast_init_process.h"
#include "custom_processes/alm_variables_calculation_process.h"
#include "custom_processes/compute_dynamic_factor_process.h"
#include "custom_processes/find_nodal_h_process.h"
#include "custom_processes/interface_preprocess_condition.h"
#include "custom_processes/master_slave_process.h"
#include "custom_processes/normal_check_process.h"
#include "custom_utilities/active_set_utilities.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app::bindings {

namespace {

/// A process class over one model part, kept alive by the process (the C++ object holds a reference).
template <class TProcess>
py::class_<TProcess> BindProcess(py::module_& m, const char* name, const char* doc) {
    py::class_<TProcess> process(m, name, doc);
    process.def("Execute", &TProcess::Execute, "Runs the process.");
    // Kratos Process hooks the reference process does not override: no-ops, so process lists can call them.
    for (const char* hook : {"ExecuteInitialize", "ExecuteBeforeSolutionLoop", "ExecuteInitializeSolutionStep",
                             "ExecuteFinalizeSolutionStep", "ExecuteBeforeOutputStep", "ExecuteAfterOutputStep",
                             "ExecuteFinalize"})
        process.def(hook, [](TProcess&) {}, "No-op (Kratos Process hook).");
    return process;
}

void BindContactUtilities(py::module_& m) {
    py::class_<ContactUtilities>(m, "ContactUtilities", "Model-part helpers of the contact workflow (static).")
        .def_static("CalculateMaxNodalH", &ContactUtilities::CalculateMaxNodalH, py::arg("model_part"))
        .def_static("CalculateMeanNodalH", &ContactUtilities::CalculateMeanNodalH, py::arg("model_part"))
        .def_static("CalculateMinimalNodalH", &ContactUtilities::CalculateMinimalNodalH, py::arg("model_part"))
        .def_static("CalculateRelativeSizeMesh", &ContactUtilities::CalculateRelativeSizeMesh, py::arg("model_part"))
        .def_static("ComputeStepJump", &ContactUtilities::ComputeStepJump, py::arg("model_part"),
                    py::arg("delta_time"), py::arg("half_step") = true)
        .def_static("CheckActivity", &ContactUtilities::CheckActivity, py::arg("model_part"),
                    py::arg("throw_error") = true)
        .def_static("CheckModelPartHasRotationDoF", &ContactUtilities::CheckModelPartHasRotationDoF,
                    py::arg("model_part"))
        .def_static("CleanContactModelParts", &ContactUtilities::CleanContactModelParts, py::arg("model_part"))
        .def_static("ComputeExplicitContributionConditions", &ContactUtilities::ComputeExplicitContributionConditions,
                    py::arg("model_part"))
        .def_static("ActivateConditionWithActiveNodes", &ContactUtilities::ActivateConditionWithActiveNodes,
                    py::arg("model_part"))
        .def_static("GetHalfJumpCenter", &ContactUtilities::GetHalfJumpCenter, py::arg("geometry"))
        .def_static("DistancePoints", &ContactUtilities::DistancePoints, py::arg("point_a"), py::arg("point_b"));
}

void BindActiveSetUtilities(py::module_& m) {
    auto active_set = m.def_submodule("ActiveSetUtilities", "Semi-smooth Newton active-set and stick/slip updates.");
    active_set.def("ComputePenaltyFrictionlessActiveSet", &ActiveSetUtilities::ComputePenaltyFrictionlessActiveSet,
                   py::arg("model_part"), py::arg("release_gap") = 0.0,
                   "Number of ACTIVE flips and held open nodes (release_gap: docs/theory/active_set.md section 2).");
    active_set.def("ComputeALMFrictionlessActiveSet", &ActiveSetUtilities::ComputeALMFrictionlessActiveSet,
                   py::arg("model_part"), "Number of ACTIVE flips.");
    active_set.def("ComputeALMFrictionlessComponentsActiveSet",
                   &ActiveSetUtilities::ComputeALMFrictionlessComponentsActiveSet, py::arg("model_part"),
                   "Number of ACTIVE flips.");
    active_set.def("ComputePenaltyFrictionalActiveSet", &ActiveSetUtilities::ComputePenaltyFrictionalActiveSet,
                   py::arg("model_part"), py::arg("pure_slip") = false, py::arg("release_gap") = 0.0,
                   "[ACTIVE flips and held open nodes, SLIP flips].");
    active_set.def("ComputeALMFrictionalActiveSet", &ActiveSetUtilities::ComputeALMFrictionalActiveSet,
                   py::arg("model_part"), py::arg("pure_slip") = false, "[ACTIVE flips, SLIP flips].");
}

}  // namespace

void BindContactProcesses(py::module_& m) {
    py::class_<InterfacePreprocessCondition>(m, "InterfacePreprocessCondition",
                                             "Builds interface (skin) conditions from the elements of the main model part.")
        .def(py::init<ModelPart&>(), py::arg("main_model_part"), py::keep_alive<1, 2>())
        .def("GenerateInterfacePart", &InterfacePreprocessCondition::GenerateInterfacePart, py::arg("model_part"),
             py::arg("simplify_geometry") = false, py::arg("contact_property_id") = 0,
             "Creates the boundary-face conditions over the part's nodes; returns how many were created.")
        .def("GenerateSkinModelPart", &InterfacePreprocessCondition::GenerateSkinModelPart,
             py::arg("destination_model_part"), py::arg("contact_property_id") = 0,
             "Skin of the whole main model part into the destination sub model part; returns the count.")
        .def("GenerateSkin", &InterfacePreprocessCondition::GenerateSkinModelPart, py::arg("destination_model_part"),
             py::arg("contact_property_id") = 0, "Alias of GenerateSkinModelPart.");
    BindProcess<FindNodalHProcess>(m, "FindNodalHProcess", "NODAL_H = shortest element edge around each node.")
        .def(py::init<ModelPart&>(), py::arg("model_part"), py::keep_alive<1, 2>());
    BindProcess<NormalCheckProcess>(m, "NormalCheckProcess", "Flips interface conditions whose normal points inwards.")
        .def(py::init<ModelPart&, double, double>(), py::arg("model_part"), py::arg("length_proportion") = 0.1,
             py::arg("check_threshold") = 5.0e-7, py::keep_alive<1, 2>())
        .def("NumberOfFlippedConditions", &NormalCheckProcess::NumberOfFlippedConditions,
             "How many conditions the last Execute() flipped.");
    BindProcess<MasterSlaveProcess>(m, "MasterSlaveProcess", "SLAVE / MASTER flags of conditions from their nodes.")
        .def(py::init<ModelPart&>(), py::arg("model_part"), py::keep_alive<1, 2>());
    BindProcess<ALMVariablesCalculationProcess>(m, "ALMVariablesCalculationProcess",
                                                "ProcessInfo INITIAL_PENALTY and SCALE_FACTOR from the interface stiffness.")
        .def(py::init<ModelPart&, double, double>(), py::arg("model_part"), py::arg("stiffness_factor") = 1.0,
             py::arg("penalty_scale_factor") = 1.0, py::keep_alive<1, 2>());
    BindProcess<ALMFastInit>(m, "ALMFastInit", "Initial nodal contact values (penalty, gaps, friction coefficients).")
        .def(py::init<ModelPart&>(), py::arg("model_part"), py::keep_alive<1, 2>());
    BindProcess<AALMAdaptPenaltyValueProcess>(m, "AALMAdaptPenaltyValueProcess", "Adaptive nodal ALM penalty.")
        .def(py::init<ModelPart&>(), py::arg("model_part"), py::keep_alive<1, 2>());
    BindProcess<ComputeDynamicFactorProcess>(m, "ComputeDynamicFactorProcess",
                                             "DYNAMIC_FACTOR: share of the step after impact.")
        .def(py::init<ModelPart&>(), py::arg("model_part"), py::keep_alive<1, 2>());
    BindContactUtilities(m);
    BindActiveSetUtilities(m);
}

}  // namespace contact_app::bindings
