// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "contact_app/kernel/geometries/quadrature.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/types.h"

namespace contact_app {

/// Abstract finite-element geometry (Kratos `Geometry<Node>`): ordered nodes plus the reference element's
/// shape functions N_k(ξ). Everything else is generic on ShapeFunctionsValues / ShapeFunctionsLocalGradients:
/// x(ξ) = Σ_k N_k(ξ) x_k, J_ij = Σ_k x_k,i ∂N_k/∂ξ_j (working_dim × local_dim), determinants, measures,
/// normals and the global → local map (Newton / Gauss–Newton).
/// Ownership: nodes are shared with the model parts (std::shared_ptr), never copied, so moving a node moves
/// the geometry. Configuration::Initial uses Node::InitialCoordinates(). Only the first
/// WorkingSpaceDimension() components of a node's coordinates are used. Node orderings are Kratos/GiD ones.
/// Concrete types: Point3D, Line2D2, Line3D2, Line2D3, Triangle2D3, Triangle3D3, Triangle2D6,
/// Quadrilateral2D4, Quadrilateral3D4, Tetrahedra3D4, Tetrahedra3D10, Hexahedra3D8, Prism3D6
/// (CreateGeometry() builds them by name), and CouplingGeometry.
class Geometry {
public:
    using Pointer = std::shared_ptr<Geometry>;
    using PointsArrayType = std::vector<Node::Pointer>;
    /// Which node coordinates a mapping uses: Node::Coordinates() or Node::InitialCoordinates().
    enum class Configuration { Current, Initial };

    virtual ~Geometry() = default;

    /// @brief New geometry of the same type on @p points (the nodes are shared, not copied).
    /// @throws InputError if the node count is wrong or a pointer is null
    virtual Pointer Create(PointsArrayType points) const = 0;
    /// @brief Kratos name of the geometry type, e.g. "Triangle2D3".
    virtual std::string Name() const = 0;
    virtual GeometryFamily Family() const = 0;
    /// @brief Dimension of the space the nodes live in (2 or 3).
    virtual int WorkingSpaceDimension() const = 0;
    /// @brief Dimension of the reference element (0 point, 1 line, 2 surface, 3 solid).
    virtual int LocalSpaceDimension() const = 0;

    std::size_t PointsNumber() const { return mPoints.size(); }
    std::size_t size() const { return mPoints.size(); }
    /// @brief Node @p i, unchecked (hot path).
    Node& operator[](std::size_t i) { return *mPoints[i]; }
    const Node& operator[](std::size_t i) const { return *mPoints[i]; }
    /// @brief Shared pointer to node @p i. @throws InputError if @p i ≥ PointsNumber()
    Node::Pointer pGetPoint(std::size_t i) const;
    const PointsArrayType& Points() const { return mPoints; }

    // -- Shape functions on the reference element --

    /// @brief N_i(ξ). @throws InputError if @p i ≥ PointsNumber()
    virtual double ShapeFunctionValue(std::size_t i, const Array3& local) const;
    /// @param[out] rN n_nodes values N_k(ξ), resized here
    /// @param[in] local ξ (components beyond LocalSpaceDimension() are ignored)
    virtual void ShapeFunctionsValues(Vector& rN, const Array3& local) const = 0;
    /// @param[out] rDN n_nodes × local_dim matrix ∂N_k/∂ξ_j, resized here
    virtual void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const = 0;
    /// @brief Local coordinates of the nodes (Kratos signature).
    /// @param[out] rResult n_nodes × local_dim, resized here
    virtual Matrix& PointsLocalCoordinates(Matrix& rResult) const = 0;

    // -- Mapping between the reference element and space --

    /// @param[out] rJ working_dim × local_dim, J_ij = Σ_k x_k,i ∂N_k/∂ξ_j, resized here
    void Jacobian(Matrix& rJ, const Array3& local,
                  Configuration configuration = Configuration::Current) const;
    /// @brief Square J: det J (signed); line: |J|; surface in 3D: |J_0 × J_1|; point: 1.
    double DeterminantOfJacobian(const Array3& local,
                                 Configuration configuration = Configuration::Current) const;
    /// @param[out] rInverse local_dim × working_dim inverse of a square Jacobian, resized here
    /// @throws InputError if J is not square, singular or inverted (det J ≤ 0); names the node ids
    void InverseOfJacobian(Matrix& rInverse, const Array3& local,
                           Configuration configuration = Configuration::Current) const;
    /// @brief x(ξ) = Σ_k N_k(ξ) x_k (z = 0 for 2D geometries).
    Array3 GlobalCoordinates(const Array3& local, Configuration configuration = Configuration::Current) const;
    /// @brief ξ with x(ξ) = @p global (current configuration): Newton for solids and 2D surfaces, exact for
    ///        linear simplices; Gauss–Newton (closest point / projection) for lines and surfaces in 3D.
    /// @throws InputError if the geometry is degenerate or Newton does not converge (names point and node
    /// ids)
    Array3 PointLocalCoordinates(const Array3& global) const;
    /// @brief Parametric inside test of PointLocalCoordinates(@p global) (lines/surfaces in 3D: of the
    ///        projection; the distance to the geometry is not checked). A point is inside its own node.
    /// @param[out] rLocal the local coordinates (meaningless when Newton diverged and false is returned)
    /// @param[in] tolerance slack on the reference-element bounds, in local units
    /// @throws InputError if the geometry is degenerate
    bool IsInside(const Array3& global, Array3& rLocal, double tolerance = 1e-9) const;

    // -- Integration --

    /// @brief GaussRule(Family(), @p order). @throws InputError if @p order is outside 1..5
    const std::vector<IntegrationPoint>& IntegrationPoints(int order) const;
    /// @brief Kratos default order: Line2D2/3D2, Triangle3, Tet4: 1; Line2D3, Triangle6, Quad4, Tet10,
    /// Prism6,
    ///        Hex8: 2; Point3D: 1.
    virtual int DefaultIntegrationOrder() const = 0;

    // -- Measures and normals (virtual so CouplingGeometry can delegate) --

    /// @brief Length of a line. @throws InputError if LocalSpaceDimension() != 1 (use DomainSize())
    virtual double Length() const;
    /// @brief Area of a surface. @throws InputError if LocalSpaceDimension() != 2 (use DomainSize())
    virtual double Area() const;
    /// @brief Volume of a solid. @throws InputError if LocalSpaceDimension() != 3 (use DomainSize())
    virtual double Volume() const;
    /// @brief ∫ det J dξ by LocalSpaceDimension(): length, area or volume (0 for a point). Signed (negative
    ///        when inverted) for full-dimensional geometries, as Kratos; exact for straight/planar and
    ///        polynomial-Jacobian geometries, Gauss order 5 for curved lines and warped quadrilaterals.
    virtual double DomainSize() const;
    /// @brief Average of the current node coordinates (Kratos Center()).
    virtual Array3 Center() const;
    /// @brief Lines: J_0 × e_z = (t_y, −t_x, 0), i.e. the tangent rotated clockwise; surfaces: J_0 × J_1.
    ///        Magnitude det J for 2D lines and 3D surfaces.
    /// @throws InputError for points and solids
    virtual Array3 Normal(const Array3& local) const;
    /// @brief Normal(@p local) / |Normal(@p local)|. @throws InputError for points, solids, degenerate
    /// geometry
    virtual Array3 UnitNormal(const Array3& local) const;

    // -- Boundary topology --

    /// @brief Local node indices of each boundary entity of dimension local_dim − 1: faces of solids ordered
    ///        so that (x_1 − x_0) × (x_2 − x_0) points out; edges of surfaces counter-clockwise, so that the
    ///        line normal (tangent rotated clockwise) points out; the two end points of lines.
    ///        Simplices list the face opposite node i at position i (as Kratos); quadratic entities list the
    ///        corner nodes first, then the mid-side nodes (Line2D3 / Triangle2D6 ordering).
    virtual std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const = 0;
    std::size_t FacesNumber() const { return LocalFacesConnectivity().size(); }

    // -- Geometry parts (only CouplingGeometry has any) --

    virtual std::size_t NumberOfGeometryParts() const { return 0; }
    /// @brief Part @p index (0 slave/parent, 1 master/paired). @throws InputError if there is no such part
    virtual Geometry& GetGeometryPart(std::size_t index);
    virtual const Geometry& GetGeometryPart(std::size_t index) const;
    /// @brief Shared pointer to part @p index. @throws InputError if there is no such part
    virtual Pointer pGetGeometryPart(std::size_t index) const;

    /// @brief Node ids as "[1, 2, 3]", for messages.
    std::string NodeIdsString() const;

protected:
    /// @param[in] points the nodes (shared ownership)
    /// @param[in] required_points node count of the concrete type, @p name its Kratos name (for the message)
    /// @throws InputError if the count is wrong or a pointer is null
    Geometry(PointsArrayType points, std::size_t required_points, const std::string& name);
    /// @brief Gauss order used by DomainSize(); default DefaultIntegrationOrder().
    virtual int MeasureIntegrationOrder() const { return DefaultIntegrationOrder(); }
    void SetPoints(PointsArrayType points) { mPoints = std::move(points); }

private:
    enum class NewtonStatus { Converged, Singular, NotConverged };
    NewtonStatus SolveLocalCoordinates(const Array3& global, Array3& rLocal) const;
    [[noreturn]] void ThrowNotDefined(const char* method, const char* expected) const;

    PointsArrayType mPoints;
};

}  // namespace contact_app
