// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/convergence_criteria/convergence_criteria.h"

namespace contact_app {

void ConvergenceCriteria::InitializeSolutionStep(ModelPart&, DofsArrayType&, const SparseMatrixType&,
                                                 const SystemVectorType&, const SystemVectorType&,
                                                 const BuilderAndSolver&) {}

}  // namespace contact_app
