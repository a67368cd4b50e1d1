// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/alm_variables_calculation_process.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include "contact_app/application.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/model_part.h"
#include "custom_utilities/contact_utilities.h"

namespace contact_app {

namespace {

constexpr double kTolerance = 1.0e-12;

/// Area-weighted sums of one side.
struct SideSums {
    double area = 0.0, stiffness = 0.0, length = 0.0;

    void Add(double young_modulus, double area_c, double nodal_length_sum, std::size_t nodes) {
        area += area_c;
        stiffness += young_modulus * area_c;
        length += nodal_length_sum * area_c / static_cast<double>(nodes);
    }
    double MeanStiffness() const { return stiffness / (area + kTolerance); }
    double MeanLength() const { return length / (area + kTolerance); }
};

}  // namespace

ALMVariablesCalculationProcess::ALMVariablesCalculationProcess(ModelPart& model_part, double stiffness_factor,
                                                               double penalty_scale_factor)
    : mrModelPart(model_part), mStiffnessFactor(stiffness_factor), mPenaltyScaleFactor(penalty_scale_factor) {
    CONTACT_CHECK(stiffness_factor > 0.0 && penalty_scale_factor > 0.0 && std::isfinite(stiffness_factor) &&
                      std::isfinite(penalty_scale_factor),
                  InputError,
                  "ALMVariablesCalculationProcess: stiffness_factor ", stiffness_factor, " and penalty_scale_factor ",
                  penalty_scale_factor, " must be positive and finite\n  fix: set advance_ALM_parameters.stiffness_factor and",
                  " penalty_scale_factor to positive values (default 1.0)");
}

void ALMVariablesCalculationProcess::Execute() {
    SideSums slave, master;
    bool warned = false;
    for (const auto& condition : mrModelPart.Conditions()) {
        const Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 0) continue;
        const Properties::Pointer& properties = condition->pGetProperties();
        const bool has_modulus = properties && properties->Has(YOUNG_MODULUS);
        if (!has_modulus && !warned) {
            std::cerr << "[WARNING] ALMVariablesCalculationProcess: condition " << condition->Id() << " of model part "
                      << mrModelPart.FullName() << " has no YOUNG_MODULUS in its properties; 0 is used\n";
            warned = true;
        }
        const double young_modulus = has_modulus ? properties->GetValue(YOUNG_MODULUS) : 0.0;
        const double area = geometry.DomainSize();
        double nodal_length_sum = 0.0;
        for (std::size_t i = 0; i < geometry.size(); ++i) nodal_length_sum += ContactUtilities::NodalH(geometry[i]);
        const bool is_slave = condition->Is(SLAVE), is_master = condition->Is(MASTER);
        if (is_slave || !is_master) slave.Add(young_modulus, area, nodal_length_sum, geometry.size());
        if (is_master || !is_slave) master.Add(young_modulus, area, nodal_length_sum, geometry.size());
    }
    CONTACT_CHECK(slave.area + master.area > 0.0, InputError, "ALMVariablesCalculationProcess: model part ",
                  mrModelPart.FullName(), " has no interface condition with a positive area",
                  "\n  fix: generate the interface conditions (InterfacePreprocessCondition) before this process");
    const double f = mStiffnessFactor;
    const SideSums& slave_side = slave.MeanStiffness() > std::numeric_limits<double>::epsilon() ? slave : master;
    const double penalty_slave = f * slave_side.MeanStiffness() / (slave_side.MeanLength() + kTolerance);
    const double penalty_master = f * master.MeanStiffness() / (master.MeanLength() + kTolerance);
    ProcessInfo& process_info = mrModelPart.GetProcessInfo();
    process_info.SetValue(INITIAL_PENALTY, std::min(penalty_slave, penalty_master));
    process_info.SetValue(SCALE_FACTOR, mPenaltyScaleFactor * std::min(penalty_slave, penalty_master));
}

}  // namespace contact_app
