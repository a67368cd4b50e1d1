// SPDX-License-Identifier: BSD-3-Clause
// Chooses the AD scalar: contact_app::Dual<N> vs Eigen's AutoDiffScalar<Matrix<double,N,1>> on a mortar-like
// kernel (triangle Jacobians, normals, shape-function products, a 4×4 inverse), N = 24 (3D4N pair).
// Prints evaluations per second for each; never part of the pass/fail suite.
// Build and run: benchmarks/run_cpp_benchmarks.sh
#include <chrono>
#include <cstdio>

#include <Eigen/Dense>
#include <unsupported/Eigen/AutoDiff>

#include "automatic_differentiation/ad_helpers.h"

namespace {

constexpr int kN = 24;

template <class T>
T Kernel(const Eigen::Matrix<T, 8, 3>& x) {
    using std::sqrt;
    Eigen::Matrix<T, 4, 4> me = Eigen::Matrix<T, 4, 4>::Zero();
    T total(0.0);
    for (int cell = 0; cell < 6; ++cell) {
        const Eigen::Matrix<T, 3, 1> a = (x.row((cell + 1) % 8) - x.row(cell)).transpose();
        const Eigen::Matrix<T, 3, 1> b = (x.row((cell + 2) % 8) - x.row(cell)).transpose();
        const Eigen::Matrix<T, 3, 1> n = a.cross(b);
        const T det = sqrt(n.dot(n));
        for (int gp = 0; gp < 3; ++gp) {
            const double s = (gp + 1) / 5.0, t = (3 - gp) / 7.0;
            Eigen::Matrix<T, 4, 1> shape;
            shape << T(1.0) - s * x(cell, 0) / det, s * x(cell, 1), t * x(cell, 2), s * t / det;
            me += (det / 6.0) * shape * shape.transpose();
            total += det * shape.sum();
        }
    }
    me += Eigen::Matrix<T, 4, 4>::Identity() * T(1.0);
    const Eigen::Matrix<T, 4, 4> inv = me.inverse();
    return total + inv.sum();
}

using AutoDiff = Eigen::AutoDiffScalar<Eigen::Matrix<double, kN, 1>>;
Eigen::Matrix<double, kN, 1> Gradient(const contact_app::Dual<kN>& v) { return v.Derivatives(); }
const Eigen::Matrix<double, kN, 1>& Gradient(const AutoDiff& v) { return v.derivatives(); }

template <class T, class TSeed>
double EvaluationsPerSecond(const Eigen::Matrix<double, 8, 3>& x0, TSeed seed, double* checksum) {
    const Eigen::Matrix<T, 8, 3> x = seed(x0);
    const int repetitions = 20000;
    const auto start = std::chrono::steady_clock::now();
    double sum = 0.0;
    for (int r = 0; r < repetitions; ++r) {
        const T value = Kernel<T>(x);
        sum += Gradient(value)[r % kN];
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    *checksum = sum;
    return repetitions / seconds;
}

}  // namespace

int main() {
    Eigen::Matrix<double, 8, 3> x0;
    x0.setRandom();
    x0.col(2) *= 0.1;
    double check_dual = 0.0, check_eigen = 0.0;
    const double dual = EvaluationsPerSecond<contact_app::Dual<kN>>(
        x0, [](const auto& v) { return contact_app::Seed<kN>(v); }, &check_dual);
    const double eigen = EvaluationsPerSecond<AutoDiff>(
        x0,
        [](const auto& v) {
            Eigen::Matrix<AutoDiff, 8, 3> r;
            for (int i = 0; i < 8; ++i)
                for (int c = 0; c < 3; ++c) r(i, c) = AutoDiff(v(i, c), kN, 3 * i + c);
            return r;
        },
        &check_eigen);
    const double plain = [&] {
        const auto start = std::chrono::steady_clock::now();
        double sum = 0.0;
        for (int r = 0; r < 200000; ++r) {
            Eigen::Matrix<double, 8, 3> x = x0;
            x(r % 8, r % 3) += 1e-12;
            sum += Kernel<double>(x);
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("  (checksum %.3f)\n", sum);
        return 200000 / seconds;
    }();
    std::printf("AD scalar benchmark (mortar-like kernel, N = %d derivatives)\n", kN);
    std::printf("  double (value only)               %12.0f evaluations/s\n", plain);
    std::printf("  contact_app::Dual<%d>             %12.0f evaluations/s (%.1fx value cost)\n", kN, dual, plain / dual);
    std::printf("  Eigen::AutoDiffScalar<Vector%dd>  %12.0f evaluations/s (%.1fx value cost)\n", kN, eigen, plain / eigen);
    std::printf("  derivative checksums agree: %s\n", std::abs(check_dual - check_eigen) < 1e-8 * (1 + std::abs(check_dual)) ? "yes" : "NO");
    return 0;
}
