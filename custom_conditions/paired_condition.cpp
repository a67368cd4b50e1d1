// SPDX-License-Identifier: BSD-3-Clause
#include "custom_conditions/paired_condition.h"

#include <sstream>

#include "custom_utilities/contact_variables.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/geometries/coupling_geometry.h"
#include "contact_app/kernel/serializer.h"

namespace contact_app {
namespace {

Geometry::Pointer PairGeometry(Geometry::Pointer slave, Geometry::Pointer master) {
    CONTACT_CHECK(slave != nullptr, InputError, "PairedCondition: the slave geometry is null",
                  "\n  fix: pass the slave face of the pair");
    if (!master) return slave;
    return std::make_shared<CouplingGeometry>(std::move(slave), std::move(master));
}

}  // namespace

PairedCondition::PairedCondition(IndexType id, Geometry::Pointer geometry, Properties::Pointer properties)
    : Condition(id, std::move(geometry), std::move(properties)) {}

PairedCondition::PairedCondition(IndexType id, Geometry::Pointer slave, Properties::Pointer properties,
                                 Geometry::Pointer master)
    : Condition(id, PairGeometry(std::move(slave), std::move(master)), std::move(properties)) {}

Condition::Pointer PairedCondition::Create(IndexType new_id, const NodesArrayType& nodes,
                                           Properties::Pointer properties) const {
    return Create(new_id, pGetParentGeometry()->Create(nodes), std::move(properties), nullptr);
}

Condition::Pointer PairedCondition::Create(IndexType new_id, Geometry::Pointer geometry,
                                           Properties::Pointer properties) const {
    if (geometry && geometry->NumberOfGeometryParts() == 2)
        return Create(new_id, geometry->pGetGeometryPart(0), std::move(properties), geometry->pGetGeometryPart(1));
    return Create(new_id, std::move(geometry), std::move(properties), nullptr);
}

Condition::Pointer PairedCondition::Create(IndexType new_id, Geometry::Pointer slave, Properties::Pointer properties,
                                           Geometry::Pointer master) const {
    return std::make_shared<PairedCondition>(new_id, std::move(slave), std::move(properties), std::move(master));
}

Geometry::Pointer PairedCondition::pGetParentGeometry() const {
    return HasPairedGeometry() ? GetGeometry().pGetGeometryPart(0) : pGetGeometry();
}

Geometry::Pointer PairedCondition::pGetPairedGeometry() const {
    CONTACT_CHECK(HasPairedGeometry(), InputError, "condition ", Id(),
                  " has no paired master geometry (YOU HAVE NOT INITIALIZED THE PAIR GEOMETRY)",
                  "\n  expected: a master face assigned by the contact search (Create(id, slave, properties, master))",
                  "\n  fix: do not list contact pair conditions in the .mdpa; let the contact search process build",
                  " them from the slave and master skins");
    return GetGeometry().pGetGeometryPart(1);
}

void PairedCondition::UpdatePairedNormal() {
    if (!HasPairedGeometry()) return;
    mPairedNormal = GetPairedGeometry().UnitNormal(Array3::Zero());
}

void PairedCondition::Initialize(const ProcessInfo& rCurrentProcessInfo) {
    Condition::Initialize(rCurrentProcessInfo);
    UpdatePairedNormal();
}

void PairedCondition::InitializeSolutionStep(const ProcessInfo& rCurrentProcessInfo) {
    Condition::InitializeSolutionStep(rCurrentProcessInfo);
    UpdatePairedNormal();
}

void PairedCondition::InitializeNonLinearIteration(const ProcessInfo& rCurrentProcessInfo) {
    Condition::InitializeNonLinearIteration(rCurrentProcessInfo);
    // 0 = NO_DERIVATIVES_COMPUTATION: the master normal stays the one of the start of the step.
    if (rCurrentProcessInfo.GetValue(CONSIDER_NORMAL_VARIATION) != 0) UpdatePairedNormal();
}

int PairedCondition::Check(const ProcessInfo& rCurrentProcessInfo) const {
    pGetPairedGeometry();  // throws the explanatory message when unpaired
    return Condition::Check(rCurrentProcessInfo);
}

void PairedCondition::Save(Serializer& rSerializer) const {
    Condition::Save(rSerializer);
    rSerializer.Save("PairedNormal", mPairedNormal);
}

void PairedCondition::Load(Serializer& rSerializer) {
    Condition::Load(rSerializer);
    rSerializer.Load("PairedNormal", mPairedNormal);
}

std::string PairedCondition::Info() const { return PairInfo("PairedCondition"); }

std::string PairedCondition::PairInfo(const char* name) const {
    std::ostringstream out;
    out << name << " #" << Id() << " (slave " << GetParentGeometry().Name() << ", master "
        << (HasPairedGeometry() ? GetPairedGeometry().Name() : std::string("none")) << ")";
    return out.str();
}

void PairedCondition::CheckNodeCounts(const char* name, int num_slave, int num_master) const {
    const Geometry& slave = GetParentGeometry();
    const Geometry& master = GetPairedGeometry();
    CONTACT_CHECK(static_cast<int>(slave.size()) == num_slave && static_cast<int>(master.size()) == num_master,
                  InputError, name, " ", Id(), " pairs a ", slave.size(), "-node slave with a ", master.size(),
                  "-node master\n  expected: ", num_slave, " and ", num_master,
                  " nodes\n  fix: use the condition name whose suffix matches the two faces");
}

void PairedCondition::CalculateLocalSystem(Matrix& rLeftHandSideMatrix, Vector& rRightHandSideVector,
                                           const ProcessInfo& rCurrentProcessInfo) {
    CalculateConditionSystem(&rLeftHandSideMatrix, &rRightHandSideVector, rCurrentProcessInfo);
}

void PairedCondition::CalculateLeftHandSide(Matrix& rLeftHandSideMatrix, const ProcessInfo& rCurrentProcessInfo) {
    CalculateConditionSystem(&rLeftHandSideMatrix, nullptr, rCurrentProcessInfo);
}

void PairedCondition::CalculateRightHandSide(Vector& rRightHandSideVector, const ProcessInfo& rCurrentProcessInfo) {
    CalculateConditionSystem(nullptr, &rRightHandSideVector, rCurrentProcessInfo);
}

void PairedCondition::CalculateConditionSystem(Matrix* pLhs, Vector* pRhs, const ProcessInfo&) {
    if (pLhs) pLhs->resize(0, 0);
    if (pRhs) pRhs->resize(0);
}

void PairedCondition::EquationIdVector(EquationIdVectorType& rResult, const ProcessInfo& rCurrentProcessInfo) const {
    DofsVectorType dofs;
    GetDofList(dofs, rCurrentProcessInfo);
    rResult.resize(dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i) rResult[i] = dofs[i]->EquationId();
}

void PairedCondition::CalculateMassMatrix(Matrix& rMassMatrix, const ProcessInfo&) { rMassMatrix.resize(0, 0); }

void PairedCondition::CalculateDampingMatrix(Matrix& rDampingMatrix, const ProcessInfo&) {
    rDampingMatrix.resize(0, 0);
}

void PairedCondition::CalculateOnIntegrationPoints(const Variable<double>&, std::vector<double>& rOutput,
                                                   const ProcessInfo&) {
    const Geometry& slave = GetParentGeometry();
    rOutput.assign(slave.IntegrationPoints(slave.DefaultIntegrationOrder()).size(), 0.0);
}

void PairedCondition::CalculateOnIntegrationPoints(const Variable<Array3>&, std::vector<Array3>& rOutput,
                                                   const ProcessInfo&) {
    const Geometry& slave = GetParentGeometry();
    rOutput.assign(slave.IntegrationPoints(slave.DefaultIntegrationOrder()).size(), Array3::Zero());
}

void PairedCondition::CalculateOnIntegrationPoints(const Variable<Vector>&, std::vector<Vector>& rOutput,
                                                   const ProcessInfo&) {
    const Geometry& slave = GetParentGeometry();
    rOutput.assign(slave.IntegrationPoints(slave.DefaultIntegrationOrder()).size(),
                   Vector::Zero(slave.WorkingSpaceDimension()));
}

}  // namespace contact_app
