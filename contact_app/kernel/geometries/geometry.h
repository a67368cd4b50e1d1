// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
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

    /// @brief New geometry of the same type on @p points.
    /// @param[in] points the nodes, shared with the caller (not copied)
    /// @throws InputError if the node count is wrong or a pointer is null
    virtual Pointer Create(PointsArrayType points) const = 0;
    /// @brief Kratos name of the geometry type, e.g. "Triangle2D3".
    virtual std::string Name() const = 0;
    /// @brief Reference-element family (selects the Gauss rules and the inside test).
    virtual GeometryFamily Family() const = 0;
    /// @brief Dimension of the space the nodes live in (2 or 3).
    virtual int WorkingSpaceDimension() const = 0;
    /// @brief Dimension of the reference element (0 point, 1 line, 2 surface, 3 solid).
    virtual int LocalSpaceDimension() const = 0;

    /// @brief Number of nodes.
    std::size_t PointsNumber() const { return mPoints.size(); }
    /// @brief Number of nodes (container-style alias of PointsNumber()).
    std::size_t size() const { return mPoints.size(); }
    /// @brief Node @p i, unchecked (hot path). @param[in] i local node index, 0-based
    Node& operator[](std::size_t i) { return *mPoints[i]; }
    /// @brief Node @p i, unchecked (hot path). @param[in] i local node index, 0-based
    const Node& operator[](std::size_t i) const { return *mPoints[i]; }
    /// @brief Shared pointer to node @p i. @param[in] i local node index, 0-based
    /// @throws InputError if @p i ≥ PointsNumber()
    Node::Pointer pGetPoint(std::size_t i) const;
    /// @brief The nodes, in Kratos/GiD order.
    const PointsArrayType& Points() const { return mPoints; }

    // -- Shape functions on the reference element --

    /// @brief N_i(ξ).
    /// @param[in] i local node index; @param[in] local ξ
    /// @throws InputError if @p i ≥ PointsNumber()
    virtual double ShapeFunctionValue(std::size_t i, const Array3& local) const;
    /// @brief All shape functions at ξ.
    /// @param[out] rN n_nodes values N_k(ξ), resized here
    /// @param[in] local ξ (components beyond LocalSpaceDimension() are ignored)
    virtual void ShapeFunctionsValues(Vector& rN, const Array3& local) const = 0;
    /// @brief Shape-function gradients with respect to the local coordinates.
    /// @param[out] rDN n_nodes × local_dim, ∂N_k/∂ξ_j, resized here
    /// @param[in] local ξ
    virtual void ShapeFunctionsLocalGradients(Matrix& rDN, const Array3& local) const = 0;
    /// @brief Local coordinates of the nodes (Kratos signature).
    /// @param[out] rResult n_nodes × local_dim, resized here
    /// @return @p rResult
    virtual Matrix& PointsLocalCoordinates(Matrix& rResult) const = 0;

    // -- Mapping between the reference element and space --

    /// @brief Jacobian of x(ξ).
    /// @param[out] rJ working_dim × local_dim, J_ij = Σ_k x_k,i ∂N_k/∂ξ_j, resized here
    /// @param[in] local ξ; @param[in] configuration current or initial node coordinates
    void Jacobian(Matrix& rJ, const Array3& local, Configuration configuration = Configuration::Current) const;
    /// @brief Square J: det J (signed); line: |J|; surface in 3D: |J_0 × J_1|; point: 1.
    /// @param[in] local ξ; @param[in] configuration current or initial node coordinates
    double DeterminantOfJacobian(const Array3& local,
                                 Configuration configuration = Configuration::Current) const;
    /// @brief Inverse of a square Jacobian.
    /// @param[out] rInverse local_dim × working_dim, resized here
    /// @param[in] local ξ; @param[in] configuration current or initial node coordinates
    /// @throws InputError if J is not square, singular or inverted (det J ≤ 0); names the node ids
    void InverseOfJacobian(Matrix& rInverse, const Array3& local,
                           Configuration configuration = Configuration::Current) const;
    /// @brief x(ξ) = Σ_k N_k(ξ) x_k (z = 0 for 2D geometries).
    /// @param[in] local ξ; @param[in] configuration current or initial node coordinates
    Array3 GlobalCoordinates(const Array3& local, Configuration configuration = Configuration::Current) const;
    /// @brief ξ with x(ξ) = @p global in the current configuration: Newton for solids and 2D surfaces
    ///        (exact for linear simplices), Gauss–Newton, i.e. the closest point, for lines and surfaces in
    ///        higher space. Starts at the reference centroid; 50 iterations at most.
    /// @param[in] global point in space (components beyond WorkingSpaceDimension() are ignored)
    /// @throws InputError if the geometry is degenerate or Newton does not converge; names point and nodes
    Array3 PointLocalCoordinates(const Array3& global) const;
    /// @brief Parametric inside test of PointLocalCoordinates(@p global); for lines and surfaces in 3D the
    ///        projection is tested and the distance is not checked (as Kratos). A Point3D contains only
    ///        points within @p tolerance of its node.
    /// @param[in] global point in space
    /// @param[out] rLocal its local coordinates (meaningless when Newton diverged and false is returned)
    /// @param[in] tolerance slack on the reference-element bounds, in local units
    /// @throws InputError if the geometry is degenerate
    bool IsInside(const Array3& global, Array3& rLocal, double tolerance = 1e-9) const;

    // -- Integration --

    /// @brief GaussRule(Family(), @p order). @param[in] order Kratos integration order, 1..5
    /// @throws InputError if @p order is outside 1..5
    const std::vector<IntegrationPoint>& IntegrationPoints(int order) const;
    /// @brief Kratos default order: 1 for Point3D, Line2D2, Line3D2, Triangle2D3/3D3, Tetrahedra3D4;
    ///        2 for Line2D3, Triangle2D6, Quadrilateral2D4/3D4, Tetrahedra3D10, Prism3D6, Hexahedra3D8.
    virtual int DefaultIntegrationOrder() const = 0;

    // -- Measures and normals (virtual so CouplingGeometry can delegate) --

    /// @brief Length of a line. @throws InputError if LocalSpaceDimension() != 1 (use DomainSize())
    virtual double Length() const;
    /// @brief Area of a surface. @throws InputError if LocalSpaceDimension() != 2 (use DomainSize())
    virtual double Area() const;
    /// @brief Volume of a solid. @throws InputError if LocalSpaceDimension() != 3 (use DomainSize())
    virtual double Volume() const;
    /// @brief ∫ det J dξ: length, area or volume by LocalSpaceDimension(), 0 for a point. Signed (negative
    ///        when inverted) for full-dimensional geometries, as Kratos. Exact for straight and planar
    ///        geometries and polynomial det J; curved lines and warped quadrilaterals use Gauss order 5.
    virtual double DomainSize() const;
    /// @brief Average of the current node coordinates (Kratos Center()).
    virtual Array3 Center() const;
    /// @brief Non-unit normal. Lines: J_0 × e_z = (t_y, −t_x, 0), the tangent rotated clockwise, of
    ///        magnitude |J|; surfaces: J_0 × J_1, of magnitude det J.
    /// @param[in] local ξ
    /// @throws InputError for points and solids
    virtual Array3 Normal(const Array3& local) const;
    /// @brief Normal(@p local) / |Normal(@p local)|.
    /// @param[in] local ξ
    /// @throws InputError for points, solids and a zero normal (degenerate geometry, line parallel to z)
    virtual Array3 UnitNormal(const Array3& local) const;

    // -- Boundary topology --

    /// @brief Local node indices of each boundary entity of dimension local_dim − 1. Solids: faces ordered
    ///        so that (x_1 − x_0) × (x_2 − x_0) points out. Surfaces: edges counter-clockwise, so the line
    ///        normal (tangent rotated clockwise) points out. Lines: the two end points. Simplices list the
    ///        entity opposite node i at position i (as Kratos); quadratic entities list corners first, then
    ///        mid-side nodes (Line2D3 / Triangle2D6 order).
    virtual std::vector<std::vector<std::size_t>> LocalFacesConnectivity() const = 0;
    /// @brief LocalFacesConnectivity().size().
    std::size_t FacesNumber() const { return LocalFacesConnectivity().size(); }

    // -- Geometry parts (only CouplingGeometry has any) --

    /// @brief Number of geometry parts: 0, or 2 for a CouplingGeometry.
    virtual std::size_t NumberOfGeometryParts() const { return 0; }
    /// @brief Shared pointer to part @p index (0 slave/parent, 1 master/paired).
    /// @param[in] index part index
    /// @throws InputError if there is no such part
    virtual Pointer pGetGeometryPart(std::size_t index) const;
    /// @brief Part @p index, as pGetGeometryPart(). @param[in] index part index
    /// @throws InputError if there is no such part
    Geometry& GetGeometryPart(std::size_t index) { return *pGetGeometryPart(index); }
    /// @brief Part @p index, as pGetGeometryPart(). @param[in] index part index
    /// @throws InputError if there is no such part
    const Geometry& GetGeometryPart(std::size_t index) const { return *pGetGeometryPart(index); }

    /// @brief Node ids as "[1, 2, 3]", for messages.
    std::string NodeIdsString() const;

protected:
    /// @param[in] points the nodes (shared ownership)
    /// @param[in] required_points node count of the concrete type
    /// @param[in] name Kratos name of the concrete type, for the message
    /// @throws InputError if the count is wrong or a pointer is null
    Geometry(PointsArrayType points, std::size_t required_points, const std::string& name);
    /// @brief Gauss order DomainSize() integrates with; default DefaultIntegrationOrder().
    virtual int MeasureIntegrationOrder() const { return DefaultIntegrationOrder(); }
    /// @brief Replaces the nodes (CouplingGeometry follows its part 0). @param[in] points the new nodes
    void SetPoints(PointsArrayType points) { mPoints = std::move(points); }

private:
    enum class NewtonStatus { Converged, Singular, NotConverged };
    NewtonStatus SolveLocalCoordinates(const Array3& global, Array3& rLocal) const;
    [[noreturn]] void ThrowNotDefined(const char* method, const char* expected) const;

    PointsArrayType mPoints;
};

}  // namespace contact_app
