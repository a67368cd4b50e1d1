// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/entity.h"

#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/node.h"
#include "contact_app/kernel/serializer.h"

namespace contact_app {

template <class TDerived>
const char* Entity<TDerived>::KindName() {
    return std::is_same_v<TDerived, Element> ? "element" : "condition";
}

template <class TDerived>
Entity<TDerived>::Entity(IndexType id, Geometry::Pointer geometry, Properties::Pointer properties)
    : mId(id), mGeometry(std::move(geometry)), mProperties(std::move(properties)) {
    CONTACT_CHECK(mGeometry != nullptr, InternalError, KindName(), " ", id, " created without a geometry");
}

template <class TDerived>
typename Entity<TDerived>::Pointer Entity<TDerived>::Create(IndexType new_id, const NodesArrayType& nodes,
                                                            Properties::Pointer properties) const {
    return Create(new_id, mGeometry->Create(nodes), std::move(properties));
}

template <class TDerived>
typename Entity<TDerived>::Pointer Entity<TDerived>::Create(IndexType new_id, Geometry::Pointer geometry,
                                                            Properties::Pointer properties) const {
    return std::make_shared<TDerived>(new_id, std::move(geometry), std::move(properties));
}

template <class TDerived>
Properties& Entity<TDerived>::GetProperties() const {
    CONTACT_CHECK(mProperties != nullptr, InputError, KindName(), " ", mId, " has no properties",
                  "\n  fix: give it a property id in the mdpa file or assign materials to its model part");
    return *mProperties;
}

template <class TDerived>
void Entity<TDerived>::Initialize(const ProcessInfo&) {}
template <class TDerived>
void Entity<TDerived>::InitializeSolutionStep(const ProcessInfo&) {}
template <class TDerived>
void Entity<TDerived>::InitializeNonLinearIteration(const ProcessInfo&) {}
template <class TDerived>
void Entity<TDerived>::FinalizeNonLinearIteration(const ProcessInfo&) {}
template <class TDerived>
void Entity<TDerived>::FinalizeSolutionStep(const ProcessInfo&) {}

template <class TDerived>
void Entity<TDerived>::CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                                            const ProcessInfo&) {
    rLeftHandSideMatrix.resize(0, 0);
    rRightHandSideVector.resize(0);
}

template <class TDerived>
void Entity<TDerived>::CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo) {
    Vector rhs;
    CalculateLocalSystem(rLeftHandSideMatrix, rhs, rCurrentProcessInfo);
}

template <class TDerived>
void Entity<TDerived>::CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo) {
    Matrix lhs;
    CalculateLocalSystem(lhs, rRightHandSideVector, rCurrentProcessInfo);
}

template <class TDerived>
void Entity<TDerived>::CalculateMassMatrix(Matrix& rMassMatrix, const ProcessInfo&) {
    rMassMatrix.resize(0, 0);
}

template <class TDerived>
void Entity<TDerived>::CalculateDampingMatrix(Matrix& rDampingMatrix, const ProcessInfo&) {
    rDampingMatrix.resize(0, 0);
}

template <class TDerived>
void Entity<TDerived>::EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo&) const {
    rResult.clear();
}

template <class TDerived>
void Entity<TDerived>::GetDofList(DofsVectorType& rElementalDofList, const ProcessInfo&) const {
    rElementalDofList.clear();
}

template <class TDerived>
void Entity<TDerived>::GetValuesVector(Vector& rValues, int) const {
    rValues.resize(0);
}
template <class TDerived>
void Entity<TDerived>::GetFirstDerivativesVector(Vector& rValues, int) const {
    rValues.resize(0);
}
template <class TDerived>
void Entity<TDerived>::GetSecondDerivativesVector(Vector& rValues, int) const {
    rValues.resize(0);
}

template <class TDerived>
void Entity<TDerived>::AddExplicitContribution(const ProcessInfo&) {}

namespace {
template <class TEntity, class TValue>
void NoIntegrationPointResult(const TEntity& entity, const VariableData& variable, std::vector<TValue>&) {
    CONTACT_THROW(InputError, entity.Info(), " cannot compute ", variable.Name(), " on its integration points",
                  "\n  fix: remove ", variable.Name(), " from the gauss_point_results of the output");
}
}  // namespace

template <class TDerived>
void Entity<TDerived>::CalculateOnIntegrationPoints(const Variable<double>& rVariable, std::vector<double>& rOutput,
                                                    const ProcessInfo&) {
    NoIntegrationPointResult(*this, rVariable, rOutput);
}
template <class TDerived>
void Entity<TDerived>::CalculateOnIntegrationPoints(const Variable<Array3>& rVariable, std::vector<Array3>& rOutput,
                                                    const ProcessInfo&) {
    NoIntegrationPointResult(*this, rVariable, rOutput);
}
template <class TDerived>
void Entity<TDerived>::CalculateOnIntegrationPoints(const Variable<Vector>& rVariable, std::vector<Vector>& rOutput,
                                                    const ProcessInfo&) {
    NoIntegrationPointResult(*this, rVariable, rOutput);
}
template <class TDerived>
void Entity<TDerived>::CalculateOnIntegrationPoints(const Variable<Matrix>& rVariable, std::vector<Matrix>& rOutput,
                                                    const ProcessInfo&) {
    NoIntegrationPointResult(*this, rVariable, rOutput);
}

template <class TDerived>
int Entity<TDerived>::Check(const ProcessInfo&) const {
    CONTACT_CHECK(mId >= 1, InputError, KindName(), " id ", mId, " is invalid\n  expected: ids start at 1");
    if (mGeometry->LocalSpaceDimension() > 0) {
        const double size = mGeometry->DomainSize();
        std::string ids;
        for (std::size_t i = 0; i < mGeometry->PointsNumber(); ++i) ids += " " + std::to_string((*mGeometry)[i].Id());
        CONTACT_CHECK(size > 0.0, InputError, Info(), " has a non-positive domain size ", size, " (nodes", ids, ")",
                      "\n  fix: check the node coordinates and the connectivity order");
    }
    return 0;
}

template <class TDerived>
std::string Entity<TDerived>::Info() const {
    std::string kind = KindName();
    kind[0] = static_cast<char>(std::toupper(kind[0]));
    return kind + " #" + std::to_string(mId) + " (" + mGeometry->Name() + ")";
}

template <class TDerived>
void Entity<TDerived>::Save(Serializer& rSerializer) const {
    rSerializer.Save("Id", mId);
    rSerializer.Save("FlagsDefined", static_cast<std::size_t>(DefinedBits()));
    rSerializer.Save("FlagsValues", static_cast<std::size_t>(ValueBits()));
}

template <class TDerived>
void Entity<TDerived>::Load(Serializer& rSerializer) {
    std::size_t defined = 0, values = 0;
    rSerializer.Load("Id", mId);
    rSerializer.Load("FlagsDefined", defined);
    rSerializer.Load("FlagsValues", values);
    Clear();
    for (int bit = 0; bit < 64; ++bit)
        if ((defined >> bit) & 1u) Set(Flags::Create(bit), ((values >> bit) & 1u) != 0);
}

template class Entity<Element>;
template class Entity<Condition>;

}  // namespace contact_app
