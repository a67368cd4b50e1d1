// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/alm_variables_calculation_process.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <vector>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/element.h"
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

/// YOUNG_MODULUS of a face: its own properties, else those of the solid element it bounds (the element holding all
/// its nodes; a real model leaves the interface's properties to the bodies). @p elements_of lists the elements of each
/// node of the root part, built on first use.
class FaceModulus {
public:
    explicit FaceModulus(const ModelPart& root) : mrRoot(root) {}

    /// The modulus, or NaN if neither the face nor an adjacent element has one.
    double operator()(const Condition& condition) {
        const Properties::Pointer& properties = condition.pGetProperties();
        if (properties && properties->Has(YOUNG_MODULUS)) return properties->GetValue(YOUNG_MODULUS);
        const Geometry& face = condition.GetGeometry();
        if (face.size() == 0) return std::numeric_limits<double>::quiet_NaN();
        if (mElementsOf.empty()) BuildNodeToElements();
        const auto found = mElementsOf.find(&face[0]);
        if (found == mElementsOf.end()) return std::numeric_limits<double>::quiet_NaN();
        for (const Element* element : found->second) {
            if (!element->pGetProperties() || !element->GetProperties().Has(YOUNG_MODULUS)) continue;
            const Geometry& solid = element->GetGeometry();
            bool bounds = true;
            for (std::size_t i = 0; i < face.size() && bounds; ++i) {
                bool has = false;
                for (std::size_t k = 0; k < solid.size() && !has; ++k) has = &solid[k] == &face[i];
                bounds = has;
            }
            if (bounds) return element->GetProperties().GetValue(YOUNG_MODULUS);
        }
        return std::numeric_limits<double>::quiet_NaN();
    }

private:
    void BuildNodeToElements() {
        for (const auto& element : mrRoot.Elements()) {
            const Geometry& solid = element->GetGeometry();
            for (std::size_t k = 0; k < solid.size(); ++k) mElementsOf[&solid[k]].push_back(element.get());
        }
    }

    const ModelPart& mrRoot;
    std::unordered_map<const Node*, std::vector<const Element*>> mElementsOf;
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
    FaceModulus face_modulus(mrModelPart.GetRootModelPart());
    for (const auto& condition : mrModelPart.Conditions()) {
        const Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 0) continue;
        // The reference uses 0 (and then a penalty of 1) for a face without YOUNG_MODULUS, which on a steel press fit
        // is an ALM penalty 1e5 times too soft; the body the face bounds knows its modulus.
        const double young_modulus = face_modulus(*condition);
        CONTACT_CHECK(std::isfinite(young_modulus), InputError, "ALMVariablesCalculationProcess: condition ",
                      condition->Id(), " of model part ", mrModelPart.FullName(),
                      " has no YOUNG_MODULUS, neither in its properties (id ",
                      condition->pGetProperties() ? condition->GetProperties().Id() : 0,
                      ") nor in those of an element it bounds",
                      "\n  expected: the modulus of the body the interface belongs to",
                      "\n  fix: give the body's elements (or the interface's properties) a YOUNG_MODULUS in the "
                      "materials file, or give the penalty yourself: \"advance_ALM_parameters\": {\"manual_ALM\": true, \"penalty\": ..., \"scale_factor\": ...}");
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
