// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

/// An element or constitutive law met det J ≤ 0 or det F ≤ 0 in the current configuration: the Newton
/// iterate is unusable (an element turned inside out), not the input. A ConvergenceError, so the iteration
/// fails, not the run: the analysis reports the step as not converged and cuts it (docs/running.md,
/// "Non-convergence"). Mapped to Python `InvertedElementError(ConvergenceError)` with the fields as attributes.
class InvertedElementError : public ConvergenceError {
public:
    /// @param what message (what, where, expected, fix) @param element_id 0 when the thrower does not know it
    /// @param quantity "det J" or "det F" @param value its value (≤ 0) @param time TIME, NaN when not known
    InvertedElementError(const std::string& what, std::size_t element_id, std::string quantity, double value,
                         double time);

    std::size_t ElementId() const { return mElementId; }
    const std::string& Quantity() const { return mQuantity; }
    double Value() const { return mValue; }
    /// TIME of the failed iteration; NaN until an element that knows the ProcessInfo located the error.
    double Time() const { return mTime; }

    /// @brief The same failure with the element and TIME filled in (the message names them once).
    /// @param[in] element_id, element_info the element that evaluated the law (kept if already set)
    /// @param[in] time TIME of the ProcessInfo (kept if already set)
    InvertedElementError Located(std::size_t element_id, const std::string& element_info, double time) const;

private:
    std::size_t mElementId;
    std::string mQuantity;
    double mValue;
    double mTime;
};

}  // namespace contact_app
