// SPDX-License-Identifier: BSD-3-Clause
// Pairs per second of segmentation + dual basis + mortar operators for each registered pair kind, value
// only (double) and value + derivatives (Dual<d(n_s+n_m)>, with and without normal variation).
// Never part of the pass/fail suite. Build and run: benchmarks/run_cpp_benchmarks.sh
#include <chrono>
#include <cstdio>
#include <string>

#include "automatic_differentiation/ad_helpers.h"
#include "custom_utilities/mortar_normals.h"
#include "custom_utilities/mortar_operators.h"
#include "tests/cpp/custom_utilities/mortar_test_utilities.h"

namespace {

using namespace contact_app;
namespace mt = contact_app::testing;

template <class TPair>
void Run() {
    constexpr int D = TPair::Dim, NS = TPair::NumSlave, NM = TPair::NumMaster, N = TPair::NumDofs;
    using AD = typename TPair::ADScalar;
    std::mt19937 rng(17);
    std::vector<mt::RandomPair<TPair>> pairs;
    while (pairs.size() < 64) pairs.push_back(mt::MakeRandomPair<TPair>(rng, 0.4));
    const MortarIntegrator<D, NS, NM, double> value_integrator;
    const MortarIntegrator<D, NS, NM, AD> ad_integrator;
    auto time = [&pairs](auto&& body) {
        const int repetitions = D == 2 ? 20000 : 4000;
        double checksum = 0.0;
        const auto start = std::chrono::steady_clock::now();
        for (int r = 0; r < repetitions; ++r) checksum += body(pairs[r % pairs.size()]);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return std::make_pair(repetitions / seconds, checksum);
    };
    const auto value = time([&](const auto& p) {
        const auto normal = FaceCenterUnitNormal<D, NS, double>(p.slave);
        const auto nodal = FaceNodalUnitNormals<D, NS, double>(p.slave);
        return IntegrateMortarPair(value_integrator, p.slave, normal, p.master, nodal, true).operators.D.sum();
    });
    const auto derivatives = time([&](const auto& p) {
        const auto normal = FaceCenterUnitNormal<D, NS, double>(p.slave);
        const auto nodal = FaceNodalUnitNormals<D, NS, double>(p.slave);
        const auto r = IntegrateMortarPair(ad_integrator, Seed<N>(p.slave), normal, Seed<N>(p.master, NS * D), nodal, true);
        return r.operators.D.sum().Value();
    });
    const auto nv = time([&](const auto& p) {
        const auto x1 = Seed<N>(p.slave);
        const auto normal = FaceCenterUnitNormal<D, NS, AD>(x1);
        const auto nodal = FaceNodalUnitNormals<D, NS, AD>(x1);
        return IntegrateMortarPair(ad_integrator, x1, normal, Seed<N>(p.master, NS * D), nodal, true).operators.D.sum().Value();
    });
    std::printf("%-7s %14.0f %18.0f %18.0f   (N = %d)\n", mt::PairKindName::template GetName<TPair>(0).c_str(), value.first,
                derivatives.first, nv.first, N);
}

}  // namespace

int main() {
    std::printf("mortar pair (segmentation + Ae + D, M, Gauss order 2), pairs per second\n");
    std::printf("%-7s %14s %18s %18s\n", "pair", "value only", "value+derivatives", "value+deriv. (NV)");
    Run<MortarPairTraits<2, 2, 2>>();
    Run<MortarPairTraits<3, 3, 3>>();
    Run<MortarPairTraits<3, 4, 4>>();
    Run<MortarPairTraits<3, 3, 4>>();
    Run<MortarPairTraits<3, 4, 3>>();
    return 0;
}
