// SPDX-License-Identifier: BSD-3-Clause
// Voigt layouts, engineering-shear conversions and the push-forward matrix of the elastic-law helpers.
#include <gtest/gtest.h>

#include <random>

#include "contact_app/structural/constitutive/elastic_utilities.h"
#include "law_test_utilities.h"

namespace contact_app::testing {
namespace {

using namespace contact_app::detail;

Matrix RandomSymmetric(int dim, std::mt19937& rng) {
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    Matrix A(dim, dim);
    for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) A(i, j) = uniform(rng);
    return 0.5 * (A + A.transpose());
}

TEST(ElasticUtilities, VoigtOrderFollowsKratos) {
    // 3D [xx, yy, zz, xy, yz, xz]; plane [xx, yy, xy]; axisymmetric [rr, zz, θθ, rz].
    EXPECT_EQ(VoigtPairs(6)[4], (VoigtPair{1, 2}));
    EXPECT_EQ(VoigtPairs(6)[5], (VoigtPair{0, 2}));
    EXPECT_EQ(VoigtPairs(3)[2], (VoigtPair{0, 1}));
    EXPECT_EQ(VoigtPairs(4)[2], (VoigtPair{2, 2}));
    EXPECT_EQ(VoigtPairs(4)[3], (VoigtPair{0, 1}));
    EXPECT_THROW(VoigtPairs(5), InternalError);
}

TEST(ElasticUtilities, StrainDoublesShearAndStressDoesNot) {
    std::mt19937 rng(3);
    for (const int size : {3, 6}) {
        const Matrix T = RandomSymmetric(size == 3 ? 2 : 3, rng);
        const Vector strain = StrainTensorToVector(T, size);
        const Vector stress = StressTensorToVector(T, size);
        EXPECT_DOUBLE_EQ(strain[size - 1], 2.0 * stress[size - 1]);
        EXPECT_LT(RelativeError(StrainVectorToTensor(strain), T), 1e-15);
        EXPECT_LT(RelativeError(StressVectorToTensor(stress), T), 1e-15);
        EXPECT_LT(RelativeError(strain, StrainVoigt(T, size)), 1e-15);
    }
}

TEST(ElasticUtilities, PushForwardMatrixMapsSToFSFt) {
    std::mt19937 rng(5);
    for (const int size : {3, 6}) {
        const int dim = size == 3 ? 2 : 3;
        const Matrix F = Matrix::Identity(dim, dim) + 0.3 * RandomSymmetric(dim, rng) + 0.2 * Matrix::Random(dim, dim);
        const Matrix S = RandomSymmetric(dim, rng);
        const Vector pushed = PushForwardMatrix(F, size) * StressVoigt(S, size);
        EXPECT_LT(RelativeError(StressTensor(pushed), F * S * F.transpose()), 1e-14);
    }
}

TEST(ElasticUtilities, LameConstantsAndDMatrixAgree) {
    auto properties = ElasticProperties(100.0, 0.2);
    ConstitutiveLaw::Parameters values;
    values.material_properties = properties.get();
    const ElasticConstants constants = ReadElasticConstants(values, "test");
    EXPECT_DOUBLE_EQ(constants.mu, 100.0 / 2.4);
    EXPECT_DOUBLE_EQ(constants.lambda, 20.0 / (1.2 * 0.6));
    const Matrix D = LinearElasticMatrix(ElasticModel::ThreeDimensional, 100.0, 0.2);
    EXPECT_NEAR(D(0, 0), constants.lambda + 2.0 * constants.mu, 1e-12);
    EXPECT_NEAR(D(0, 1), constants.lambda, 1e-12);
    EXPECT_NEAR(D(5, 5), constants.mu, 1e-12);
}

}  // namespace
}  // namespace contact_app::testing
