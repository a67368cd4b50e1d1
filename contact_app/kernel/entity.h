// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "contact_app/kernel/data_value_holder.h"
#include "contact_app/kernel/dof.h"
#include "contact_app/kernel/flags.h"
#include "contact_app/kernel/geometries/geometry.h"
#include "contact_app/kernel/process_info.h"
#include "contact_app/kernel/properties.h"

namespace contact_app {

class Serializer;

/// The finite-element interface shared by Element and Condition (Kratos Element/Condition API):
/// id, geometry, properties, flags, non-historical values and the life-cycle hooks a solver calls.
/// The base implementation contributes nothing (a "mesh" entity): empty DoF list, 0×0 local
/// system. @tparam TDerived Element or Condition, the type Create() returns.
template <class TDerived>
class Entity : public Flags, public DataValueHolder {
public:
    using Pointer = std::shared_ptr<TDerived>;
    using GeometryType = Geometry;
    using NodesArrayType = Geometry::PointsArrayType;

    /// @param[in] id         element or condition Id (unique in its model part tree)
    /// @param[in] geometry   shared with the model part (not null)
    /// @param[in] properties may be null until the materials are read
    Entity(IndexType id, Geometry::Pointer geometry, Properties::Pointer properties = nullptr);
    virtual ~Entity() = default;

    /// A new entity of the same class on @p nodes (the geometry type of this prototype).
    /// @throws InputError if the node count does not fit the geometry.
    virtual Pointer Create(IndexType new_id, const NodesArrayType& nodes, Properties::Pointer properties) const;
    /// A new entity of the same class on @p geometry.
    virtual Pointer Create(IndexType new_id, Geometry::Pointer geometry, Properties::Pointer properties) const;

    IndexType Id() const { return mId; }
    void SetId(IndexType id) { mId = id; }
    Geometry& GetGeometry() { return *mGeometry; }
    const Geometry& GetGeometry() const { return *mGeometry; }
    const Geometry::Pointer& pGetGeometry() const { return mGeometry; }
    /// @throws InputError if no properties were assigned.
    Properties& GetProperties() const;
    const Properties::Pointer& pGetProperties() const { return mProperties; }
    void SetProperties(Properties::Pointer properties) { mProperties = std::move(properties); }

    // -- Life cycle --
    virtual void Initialize(const ProcessInfo& rCurrentProcessInfo);
    virtual void InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo);
    virtual void InitializeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo);
    virtual void FinalizeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo);
    virtual void FinalizeSolutionStep(const ProcessInfo& rCurrentProcessInfo);

    // -- Local system; sizes are set by the callee --
    virtual void CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                                      const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateMassMatrix(Matrix& rMassMatrix, const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateDampingMatrix(Matrix& rDampingMatrix, const ProcessInfo& rCurrentProcessInfo);
    virtual void EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo& rCurrentProcessInfo) const;
    virtual void GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo& rCurrentProcessInfo) const;
    /// DoF values (step @p Step) in local-system order; derivatives for dynamic schemes.
    virtual void GetValuesVector(Vector& rValues, int Step = 0) const;
    virtual void GetFirstDerivativesVector(Vector& rValues, int Step = 0) const;
    virtual void GetSecondDerivativesVector(Vector& rValues, int Step = 0) const;
    /// Explicit nodal contributions (weighted gaps, nodal areas, ...); the only place besides
    /// processes where entities write nodal data.
    virtual void AddExplicitContribution(const ProcessInfo& rCurrentProcessInfo);

    // -- Results at integration points (one entry per point) --
    virtual void CalculateOnIntegrationPoints(const Variable<double>& rVariable, std::vector<double>& rOutput,
                                              const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateOnIntegrationPoints(const Variable<Array3>& rVariable, std::vector<Array3>& rOutput,
                                              const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateOnIntegrationPoints(const Variable<Vector>& rVariable, std::vector<Vector>& rOutput,
                                              const ProcessInfo& rCurrentProcessInfo);
    virtual void CalculateOnIntegrationPoints(const Variable<Matrix>& rVariable, std::vector<Matrix>& rOutput,
                                              const ProcessInfo& rCurrentProcessInfo);

    /// Verifies what the entity needs (variables, DoFs, properties, geometry). Returns 0 or throws
    /// InputError with the entity id and the missing item.
    virtual int Check(const ProcessInfo& rCurrentProcessInfo) const;
    /// Short description, e.g. `Element #3 (Quadrilateral2D4)`.
    virtual std::string Info() const;

    // -- Restart state (Kratos save/load). The base stores the id and the flags; geometry, properties and
    //    non-historical values belong to the model part. Derived classes append their members after it. --
    virtual void Save(Serializer& rSerializer) const;
    /// @throws InputError if the buffer was not written by Save() of the same class
    virtual void Load(Serializer& rSerializer);

protected:
    /// Kind name used in messages ("element" / "condition").
    static const char* KindName();

private:
    IndexType mId;
    Geometry::Pointer mGeometry;
    Properties::Pointer mProperties;
};

}  // namespace contact_app
