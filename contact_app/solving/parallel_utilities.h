// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

/// The threads of the parallel assembly (Kratos ParallelUtilities). They are OpenMP's: OMP_NUM_THREADS when set, else
/// one per core; results do not depend on the count (docs/architecture.md, "Threading model").
class ParallelUtilities {
public:
    /// Threads the next parallel region will use (1 in a build without OpenMP).
    static int GetNumThreads();
    /// Sets the threads of the following parallel regions of the calling thread. @throws InputError if @p threads < 1.
    static void SetNumThreads(int threads);
};

}  // namespace contact_app
