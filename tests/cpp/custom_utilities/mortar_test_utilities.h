// SPDX-License-Identifier: BSD-3-Clause
/// Shared fixtures of the mortar tests: random pairs of every kind and an independent clipping reference.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "custom_utilities/mortar_types.h"

namespace contact_app::testing {

template <class TTuple>
struct TestingTypes;
template <class... TPairs>
struct TestingTypes<std::tuple<TPairs...>> {
    using type = ::testing::Types<TPairs...>;
};
/// Every registered pair (CONTACT_APP_FOR_EACH_MORTAR_PAIR), so a new pair gets the typed tests.
using PairKinds = TestingTypes<RegisteredMortarPairs>::type;

struct PairKindName {
    template <class TPair>
    static std::string GetName(int) {
        std::string name = std::to_string(TPair::Dim) + "D" + std::to_string(TPair::NumSlave) + "N";
        if (TPair::NumMaster != TPair::NumSlave) name += std::to_string(TPair::NumMaster) + "N";
        return name;
    }
};

/// A random pair: slave a (perturbed) unit face in the plane z = 0 with normal +z (2D: y = 0, normal +y),
/// master a scaled, rotated, shifted and slightly warped copy facing it (reversed node order), at a small
/// gap or penetration; then both moved by one random rigid motion.
template <class TPair>
struct RandomPair {
    NodeCoordinates<double, TPair::Dim, TPair::NumSlave> slave;
    NodeCoordinates<double, TPair::Dim, TPair::NumMaster> master;
};

template <int TNumNodes>
std::vector<Eigen::Vector2d> PerturbedUnitFace(std::mt19937& rng, double noise) {
    std::uniform_real_distribution<double> u(-noise, noise);
    std::vector<Eigen::Vector2d> p;
    if (TNumNodes == 3) p = {{0, 0}, {1, 0}, {0, 1}};
    else p = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (auto& x : p) x += Eigen::Vector2d(u(rng), u(rng));
    return p;
}

inline Eigen::Matrix3d RandomRotation(std::mt19937& rng) {
    std::normal_distribution<double> g;
    Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
    return q.normalized().toRotationMatrix();
}

template <class TPair>
RandomPair<TPair> MakeRandomPair(std::mt19937& rng, double shift = 0.5, bool rigid_motion = true) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    RandomPair<TPair> pair;
    if constexpr (TPair::Dim == 2) {
        pair.slave << 1.0 + 0.1 * u(rng), 0.05 * u(rng), 0.1 * u(rng), 0.05 * u(rng);  // right to left: normal +y
        const double x0 = shift * u(rng), length = 1.0 + 0.3 * u(rng), gap = 0.05 * u(rng), tilt = 0.1 * u(rng);
        pair.master << x0, gap, x0 + length, gap + tilt;
        const double angle = M_PI * u(rng);
        Eigen::Matrix2d r;
        r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
        if (rigid_motion) {
            const Eigen::RowVector2d t(u(rng), u(rng));
            pair.slave = (pair.slave * r.transpose()).rowwise() + t;
            pair.master = (pair.master * r.transpose()).rowwise() + t;
        }
    } else {
        const auto s = PerturbedUnitFace<TPair::NumSlave>(rng, 0.15);
        for (int i = 0; i < TPair::NumSlave; ++i) pair.slave.row(i) << s[i][0], s[i][1], 0.0;
        const auto m = PerturbedUnitFace<TPair::NumMaster>(rng, 0.15);
        const double angle = M_PI * u(rng), scale = 1.0 + 0.3 * u(rng), gap = 0.05 * u(rng);
        const Eigen::Vector2d offset(shift * u(rng), shift * u(rng));
        for (int j = 0; j < TPair::NumMaster; ++j) {
            const Eigen::Vector2d p = scale * (Eigen::Rotation2Dd(angle).toRotationMatrix() * (m[TPair::NumMaster - 1 - j] - Eigen::Vector2d(0.4, 0.4)));
            pair.master.row(j) << p[0] + 0.4 + offset[0], p[1] + 0.4 + offset[1], gap + 0.02 * u(rng);
        }
        if (rigid_motion) {
            const Eigen::Matrix3d r = RandomRotation(rng);
            const Eigen::RowVector3d t(u(rng), u(rng), u(rng));
            pair.slave = (pair.slave * r.transpose()).rowwise() + t;
            pair.master = (pair.master * r.transpose()).rowwise() + t;
        }
    }
    return pair;
}

// -- Independent reference: Sutherland–Hodgman clipping of the projected polygons (plain double) --
using Polygon = std::vector<Eigen::Vector2d>;

inline double SignedArea(const Polygon& p) {
    double a = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const auto& x = p[k];
        const auto& y = p[(k + 1) % p.size()];
        a += 0.5 * (x[0] * y[1] - x[1] * y[0]);
    }
    return a;
}

inline Polygon SutherlandHodgman(Polygon subject, Polygon clip) {
    if (SignedArea(clip) < 0) std::reverse(clip.begin(), clip.end());
    for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
        const Eigen::Vector2d a = clip[e], b = clip[(e + 1) % clip.size()];
        auto side = [&](const Eigen::Vector2d& p) { return (b - a)[0] * (p - a)[1] - (b - a)[1] * (p - a)[0]; };
        Polygon output;
        for (std::size_t k = 0; k < subject.size(); ++k) {
            const Eigen::Vector2d p = subject[k], q = subject[(k + 1) % subject.size()];
            const double sp = side(p), sq = side(q);
            if (sp >= 0) output.push_back(p);
            if ((sp >= 0) != (sq >= 0)) output.push_back(p + (q - p) * (sp / (sp - sq)));
        }
        subject = output;
    }
    return subject;
}

/// Overlap measure of the master projected along @p normal on the slave plane/line.
template <int TDim, int TNS, int TNM>
double ReferenceOverlap(const NodeCoordinates<double, TDim, TNS>& slave, const SpatialVector<double, TDim>& normal,
                        const NodeCoordinates<double, TDim, TNM>& master) {
    const SpatialVector<double, TDim> n = normal.normalized();
    const SpatialVector<double, TDim> c = slave.colwise().mean().transpose();
    if constexpr (TDim == 2) {
        const Eigen::Vector2d t(-n[1], n[0]);
        auto coord = [&](const Eigen::RowVector2d& x) { return (x.transpose() - c).dot(t); };
        const double s0 = std::min(coord(slave.row(0)), coord(slave.row(1))), s1 = std::max(coord(slave.row(0)), coord(slave.row(1)));
        const double m0 = std::min(coord(master.row(0)), coord(master.row(1))), m1 = std::max(coord(master.row(0)), coord(master.row(1)));
        return std::max(0.0, std::min(s1, m1) - std::max(s0, m0));
    } else {
        Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
        auto project = [&](const Eigen::RowVector3d& x) {
            const Eigen::Vector3d d = x.transpose() - c;
            return Eigen::Vector2d(d.dot(t1), d.dot(t2));
        };
        Polygon s, m;
        for (int i = 0; i < TNS; ++i) s.push_back(project(slave.row(i)));
        for (int j = 0; j < TNM; ++j) m.push_back(project(master.row(j)));
        return std::abs(SignedArea(SutherlandHodgman(m, s)));
    }
}

}  // namespace contact_app::testing
