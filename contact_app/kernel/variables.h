// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <memory>
#include <string>

#include "contact_app/kernel/variable_data.h"

namespace contact_app {

class ConstitutiveLaw;
class MasterSlaveConstraint;
class TableStreamUtility;

// Kernel (Kratos core) and structural (Kratos StructuralMechanicsApplication) variables, with their
// Kratos names and types (docs/input_layer.md §6). One table declares and defines them.

/// Scalar, vector, matrix, string and pointer variables: X(type, NAME). RESTART_PROCESS_STATES is contact_app's own:
/// the JSON state of the Python processes (output counters, search state) that a restart file carries in the
/// ProcessInfo (contact_app/io/restart_utility.py).
#define CONTACT_APP_KERNEL_VARIABLES(X)                                                          \
    X(double, TIME) X(double, DELTA_TIME) X(int, STEP) X(int, NL_ITERATION_NUMBER)               \
    X(int, DOMAIN_SIZE) X(bool, IS_RESTARTED) X(double, CONVERGENCE_RATIO) X(double, RESIDUAL_NORM) \
    X(bool, RESET_EQUATION_IDS) X(double, BOSSAK_ALPHA) X(double, NEWMARK_BETA)                   \
    X(double, NEWMARK_GAMMA) X(double, PRESSURE) X(double, POSITIVE_FACE_PRESSURE)               \
    X(double, NEGATIVE_FACE_PRESSURE) X(double, YOUNG_MODULUS) X(double, POISSON_RATIO)          \
    X(double, DENSITY) X(double, THICKNESS) X(double, FRICTION_COEFFICIENT) X(int, INTEGRATION_ORDER) \
    X(bool, COMPUTE_LUMPED_MASS_MATRIX) X(double, MASS_FACTOR) X(double, RAYLEIGH_ALPHA)          \
    X(double, RAYLEIGH_BETA) X(double, VON_MISES_STRESS) X(double, STRAIN_ENERGY)                 \
    X(double, ERROR_INTEGRATION_POINT) X(double, NODAL_H) X(double, NODAL_AREA) X(double, NODAL_MASS) \
    X(double, INITIAL_PENALTY) X(double, SCALE_FACTOR) X(double, TANGENT_FACTOR)                  \
    X(double, SCALAR_LAGRANGE_MULTIPLIER) X(double, NODAL_MAUX) X(double, NODAL_PAUX)             \
    X(double, NORMAL_CONTACT_STRESS) X(double, TANGENTIAL_CONTACT_STRESS) X(double, CONTACT_PRESSURE) \
    X(double, ERROR_RATIO) X(double, DISTANCE) X(double, TEMPERATURE)                             \
    X(Vector, CAUCHY_STRESS_VECTOR) X(Vector, PK2_STRESS_VECTOR) X(Vector, GREEN_LAGRANGE_STRAIN_VECTOR) \
    X(Vector, ALMANSI_STRAIN_VECTOR) X(Vector, INITIAL_STRAIN_VECTOR)                            \
    X(Matrix, CAUCHY_STRESS_TENSOR) X(Matrix, PK2_STRESS_TENSOR) X(Matrix, GREEN_LAGRANGE_STRAIN_TENSOR) \
    X(Matrix, ALMANSI_STRAIN_TENSOR) X(Matrix, DEFORMATION_GRADIENT) X(Matrix, CONSTITUTIVE_MATRIX) \
    X(std::string, IDENTIFIER) X(std::string, RESTART_PROCESS_STATES)                             \
    X(std::shared_ptr<ConstitutiveLaw>, CONSTITUTIVE_LAW)                                        \
    X(std::shared_ptr<MasterSlaveConstraint>, MASTER_SLAVE_CONSTRAINT)                             \
    X(std::shared_ptr<TableStreamUtility>, TABLE_UTILITY)

/// 3-vector variables, each with its _X, _Y, _Z components: X(NAME).
#define CONTACT_APP_KERNEL_ARRAY3_VARIABLES(X)                                                   \
    X(DISPLACEMENT) X(REACTION) X(VELOCITY) X(ACCELERATION) X(VOLUME_ACCELERATION) X(ROTATION)    \
    X(REACTION_MOMENT) X(ANGULAR_VELOCITY) X(ANGULAR_ACCELERATION) X(POINT_LOAD) X(POINT_MOMENT)  \
    X(LINE_LOAD) X(SURFACE_LOAD) X(BODY_FORCE) X(FORCE) X(NORMAL) X(TANGENT_XI) X(TANGENT_ETA)    \
    X(VECTOR_LAGRANGE_MULTIPLIER) X(CONTACT_FORCE) X(FORCE_RESIDUAL) X(NODAL_VAUX)                \
    X(MESH_DISPLACEMENT)

#define CONTACT_APP_DECLARE_VARIABLE(type, name) extern const Variable<type> name;
#define CONTACT_APP_DECLARE_ARRAY3_VARIABLE(name)                                      \
    extern const Variable<Array3> name;                                               \
    extern const Variable<double> name##_X, name##_Y, name##_Z;
#define CONTACT_APP_DEFINE_VARIABLE(type, name) const Variable<type> name(#name);
#define CONTACT_APP_DEFINE_ARRAY3_VARIABLE(name)                                       \
    const Variable<Array3> name(#name);                                               \
    const Variable<double> name##_X(#name "_X", name, 0), name##_Y(#name "_Y", name, 1), \
        name##_Z(#name "_Z", name, 2);

CONTACT_APP_KERNEL_VARIABLES(CONTACT_APP_DECLARE_VARIABLE)
CONTACT_APP_KERNEL_ARRAY3_VARIABLES(CONTACT_APP_DECLARE_ARRAY3_VARIABLE)

/// Forces the kernel variables into the link (they register themselves when constructed).
void RegisterKernelVariables();

}  // namespace contact_app
