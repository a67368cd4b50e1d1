// SPDX-License-Identifier: BSD-3-Clause
#pragma once

namespace contact_app {

class ModelPart;

/// Adaptive nodal ALM penalty (Kratos AALMAdaptPenaltyValueProcess after Bussetta, Marceau and Ponthot,
/// docs/theory/contact_strategies.md §5, reproduced as coded). For every node with NODAL_AREA A > machine ε:
/// g = g̃/A, g_old = g̃(previous step)/A, g_max = MAX_GAP_FACTOR·NODAL_H, ε_prev = ProcessInfo INITIAL_PENALTY at
/// step 1 / iteration 1, else the nodal value. Sign change (g·g_old < 0): ε = |ε_prev g_old/g (|g|+g_max)/(g−g_old)|
/// if |g_old| > g_max, else |ε_prev g_old/(10 g)|. Else, if |g| > g_max: ε = 2ε_prev when |g − g_old| >
/// max(g/10, g_old, 5 g_max) (signed, as coded); else ε_prev(√(|g|/g_max − 1) + 1)² when |g| < 10 g_max; else
/// 2ε_prev g_old/g when |g| > 1.01|g_old|, else ε_prev(√(|g|/g_max − 1) + 1). Otherwise ε = ε_prev.
/// Result: nodal INITIAL_PENALTY. Needs the historical WEIGHTED_GAP with a buffer of at least 2.
class AALMAdaptPenaltyValueProcess {
public:
    /// @param[in,out] model_part the contact part (kept by reference; must outlive the process)
    explicit AALMAdaptPenaltyValueProcess(ModelPart& model_part) : mrModelPart(model_part) {}
    /// @brief Updates the nodal INITIAL_PENALTY.
    /// @throws InputError without historical WEIGHTED_GAP or with a buffer size below 2
    void Execute();

private:
    ModelPart& mrModelPart;
};

}  // namespace contact_app
