// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/inverted_element_error.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace contact_app {

InvertedElementError::InvertedElementError(const std::string& what, std::size_t element_id, std::string quantity,
                                           double value, double time)
    : ConvergenceError(what), mElementId(element_id), mQuantity(std::move(quantity)), mValue(value), mTime(time) {}

InvertedElementError InvertedElementError::Located(std::size_t element_id, const std::string& element_info,
                                                   double time) const {
    std::string message = what();
    if (mElementId == 0 && element_id != 0) message = element_info + ": " + message;
    const bool add_time = std::isnan(mTime) && !std::isnan(time);
    if (add_time) {
        // The first line says what and where: TIME belongs there, before "expected"/"fix".
        std::ostringstream stamp;
        stamp << " (TIME = " << time << ")";
        const std::size_t end_of_line = message.find('\n');
        message.insert(end_of_line == std::string::npos ? message.size() : end_of_line, stamp.str());
    }
    return InvertedElementError(message, mElementId != 0 ? mElementId : element_id, mQuantity, mValue,
                                add_time ? time : mTime);
}

}  // namespace contact_app
