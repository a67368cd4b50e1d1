// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/parallel_utilities.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

int ParallelUtilities::GetNumThreads() {
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

void ParallelUtilities::SetNumThreads(int threads) {
    CONTACT_CHECK(threads >= 1, InputError, "the number of assembly threads must be at least 1, got ", threads,
                  "\n  fix: set OMP_NUM_THREADS to a positive integer");
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
}

}  // namespace contact_app
