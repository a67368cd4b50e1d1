// SPDX-License-Identifier: BSD-3-Clause
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "contact_app/bindings/binding_helpers.h"
#include "contact_app/bindings/bindings.h"
#include "contact_app/kernel/condition.h"
#include "contact_app/kernel/element.h"
#include "contact_app/kernel/master_slave_constraint.h"

namespace contact_app::bindings {

namespace {

/// Hooks shared by Element, Condition and MasterSlaveConstraint: f(process_info).
template <class TPyClass>
void DefLifeCycle(TPyClass& cls) {
    using Owner = typename TPyClass::type;
    const auto pi = py::arg("process_info");
    cls.def(
           "Initialize", [](Owner& self, const ProcessInfo& info) { self.Initialize(info); }, pi,
           "Called once before the analysis.")
        .def(
            "InitializeSolutionStep", [](Owner& self, const ProcessInfo& info) { self.InitializeSolutionStep(info); },
            pi, "Called at the start of each step.")
        .def(
            "InitializeNonLinearIteration",
            [](Owner& self, const ProcessInfo& info) { self.InitializeNonLinearIteration(info); }, pi,
            "Called before each non-linear iteration.")
        .def(
            "FinalizeNonLinearIteration",
            [](Owner& self, const ProcessInfo& info) { self.FinalizeNonLinearIteration(info); }, pi,
            "Called after each non-linear iteration.")
        .def(
            "FinalizeSolutionStep", [](Owner& self, const ProcessInfo& info) { self.FinalizeSolutionStep(info); }, pi,
            "Called at the end of each step.")
        .def(
            "Check", [](const Owner& self, const ProcessInfo& info) { return self.Check(info); }, pi,
            "0, or InputError naming what is missing.")
        .def_property_readonly(
            "Id", [](const Owner& self) { return self.Id(); }, "Id.")
        .def(
            "Info", [](const Owner& self) { return self.Info(); }, "Short description.")
        .def(
            "__repr__", [](const Owner& self) { return "<" + self.Info() + ">"; }, "<Info()>.");
    DefValueAccess(cls);
    DefIdentity(cls);
}

template <class T, class TPyClass>
void DefOnIntegrationPoints(TPyClass& cls) {
    using Owner = typename TPyClass::type;
    cls.def(
        "CalculateOnIntegrationPoints",
        [](Owner& self, const Variable<T>& variable, const ProcessInfo& info) {
            std::vector<T> output;
            self.CalculateOnIntegrationPoints(variable, output, info);
            return output;
        },
        py::arg("variable"), py::arg("process_info"), "One value per integration point.");
}

/// Element or Condition (Kratos Entity API).
template <class TEntity>
auto BindEntity(py::module_& m, const char* name, const char* doc) {
    py::class_<TEntity, Flags, std::shared_ptr<TEntity>> cls(m, name, doc, py::multiple_inheritance());
    DefLifeCycle(cls);
    const auto pi = py::arg("process_info");
    cls.def(
           "CalculateLocalSystem",
           [](TEntity& self, const ProcessInfo& info) {
               Matrix lhs;
               Vector rhs;
               self.CalculateLocalSystem(lhs, rhs, info);
               return std::make_pair(std::move(lhs), std::move(rhs));
           },
           pi, "(LHS, RHS) of the local system.")
        .def(
            "CalculateLeftHandSide",
            [](TEntity& self, const ProcessInfo& info) {
                Matrix lhs;
                self.CalculateLeftHandSide(lhs, info);
                return lhs;
            },
            pi, "LHS of the local system.")
        .def(
            "CalculateRightHandSide",
            [](TEntity& self, const ProcessInfo& info) {
                Vector rhs;
                self.CalculateRightHandSide(rhs, info);
                return rhs;
            },
            pi, "RHS of the local system.")
        .def(
            "CalculateMassMatrix",
            [](TEntity& self, const ProcessInfo& info) {
                Matrix mass;
                self.CalculateMassMatrix(mass, info);
                return mass;
            },
            pi, "Mass matrix.")
        .def(
            "CalculateDampingMatrix",
            [](TEntity& self, const ProcessInfo& info) {
                Matrix damping;
                self.CalculateDampingMatrix(damping, info);
                return damping;
            },
            pi, "Damping matrix.")
        .def(
            "EquationIdVector",
            [](const TEntity& self, const ProcessInfo& info) {
                EquationIdVectorType ids;
                self.EquationIdVector(ids, info);
                return ids;
            },
            pi, "Equation ids in local-system order.")
        .def(
            "GetDofList",
            [](py::object self, const ProcessInfo& info) {
                DofsVectorType dofs;
                self.cast<const TEntity&>().GetDofList(dofs, info);
                return ReferenceList(dofs, self);
            },
            pi, "DoFs in local-system order.")
        .def(
            "GetValuesVector",
            [](const TEntity& self, int step) {
                Vector values;
                self.GetValuesVector(values, step);
                return values;
            },
            py::arg("step") = 0, "DoF values at buffer step, in local-system order.")
        .def(
            "AddExplicitContribution",
            [](TEntity& self, const ProcessInfo& info) { self.AddExplicitContribution(info); }, pi,
            "Explicit nodal contributions (weighted gap, slip, nodal area).")
        .def("GetGeometry", &TEntity::pGetGeometry, "The geometry (for paired conditions: the slave one).")
        .def(
            "GetNodes", [](const TEntity& self) { return self.GetGeometry().Points(); }, "The nodes of the geometry.")
        .def(
            "GetProperties",
            [](const TEntity& self) {
                self.GetProperties();  // throws the descriptive InputError when unset
                return self.pGetProperties();
            },
            "The properties; InputError if none were assigned.")
        .def_property("Properties", &TEntity::pGetProperties, &TEntity::SetProperties,
                      "The properties (None if unset).");
    DefOnIntegrationPoints<double>(cls);
    DefOnIntegrationPoints<Array3>(cls);
    DefOnIntegrationPoints<Vector>(cls);
    DefOnIntegrationPoints<Matrix>(cls);
    return cls;
}

void BindMasterSlaveConstraint(py::module_& m) {
    using Constraint = MasterSlaveConstraint;
    py::class_<Constraint, Flags, std::shared_ptr<Constraint>> cls(
        m, "MasterSlaveConstraint", "A multipoint constraint u_slave = T u_master + c (Kratos MasterSlaveConstraint).",
        py::multiple_inheritance());
    DefLifeCycle(cls);
    const auto pi = py::arg("process_info");
    cls.def(
           "GetDofList",
           [](py::object self, const ProcessInfo& info) {
               DofsVectorType slaves, masters;
               self.cast<const Constraint&>().GetDofList(slaves, masters, info);
               return py::make_tuple(ReferenceList(slaves, self), ReferenceList(masters, self));
           },
           pi, "(slave DoFs, master DoFs).")
        .def(
            "EquationIdVector",
            [](const Constraint& self, const ProcessInfo& info) {
                EquationIdVectorType slaves, masters;
                self.EquationIdVector(slaves, masters, info);
                return std::make_pair(slaves, masters);
            },
            pi, "(slave equation ids, master equation ids).")
        .def(
            "CalculateLocalSystem",
            [](Constraint& self, const ProcessInfo& info) {
                Matrix relation;
                Vector constant;
                self.CalculateLocalSystem(relation, constant, info);
                return std::make_pair(std::move(relation), std::move(constant));
            },
            pi, "(T, c): relation (slaves x masters) and constant.")
        .def(
            "Apply", [](Constraint& self, const ProcessInfo& info) { self.Apply(info); }, pi,
            "Sets the slave values to T u_master + c.")
        .def(
            "GetSlaveDofsVector",
            [](py::object self) { return ReferenceList(self.cast<const Constraint&>().GetSlaveDofsVector(), self); },
            "The slave DoFs.")
        .def(
            "GetMasterDofsVector",
            [](py::object self) { return ReferenceList(self.cast<const Constraint&>().GetMasterDofsVector(), self); },
            "The master DoFs.");
}

}  // namespace

void BindEntities(py::module_& m) {
    auto element = BindEntity<Element>(
        m, "Element", "A domain element (Kratos Element); the base class is a geometry-only mesh element.");
    element.def("WhyStiffnessVaries", &Element::WhyStiffnessVaries,
                "Why the tangent stiffness may change with the displacement, \"\" if it cannot while the properties "
                "stay; completes \"element <id> ...\".");
    BindEntity<Condition>(m, "Condition", "A boundary or interface condition (Kratos Condition).");
    BindMasterSlaveConstraint(m);
}

}  // namespace contact_app::bindings
