// SPDX-License-Identifier: BSD-3-Clause
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/geometries/geometry_factory.h"

namespace contact_app::bindings {

namespace {

using Config = Geometry::Configuration;

/// Local or global coordinates given with 1 to 3 components, padded with zeros (ξ, η → (ξ, η, 0)).
Array3 Point(const Vector& coordinates) {
    CONTACT_CHECK(coordinates.size() >= 1 && coordinates.size() <= 3, InputError,
                  "a point needs 1 to 3 coordinates, got ", coordinates.size());
    Array3 point = Array3::Zero();
    point.head(coordinates.size()) = coordinates;
    return point;
}

Node::Pointer NodeAt(const Geometry& self, long index) {
    const long count = static_cast<long>(self.PointsNumber());
    if (index < 0) index += count;
    if (index < 0 || index >= count) throw py::index_error("node index out of range for " + self.Name());
    return self.pGetPoint(static_cast<std::size_t>(index));
}

py::list IntegrationPointList(const Geometry& self, int order) {
    py::list points;
    for (const IntegrationPoint& point : self.IntegrationPoints(order))
        points.append(py::make_tuple(point.local, point.weight));
    return points;
}

}  // namespace

void BindGeometries(py::module_& m) {
    py::class_<Geometry, std::shared_ptr<Geometry>> geometry(m, "Geometry",
                                                             "A finite-element geometry: nodes and shape functions.");
    py::enum_<Config>(geometry, "Configuration", "Which node coordinates a mapping uses.")
        .value("Current", Config::Current)
        .value("Initial", Config::Initial);
    // The default's description is a Python expression (the enum's repr is not), for help() and the stubs.
    const auto current = py::arg_v("configuration", Config::Current, "Geometry.Configuration.Current");

    geometry.def("Name", &Geometry::Name, "Kratos name of the geometry type (\"Quadrilateral2D4\").")
        .def("PointsNumber", &Geometry::PointsNumber, "Number of nodes.")
        .def("__len__", &Geometry::PointsNumber, "Number of nodes.")
        .def("__getitem__", &NodeAt, py::arg("index"), "Node index (negative counts from the end).")
        .def(
            "__iter__", [](const Geometry& self) { return py::iter(py::cast(self.Points())); },
            "Iterates over the nodes.")
        .def("WorkingSpaceDimension", &Geometry::WorkingSpaceDimension, "Dimension of the space of the nodes (2 or 3).")
        .def("LocalSpaceDimension", &Geometry::LocalSpaceDimension, "Dimension of the reference element (0..3).")
        .def("Length", &Geometry::Length, "Length of a line.")
        .def("Area", &Geometry::Area, "Area of a surface.")
        .def("Volume", &Geometry::Volume, "Volume of a solid.")
        .def("DomainSize", &Geometry::DomainSize, "Length, area or volume by local dimension.")
        .def("Center", &Geometry::Center, "Average of the current node coordinates.")
        .def(
            "Normal", [](const Geometry& self, const Vector& local) { return self.Normal(Point(local)); },
            py::arg("local"), "Normal at local coordinates (magnitude det J).")
        .def(
            "UnitNormal", [](const Geometry& self, const Vector& local) { return self.UnitNormal(Point(local)); },
            py::arg("local"), "Unit normal at local coordinates.")
        .def(
            "ShapeFunctionValue",
            [](const Geometry& self, std::size_t i, const Vector& local) {
                return self.ShapeFunctionValue(i, Point(local));
            },
            py::arg("index"), py::arg("local"), "N_index(local).")
        .def(
            "ShapeFunctionsValues",
            [](const Geometry& self, const Vector& local) {
                Vector values;
                self.ShapeFunctionsValues(values, Point(local));
                return values;
            },
            py::arg("local"), "N_k(local) for every node.")
        .def(
            "ShapeFunctionsLocalGradients",
            [](const Geometry& self, const Vector& local) {
                Matrix gradients;
                self.ShapeFunctionsLocalGradients(gradients, Point(local));
                return gradients;
            },
            py::arg("local"), "dN_k/dxi_j (nodes x local dimension).")
        .def(
            "PointsLocalCoordinates",
            [](const Geometry& self) {
                Matrix result;
                return Matrix(self.PointsLocalCoordinates(result));
            },
            "Local coordinates of the nodes (nodes x local dimension).")
        .def(
            "Jacobian",
            [](const Geometry& self, const Vector& local, Config configuration) {
                Matrix jacobian;
                self.Jacobian(jacobian, Point(local), configuration);
                return jacobian;
            },
            py::arg("local"), current, "J (working dimension x local dimension) at local coordinates.")
        .def(
            "DeterminantOfJacobian",
            [](const Geometry& self, const Vector& local, Config configuration) {
                return self.DeterminantOfJacobian(Point(local), configuration);
            },
            py::arg("local"), current, "det J (signed for square J; |J| or |J0 x J1| otherwise).")
        .def(
            "InverseOfJacobian",
            [](const Geometry& self, const Vector& local, Config configuration) {
                Matrix inverse;
                self.InverseOfJacobian(inverse, Point(local), configuration);
                return inverse;
            },
            py::arg("local"), current, "Inverse of a square Jacobian.")
        .def(
            "GlobalCoordinates",
            [](const Geometry& self, const Vector& local, Config configuration) {
                return self.GlobalCoordinates(Point(local), configuration);
            },
            py::arg("local"), current, "x(local) = sum_k N_k(local) x_k.")
        .def(
            "PointLocalCoordinates",
            [](const Geometry& self, const Vector& global) { return self.PointLocalCoordinates(Point(global)); },
            py::arg("global_coordinates"), "Local coordinates of a global point (current configuration).")
        .def(
            "IsInside",
            [](const Geometry& self, const Vector& global, double tolerance) {
                Array3 local = Array3::Zero();
                const bool inside = self.IsInside(Point(global), local, tolerance);
                return std::make_pair(inside, local);
            },
            py::arg("global_coordinates"), py::arg("tolerance") = 1e-9,
            "(inside, local coordinates) of a global point.")
        .def(
            "IntegrationPoints",
            [](const Geometry& self, std::optional<int> order) {
                return IntegrationPointList(self, order ? *order : self.DefaultIntegrationOrder());
            },
            py::arg("order") = py::none(), "Gauss points as (local, weight) tuples (default order if None).")
        .def("DefaultIntegrationOrder", &Geometry::DefaultIntegrationOrder, "Kratos default integration order.")
        .def("LocalFacesConnectivity", &Geometry::LocalFacesConnectivity, "Local node indices of each boundary entity.")
        .def("FacesNumber", &Geometry::FacesNumber, "Number of boundary entities.")
        .def("NumberOfGeometryParts", &Geometry::NumberOfGeometryParts, "Parts of a coupling geometry (0 otherwise).")
        .def("GetGeometryPart", &Geometry::pGetGeometryPart, py::arg("index"), "Part index (0 slave, 1 master).")
        .def(
            "__repr__", [](const Geometry& self) { return "<" + self.Name() + " " + self.NodeIdsString() + ">"; },
            "<Quadrilateral2D4 [1, 2, 3, 4]>.");

    m.def("create_geometry", &CreateGeometry, py::arg("name"), py::arg("nodes"),
          "A geometry of a registered type (\"Triangle2D3\", ...) on nodes.");
}

}  // namespace contact_app::bindings
