// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/geometries/geometry.h"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {
namespace {

constexpr int kMaxNewtonIterations = 50;
constexpr double kNewtonCloseTolerance = 1e-10;  // then one more (quadratically convergent) step
constexpr double kSingularRatio = 1e-24;         // det(JᵀJ) / (tr(JᵀJ)/d)^d below this: degenerate

const Array3& NodeCoordinates(const Node& node, Geometry::Configuration configuration) {
    return configuration == Geometry::Configuration::Current ? node.Coordinates() : node.InitialCoordinates();
}

std::string Format(const Array3& x) {
    std::ostringstream stream;
    stream.precision(17);
    stream << "(" << x[0] << ", " << x[1] << ", " << x[2] << ")";
    return stream.str();
}

// Starting point of the local-coordinate Newton iteration: the reference element's centroid.
Array3 ReferenceCenter(GeometryFamily family) {
    switch (family) {
        case GeometryFamily::Triangle: return Array3(1.0 / 3.0, 1.0 / 3.0, 0.0);
        case GeometryFamily::Tetrahedra: return Array3(0.25, 0.25, 0.25);
        case GeometryFamily::Prism: return Array3(1.0 / 3.0, 1.0 / 3.0, 0.5);
        default: return Array3::Zero();
    }
}

bool IsInsideReference(GeometryFamily family, const Array3& xi, double tolerance) {
    const double upper = 1.0 + tolerance;
    const auto in_cube = [&](int dim) { return xi.head(dim).cwiseAbs().maxCoeff() <= upper; };
    const auto in_simplex = [&](int dim) {
        return xi.head(dim).minCoeff() >= -tolerance && xi.head(dim).sum() <= upper;
    };
    switch (family) {
        case GeometryFamily::Point: return true;
        case GeometryFamily::Linear: return in_cube(1);
        case GeometryFamily::Quadrilateral: return in_cube(2);
        case GeometryFamily::Hexahedra: return in_cube(3);
        case GeometryFamily::Triangle: return in_simplex(2);
        case GeometryFamily::Tetrahedra: return in_simplex(3);
        case GeometryFamily::Prism: return in_simplex(2) && xi[2] >= -tolerance && xi[2] <= upper;
    }
    return false;
}

Array3 Pad(const Matrix& J, int column) {
    Array3 result = Array3::Zero();
    result.head(J.rows()) = J.col(column);
    return result;
}

}  // namespace

Geometry::Geometry(PointsArrayType points, std::size_t required_points, const std::string& name)
    : mPoints(std::move(points)) {
    CONTACT_CHECK(mPoints.size() == required_points, InputError, name, " needs ", required_points,
                  " nodes, got ", mPoints.size(), "\n  expected: ", required_points,
                  " nodes in Kratos/GiD order\n  fix: pass exactly ", required_points,
                  " nodes, or choose the geometry type that matches the element's node count");
    for (std::size_t i = 0; i < mPoints.size(); ++i)
        CONTACT_CHECK(mPoints[i] != nullptr, InputError, name, ": node pointer ", i,
                      " is null\n  fix: create every node (e.g. through the model part) before the geometry");
}

Node::Pointer Geometry::pGetPoint(std::size_t i) const {
    CONTACT_CHECK(i < mPoints.size(), InputError, "node index ", i, " out of range for ", Name(), " ",
                  NodeIdsString(), "\n  expected: an index below ", mPoints.size(),
                  "\n  fix: use a local node index (0-based)");
    return mPoints[i];
}

std::string Geometry::NodeIdsString() const {
    std::ostringstream stream;
    stream << "[";
    for (std::size_t i = 0; i < mPoints.size(); ++i) stream << (i ? ", " : "") << mPoints[i]->Id();
    stream << "]";
    return stream.str();
}

double Geometry::ShapeFunctionValue(std::size_t i, const Array3& local) const {
    CONTACT_CHECK(i < mPoints.size(), InputError, "shape function index ", i, " out of range for ", Name(),
                  " (", mPoints.size(), " nodes)\n  fix: use a local node index below ", mPoints.size());
    Vector N;
    ShapeFunctionsValues(N, local);
    return N[static_cast<Eigen::Index>(i)];
}

void Geometry::Jacobian(Matrix& rJ, const Array3& local, Configuration configuration) const {
    const int working_dim = WorkingSpaceDimension();
    Matrix DN;
    ShapeFunctionsLocalGradients(DN, local);
    rJ.setZero(working_dim, DN.cols());
    for (std::size_t k = 0; k < mPoints.size(); ++k)
        rJ += NodeCoordinates(*mPoints[k], configuration).head(working_dim) *
              DN.row(static_cast<Eigen::Index>(k));
}

double Geometry::DeterminantOfJacobian(const Array3& local, Configuration configuration) const {
    Matrix J;
    Jacobian(J, local, configuration);
    if (J.cols() == 0) return 1.0;  // a point: counting measure, so a point rule evaluates the integrand
    if (J.rows() == J.cols()) return J.determinant();
    if (J.cols() == 1) return J.norm();
    return Pad(J, 0).cross(Pad(J, 1)).norm();
}

void Geometry::InverseOfJacobian(Matrix& rInverse, const Array3& local, Configuration configuration) const {
    Matrix J;
    Jacobian(J, local, configuration);
    CONTACT_CHECK(
        J.rows() == J.cols() && J.cols() > 0, InputError, "InverseOfJacobian needs a square Jacobian; ", Name(),
        " ", NodeIdsString(), " has a ", J.rows(), "×", J.cols(),
        " one\n  fix: use DeterminantOfJacobian() / UnitNormal() for lines and surfaces in higher space");
    const double det = J.determinant();
    const double scale = std::pow(J.norm(), static_cast<double>(J.cols()));
    CONTACT_CHECK(det > 1e-12 * scale, InputError, Name(), " with nodes ", NodeIdsString(),
                  (det < 0.0 ? " is inverted" : " is degenerate"), " at local point ", Format(local),
                  ": det J = ", det, "\n  expected: det J > 0\n  fix: ",
                  (det < 0.0 ? "reorder the element's nodes (Kratos/GiD orientation)"
                             : "remove the collapsed element or move its coincident/collinear nodes"));
    rInverse = J.inverse();
}

Array3 Geometry::GlobalCoordinates(const Array3& local, Configuration configuration) const {
    Vector N;
    ShapeFunctionsValues(N, local);
    const int working_dim = WorkingSpaceDimension();
    Array3 x = Array3::Zero();
    for (std::size_t k = 0; k < mPoints.size(); ++k)
        x.head(working_dim) +=
            N[static_cast<Eigen::Index>(k)] * NodeCoordinates(*mPoints[k], configuration).head(working_dim);
    return x;
}

Geometry::NewtonStatus Geometry::SolveLocalCoordinates(const Array3& global, Array3& rLocal) const {
    const int working_dim = WorkingSpaceDimension();
    const int local_dim = LocalSpaceDimension();
    rLocal = ReferenceCenter(Family());
    if (local_dim == 0) return NewtonStatus::Converged;
    Matrix J;
    bool close = false;
    for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
        Jacobian(J, rLocal);
        const Matrix JtJ = J.transpose() * J;
        const double mean = JtJ.trace() / local_dim;
        // Singular at the centroid: the geometry is degenerate. Later (an iterate outside a distorted
        // element may hit a fold of the extrapolated map): the point is just not reachable.
        if (!(mean > 0.0) || JtJ.determinant() <= kSingularRatio * std::pow(mean, local_dim))
            return iteration == 0 ? NewtonStatus::Singular : NewtonStatus::NotConverged;
        const Vector residual = (global - GlobalCoordinates(rLocal)).head(working_dim);
        // Square J: Newton; rectangular J: Gauss–Newton, i.e. the least-squares (closest point) step.
        const Vector step = J.colPivHouseholderQr().solve(residual);
        rLocal.head(local_dim) += step;
        if (!rLocal.allFinite() || rLocal.norm() > 1e6) return NewtonStatus::NotConverged;
        if (close) return NewtonStatus::Converged;
        close = step.lpNorm<Eigen::Infinity>() < kNewtonCloseTolerance;
    }
    return NewtonStatus::NotConverged;
}

Array3 Geometry::PointLocalCoordinates(const Array3& global) const {
    Array3 local;
    const NewtonStatus status = SolveLocalCoordinates(global, local);
    CONTACT_CHECK(status != NewtonStatus::Singular, InputError, "cannot compute local coordinates of point ",
                  Format(global), " in ", Name(), " with nodes ", NodeIdsString(),
                  ": the Jacobian is singular (zero length/area/volume)\n  expected: a non-degenerate geometry",
                  "\n  fix: remove the collapsed element or separate its coincident/collinear nodes");
    CONTACT_CHECK(
        status == NewtonStatus::Converged, InputError, "local coordinates of point ", Format(global), " in ",
        Name(), " with nodes ", NodeIdsString(), " did not converge in ", kMaxNewtonIterations,
        " Newton iterations (last iterate ", Format(local),
        ")\n  expected: a point inside or near the geometry\n  fix: call IsInside() for points that may be"
        " far away, or check the element for severe distortion");
    return local;
}

bool Geometry::IsInside(const Array3& global, Array3& rLocal, double tolerance) const {
    if (LocalSpaceDimension() == 0) {
        rLocal.setZero();
        return (global - mPoints.front()->Coordinates()).norm() <= tolerance;
    }
    const NewtonStatus status = SolveLocalCoordinates(global, rLocal);
    if (status == NewtonStatus::Singular) PointLocalCoordinates(global);  // throws the explanatory error
    return status == NewtonStatus::Converged && IsInsideReference(Family(), rLocal, tolerance);
}

const std::vector<IntegrationPoint>& Geometry::IntegrationPoints(int order) const {
    return GaussRule(Family(), order);
}

void Geometry::ThrowNotDefined(const char* method, const char* expected) const {
    CONTACT_THROW(InputError, method, "() is not defined for ", Name(), " with nodes ", NodeIdsString(),
                  " (local dimension ", LocalSpaceDimension(), ")\n  expected: ", expected,
                  "\n  fix: use DomainSize() for the measure of any geometry, or the faces "
                  "(LocalFacesConnectivity()) of a solid for normals");
}

double Geometry::Length() const {
    if (LocalSpaceDimension() != 1) ThrowNotDefined("Length", "a line (local dimension 1)");
    return DomainSize();
}

double Geometry::Area() const {
    if (LocalSpaceDimension() != 2) ThrowNotDefined("Area", "a surface (local dimension 2)");
    return DomainSize();
}

double Geometry::Volume() const {
    if (LocalSpaceDimension() != 3) ThrowNotDefined("Volume", "a solid (local dimension 3)");
    return DomainSize();
}

double Geometry::DomainSize() const {
    if (LocalSpaceDimension() == 0) return 0.0;
    double measure = 0.0;
    for (const auto& point : IntegrationPoints(MeasureIntegrationOrder()))
        measure += point.weight * DeterminantOfJacobian(point.local);
    return measure;
}

Array3 Geometry::Center() const {
    Array3 center = Array3::Zero();
    for (const auto& node : mPoints) center += node->Coordinates();
    return center / static_cast<double>(mPoints.size());
}

Array3 Geometry::Normal(const Array3& local) const {
    const int local_dim = LocalSpaceDimension();
    if (local_dim != 1 && local_dim != 2) ThrowNotDefined("Normal", "a line or a surface");
    Matrix J;
    Jacobian(J, local);
    if (local_dim == 1) return Pad(J, 0).cross(Array3::UnitZ());
    return Pad(J, 0).cross(Pad(J, 1));
}

Array3 Geometry::UnitNormal(const Array3& local) const {
    const Array3 normal = Normal(local);
    const double norm = normal.norm();
    CONTACT_CHECK(norm > 0.0, InputError, "UnitNormal(): ", Name(), " with nodes ", NodeIdsString(),
                  " has a zero normal at local point ", Format(local),
                  "\n  expected: a non-degenerate geometry (lines must not be parallel to z)"
                  "\n  fix: remove the collapsed element or separate its coincident/collinear nodes");
    return normal / norm;
}

Geometry::Pointer Geometry::pGetGeometryPart(std::size_t index) const {
    CONTACT_THROW(InputError, "geometry part ", index, " requested from ", Name(), " with nodes ",
                  NodeIdsString(),
                  ", which has no geometry parts\n  expected: a CouplingGeometry (paired "
                  "condition)\n  fix: check NumberOfGeometryParts() before asking for a part");
}

}  // namespace contact_app
