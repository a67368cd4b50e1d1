// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/structural/constitutive/elastic_utilities.h"

#include <cmath>

#include <Eigen/LU>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/inverted_element_error.h"
#include "contact_app/kernel/properties.h"
#include "contact_app/kernel/variables.h"

namespace contact_app::detail {

namespace {

// docs/theory/structural.md §4: Kratos rejects 0.499 < ν < 0.501 and −1.01 < ν < −0.999; together with the
// mathematical range (−1, 0.5) that leaves [−0.999, 0.499].
constexpr double kMinPoisson = -0.999;
constexpr double kMaxPoisson = 0.499;

int TensorDimensionOfSize(int strain_size) { return strain_size == 3 ? 2 : 3; }

}  // namespace

int StrainSize(ElasticModel model) {
    switch (model) {
        case ElasticModel::ThreeDimensional: return 6;
        case ElasticModel::Axisymmetric: return 4;
        case ElasticModel::PlaneStrain:
        case ElasticModel::PlaneStress: return 3;
    }
    CONTACT_THROW(InternalError, "unknown ElasticModel");
}

int TensorDimension(ElasticModel model) { return TensorDimensionOfSize(StrainSize(model)); }

const std::vector<VoigtPair>& VoigtPairs(int strain_size) {
    static const std::vector<VoigtPair> plane{{0, 0}, {1, 1}, {0, 1}};
    static const std::vector<VoigtPair> axisymmetric{{0, 0}, {1, 1}, {2, 2}, {0, 1}};
    static const std::vector<VoigtPair> solid{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
    switch (strain_size) {
        case 3: return plane;
        case 4: return axisymmetric;
        case 6: return solid;
        default: CONTACT_THROW(InternalError, "no Voigt layout for strain size ", strain_size, " (expected 3, 4 or 6)");
    }
}

ElasticConstants ReadElasticConstants(const ConstitutiveLaw::Parameters& values, const std::string& law_name) {
    CONTACT_CHECK(values.material_properties != nullptr, InternalError, law_name,
                  ": CalculateMaterialResponse called without material_properties");
    const Properties& properties = *values.material_properties;
    ElasticConstants constants{};
    constants.young = properties.GetChecked(YOUNG_MODULUS);
    constants.poisson = properties.GetChecked(POISSON_RATIO);
    const double nu = constants.poisson;
    constants.lambda = constants.young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    constants.mu = constants.young / (2.0 * (1.0 + nu));
    return constants;
}

void CheckElasticProperties(const Properties& properties, const std::string& law_name) {
    const IndexType id = properties.Id();
    const std::string fix_where = " in the \"Variables\" block of property " + std::to_string(id) + " (materials file)";
    CONTACT_CHECK(properties.Has(YOUNG_MODULUS), InputError, law_name, ": properties ", id,
                  " have no YOUNG_MODULUS\n  expected: YOUNG_MODULUS > 0\n  fix: set YOUNG_MODULUS", fix_where);
    const double young = properties.GetValue(YOUNG_MODULUS);
    CONTACT_CHECK(young > 0.0, InputError, law_name, ": properties ", id, " have YOUNG_MODULUS = ", young,
                  "\n  expected: YOUNG_MODULUS > 0\n  fix: set a positive YOUNG_MODULUS", fix_where);
    CONTACT_CHECK(properties.Has(POISSON_RATIO), InputError, law_name, ": properties ", id,
                  " have no POISSON_RATIO\n  expected: ", kMinPoisson, " <= POISSON_RATIO <= ", kMaxPoisson,
                  "\n  fix: set POISSON_RATIO", fix_where, " (0.0 if that is what you mean)");
    const double nu = properties.GetValue(POISSON_RATIO);
    CONTACT_CHECK(nu >= kMinPoisson && nu <= kMaxPoisson, InputError, law_name, ": properties ", id,
                  " have POISSON_RATIO = ", nu, "\n  expected: ", kMinPoisson, " <= POISSON_RATIO <= ", kMaxPoisson,
                  " (λ is singular at 0.5, μ at -1)\n  fix: use a POISSON_RATIO in that range, e.g. 0.49 for a nearly"
                  " incompressible material", fix_where);
    if (properties.Has(DENSITY)) {
        const double density = properties.GetValue(DENSITY);
        CONTACT_CHECK(density >= 0.0, InputError, law_name, ": properties ", id, " have DENSITY = ", density,
                      "\n  expected: DENSITY >= 0\n  fix: set a non-negative DENSITY", fix_where);
    }
}

Matrix LinearElasticMatrix(ElasticModel model, double young, double poisson) {
    const double nu = poisson;
    if (model == ElasticModel::PlaneStress) {
        Matrix D = Matrix::Zero(3, 3);
        const double factor = young / (1.0 - nu * nu);
        D(0, 0) = D(1, 1) = factor;
        D(0, 1) = D(1, 0) = factor * nu;
        D(2, 2) = factor * 0.5 * (1.0 - nu);
        return D;
    }
    // 3D D; plane strain and axisymmetric keep the rows/columns of their Voigt components.
    const double c = young / ((1.0 + nu) * (1.0 - 2.0 * nu));
    Matrix solid = Matrix::Zero(6, 6);
    for (int a = 0; a < 3; ++a) {
        for (int b = 0; b < 3; ++b) solid(a, b) = c * (a == b ? 1.0 - nu : nu);
        solid(a + 3, a + 3) = c * 0.5 * (1.0 - 2.0 * nu);
    }
    static const std::vector<int> plane_rows{0, 1, 3};
    static const std::vector<int> axisymmetric_rows{0, 1, 2, 3};
    switch (model) {
        case ElasticModel::ThreeDimensional: return solid;
        case ElasticModel::PlaneStrain: return solid(plane_rows, plane_rows);
        case ElasticModel::Axisymmetric: return solid(axisymmetric_rows, axisymmetric_rows);
        default: CONTACT_THROW(InternalError, "unknown ElasticModel");
    }
}

Vector StrainTensorToVector(const Matrix& tensor, int strain_size) {
    const auto& pairs = VoigtPairs(strain_size);
    Vector voigt(strain_size);
    for (int a = 0; a < strain_size; ++a) {
        const auto [i, j] = pairs[a];
        voigt[a] = (i == j ? 1.0 : 2.0) * tensor(i, j);
    }
    return voigt;
}

Vector StressTensorToVector(const Matrix& tensor, int strain_size) {
    const auto& pairs = VoigtPairs(strain_size);
    Vector voigt(strain_size);
    for (int a = 0; a < strain_size; ++a) voigt[a] = tensor(pairs[a][0], pairs[a][1]);
    return voigt;
}

Matrix StrainVectorToTensor(const Vector& voigt) {
    const int size = static_cast<int>(voigt.size());
    const auto& pairs = VoigtPairs(size);
    const int dim = TensorDimensionOfSize(size);
    Matrix tensor = Matrix::Zero(dim, dim);
    for (int a = 0; a < size; ++a) {
        const auto [i, j] = pairs[a];
        const double value = (i == j ? 1.0 : 0.5) * voigt[a];
        tensor(i, j) = tensor(j, i) = value;
    }
    return tensor;
}

Matrix StressVectorToTensor(const Vector& voigt) {
    const int size = static_cast<int>(voigt.size());
    const auto& pairs = VoigtPairs(size);
    const int dim = TensorDimensionOfSize(size);
    Matrix tensor = Matrix::Zero(dim, dim);
    for (int a = 0; a < size; ++a) tensor(pairs[a][0], pairs[a][1]) = tensor(pairs[a][1], pairs[a][0]) = voigt[a];
    return tensor;
}

Matrix DeformationGradient(const ConstitutiveLaw::Parameters& values, int dim, bool allow_padding,
                           const std::string& law_name) {
    const Matrix& F = values.deformation_gradient;
    CONTACT_CHECK(F.rows() == F.cols() && F.rows() >= 2, InputError, law_name, ": the deformation gradient is ",
                  F.rows(), "×", F.cols(), "\n  expected: a square 2×2 or 3×3 matrix\n  fix: the element must fill"
                  " Parameters::deformation_gradient before CalculateMaterialResponse");
    if (F.rows() >= dim) return F.topLeftCorner(dim, dim);
    CONTACT_CHECK(allow_padding, InputError, law_name, ": got a ", F.rows(), "×", F.cols(),
                  " deformation gradient\n  expected: ", dim, "×", dim,
                  "\n  fix: use this law with ", dim, "D elements, or a 2D law with 2D elements");
    Matrix padded = Matrix::Identity(dim, dim);
    padded.topLeftCorner(F.rows(), F.cols()) = F;  // hoop stretch 1: the element gave no F₃₃
    return padded;
}

Vector GreenLagrangeStrainVector(const Matrix& F, int strain_size) {
    const Matrix E = 0.5 * (F.transpose() * F - Matrix::Identity(F.rows(), F.cols()));
    return StrainTensorToVector(E, strain_size);
}

Vector AlmansiStrainVector(const Matrix& F, int strain_size) {
    const Matrix b = F * F.transpose();
    const Matrix e = 0.5 * (Matrix::Identity(F.rows(), F.cols()) - b.inverse());
    return StrainTensorToVector(e, strain_size);
}

Matrix PushForwardMatrix(const Matrix& F, int strain_size) {
    const auto& pairs = VoigtPairs(strain_size);
    Matrix Q(strain_size, strain_size);
    for (int a = 0; a < strain_size; ++a) {
        const auto [i, j] = pairs[a];
        for (int A = 0; A < strain_size; ++A) {
            const auto [I, J] = pairs[A];
            Q(a, A) = F(i, I) * F(j, J) + (I != J ? F(i, J) * F(j, I) : 0.0);
        }
    }
    return Q;
}

Vector MaterialStrain(const ConstitutiveLaw::Parameters& values, ElasticModel model, const std::string& law_name) {
    const int size = StrainSize(model);
    if (values.use_element_provided_strain) {
        CheckStrainVectorSize(values.strain_vector, size, law_name);
        return values.strain_vector;
    }
    const bool axisymmetric = model == ElasticModel::Axisymmetric;
    return GreenLagrangeStrainVector(DeformationGradient(values, TensorDimension(model), axisymmetric, law_name), size);
}

void CheckStrainVectorSize(const Vector& strain, int strain_size, const std::string& law_name) {
    CONTACT_CHECK(strain.size() == strain_size, InputError, law_name, ": the element provided a strain vector of size ",
                  strain.size(), "\n  expected: size ", strain_size,
                  "\n  fix: pair this law with an element of the same dimension (strain size ", strain_size, ")");
}

void CheckPositiveDeterminant(const ConstitutiveLaw::Parameters& values, const std::string& law_name) {
    if (values.determinant_f > 0.0) return;
    const std::string nodes = values.element_geometry != nullptr
                                  ? " (element nodes " + values.element_geometry->NodeIdsString() + ")"
                                  : std::string();
    // The element that evaluates the law adds its id and TIME (BaseSolidElement::PointResponse).
    throw InvertedElementError(
        detail::Concat(law_name, ": det F = ", values.determinant_f, " at an integration point", nodes,
                       "\n  expected: det F > 0 (an inverted element has no finite-strain stress)",
                       "\n  fix: reduce the load or time step (or enable step cutting: "
                       "contact_settings.adaptative_strategy), or refine the mesh where it inverts"),
        0, "det F", values.determinant_f, std::nan(""));
}

void ThrowUnsupportedPK1(const std::string& law_name) {
    CONTACT_THROW(ConfigurationError, law_name, ": StressMeasure::PK1 is not available",
                  "\n  expected: PK2, Kirchhoff or Cauchy (the unsymmetric P = F S has no Voigt form)",
                  "\n  fix: request PK2 and form P = F S in the element");
}

}  // namespace contact_app::detail
