// SPDX-License-Identifier: BSD-3-Clause
// Local-system evaluations per second of every contact family (plane, no NV) × geometry pair: RHS only (double)
// and LHS + RHS (AD over the pair), with all slave nodes active (frictional: stick and slip, in a sliding step),
// after the pair's explicit pass (the nodal sums a residual reads). Never part of the pass/fail suite.
// Build and run: benchmarks/run_cpp_benchmarks.sh [build_dir]
#include <chrono>
#include <cstdio>
#include <string>

#include "contact_app/application.h"
#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/geometries/geometry_factory.h"
#include "contact_app/kernel/model.h"
#include "contact_app/kernel/registry.h"
#include "custom_conditions/contact_condition_registration.h"
#include "custom_conditions/paired_condition.h"
#include "custom_utilities/mortar_normals.h"
#include "tests/cpp/custom_utilities/mortar_test_utilities.h"

namespace {

using namespace contact_app;
namespace mt = contact_app::testing;

struct Rates {
    double rhs = 0.0, lhs_rhs = 0.0;
};

/// One pair of kind TPair under the registered condition @p name, evaluated repeatedly.
/// @p normal_variation: CONSIDER_NORMAL_VARIATION (3: the normals follow the iterate; the penalty pairs then also run
/// the AD pass that records ∂RHS/∂n, docs/theory/mortar.md §7 "Normals that follow the iterate").
/// @p tessellation: CONSIDER_TESSELLATION (true, the default: cells fan around the overlap's area centroid; false:
/// from its first vertex, the reference's default; docs/theory/mortar.md §1).
template <class TPair>
Rates Measure(const std::string& name, bool slip, int normal_variation, bool tessellation = true) {
    constexpr int D = TPair::Dim, NS = TPair::NumSlave, NM = TPair::NumMaster;
    Model model;
    ModelPart& part = model.CreateModelPart("Contact");
    for (const VariableData* v :
         {static_cast<const VariableData*>(&DISPLACEMENT), static_cast<const VariableData*>(&NORMAL),
          static_cast<const VariableData*>(&WEIGHTED_GAP), static_cast<const VariableData*>(&WEIGHTED_SLIP),
          static_cast<const VariableData*>(&LAGRANGE_MULTIPLIER_CONTACT_PRESSURE),
          static_cast<const VariableData*>(&VECTOR_LAGRANGE_MULTIPLIER)})
        part.AddNodalSolutionStepVariable(*v);
    part.SetBufferSize(2);
    auto properties = part.CreateNewProperties(1);
    properties->SetValue(CONSIDER_TESSELLATION, tessellation);
    std::mt19937 rng(17);
    const auto coordinates = mt::MakeRandomPair<TPair>(rng, 0.2);
    Geometry::PointsArrayType slave, master;
    for (int i = 0; i < NS + NM; ++i) {
        const Eigen::VectorXd x = i < NS ? Eigen::VectorXd(coordinates.slave.row(i).transpose())
                                         : Eigen::VectorXd(coordinates.master.row(i - NS).transpose());
        auto node = part.CreateNewNode(i + 1, x[0], x[1], D == 3 ? x[2] : 0.0);
        (i < NS ? slave : master).push_back(node);
    }
    const auto nodal = FaceNodalUnitNormals<D, NS, double>(coordinates.slave);
    const auto center = FaceCenterUnitNormal<D, NS, double>(coordinates.slave);
    const auto& prototype = dynamic_cast<const PairedCondition&>(Registry<Condition>::Instance().Get(name));
    const std::string face_s = D == 2 ? "Line2D2" : (NS == 3 ? "Triangle3D3" : "Quadrilateral3D4");
    const std::string face_m = D == 2 ? "Line2D2" : (NM == 3 ? "Triangle3D3" : "Quadrilateral3D4");
    auto condition = prototype.Create(1, CreateGeometry(face_s, slave), properties, CreateGeometry(face_m, master));
    Array3 c = Array3::Zero();
    c.head(D) = center;
    condition->SetValue(NORMAL, c);
    for (int j = 0; j < NS; ++j) {
        Node& node = *slave[j];
        Array3 n = Array3::Zero();
        n.head(D) = nodal.row(j).transpose();
        node.FastGetSolutionStepValue(NORMAL) = n;
        node.Set(ACTIVE, true);
        node.Set(SLIP, slip);
        node.SetValue(INITIAL_PENALTY, 10.0);
        node.SetValue(FRICTION_COEFFICIENT, 0.3);
        node.FastGetSolutionStepValue(LAGRANGE_MULTIPLIER_CONTACT_PRESSURE) = -0.1;
        node.FastGetSolutionStepValue(VECTOR_LAGRANGE_MULTIPLIER) = -0.1 * n;
    }
    ProcessInfo info;
    info.SetValue(SCALE_FACTOR, 1.0);
    info.SetValue(TANGENT_FACTOR, 0.1);
    info.SetValue(CONSIDER_NORMAL_VARIATION, normal_variation);
    condition->Initialize(info);
    condition->InitializeSolutionStep(info);
    for (int l = 0; l < NM; ++l) {  // a sliding step: the master moved since the start of the step
        master[l]->FastGetSolutionStepValue(DISPLACEMENT)[0] = 0.01;
        master[l]->Coordinates()[0] += 0.01;
    }
    condition->AddExplicitContribution(info);
    const int repetitions = D == 2 ? 20000 : 2000;
    auto time = [&](auto&& body) {
        const auto start = std::chrono::steady_clock::now();
        double checksum = 0.0;
        for (int r = 0; r < repetitions; ++r) checksum += body();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (checksum == 1234.5) std::printf(" ");  // keep the work observable
        return repetitions / seconds;
    };
    Matrix lhs;
    Vector rhs;
    Rates rates;
    rates.rhs = time([&] {
        condition->CalculateRightHandSide(rhs, info);
        return rhs[0];
    });
    rates.lhs_rhs = time([&] {
        condition->CalculateLocalSystem(lhs, rhs, info);
        return lhs(0, 0);
    });
    return rates;
}

/// Both cell layouts of one pair, LHS+RHS per second (stick for the frictional families).
template <class TPair>
void CellRow(const char* family, const char* suffix) {
    const std::string name = std::string(family) + "MortarContactCondition" + suffix;
    const Rates fan = Measure<TPair>(name, false, 0, false), centroid = Measure<TPair>(name, false, 0, true);
    std::printf("%-26s %-7s %14.0f %14.0f %+7.0f %%\n", family, suffix, fan.lhs_rhs, centroid.lhs_rhs,
                100.0 * (centroid.lhs_rhs / fan.lhs_rhs - 1.0));
}

template <class TPair>
void Row(const char* family, const char* suffix, double& ratio_out, int normal_variation = 0) {
    const std::string name = std::string(family) + "MortarContactCondition" + suffix;
    const bool frictional = std::string(family).find("Frictional") != std::string::npos;
    for (const bool slip : {false, true}) {
        if (slip && !frictional) break;
        const Rates r = Measure<TPair>(name, slip, normal_variation);
        if (!slip) ratio_out = r.rhs / r.lhs_rhs;
        std::printf("%-26s %-7s %-5s %14.0f %14.0f %8.1f\n", family, suffix, frictional ? (slip ? "slip" : "stick") : "",
                    r.rhs, r.lhs_rhs, r.rhs / r.lhs_rhs);
    }
}

}  // namespace

int main() {
    RegisterContactApplication();
    RegisterContactConditions();
    std::printf(
        "contact local system (all slave nodes active, sliding step), evaluations per second\n");
    std::printf("%-26s %-7s %-5s %14s %14s %8s\n", "family", "pair", "state", "RHS only", "LHS+RHS", "ratio");
    double ratio = 0.0, alm_frictional_3d4n = 0.0;
    for (const char* family : {"ALMFrictionless", "ALMFrictionlessComponents", "ALMFrictional", "PenaltyFrictionless",
                               "PenaltyFrictional"}) {
        Row<MortarPairTraits<2, 2, 2>>(family, "2D2N", ratio);
        Row<MortarPairTraits<3, 3, 3>>(family, "3D3N", ratio);
        Row<MortarPairTraits<3, 4, 4>>(family, "3D4N", ratio);
        if (std::string(family) == "ALMFrictional") alm_frictional_3d4n = ratio;
        Row<MortarPairTraits<3, 3, 4>>(family, "3D3N4N", ratio);
        Row<MortarPairTraits<3, 4, 3>>(family, "3D4N3N", ratio);
    }
    std::printf("ALMFrictional 3D4N: LHS+RHS costs %.1fx the RHS alone (%s 10x)\n", alm_frictional_3d4n,
                alm_frictional_3d4n <= 10.0 ? "within" : "NOT within");
    std::printf("\npenalty families, normals following the iterate (CONSIDER_NORMAL_VARIATION = 3, sets settled)\n");
    for (const char* family : {"PenaltyFrictionless", "PenaltyFrictional"}) {
        Row<MortarPairTraits<2, 2, 2>>(family, "2D2N", ratio, 3);
        Row<MortarPairTraits<3, 3, 3>>(family, "3D3N", ratio, 3);
        Row<MortarPairTraits<3, 4, 4>>(family, "3D4N", ratio, 3);
        Row<MortarPairTraits<3, 3, 4>>(family, "3D3N4N", ratio, 3);
        Row<MortarPairTraits<3, 4, 3>>(family, "3D4N3N", ratio, 3);
    }
    std::printf("\nmortar cells: LHS+RHS per second, fan from the first vertex vs around the area centroid (default)\n");
    std::printf("%-26s %-7s %14s %14s %9s\n", "family", "pair", "first vertex", "centroid", "change");
    for (const char* family : {"ALMFrictionless", "ALMFrictional", "PenaltyFrictional"}) {
        CellRow<MortarPairTraits<3, 3, 3>>(family, "3D3N");
        CellRow<MortarPairTraits<3, 4, 4>>(family, "3D4N");
        CellRow<MortarPairTraits<3, 3, 4>>(family, "3D3N4N");
        CellRow<MortarPairTraits<3, 4, 3>>(family, "3D4N3N");
    }
    return 0;
}
