// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/table.h"

#include <algorithm>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

void Table::PushBack(double x, double y) {
    const auto position = std::lower_bound(mRows.begin(), mRows.end(), x,
                                           [](const auto& row, double value) { return row.first < value; });
    CONTACT_CHECK(position == mRows.end() || position->first != x, InputError, "table ", mInputVariable, " -> ",
                  mOutputVariable, " has two rows with x = ", x, "\n  fix: give every row a distinct x");
    mRows.insert(position, {x, y});
}

std::size_t Table::Segment(double x) const {
    // Index i of the segment [x_i, x_{i+1}] used for x (end segments extend outwards).
    const auto upper = std::upper_bound(mRows.begin(), mRows.end(), x,
                                        [](double value, const auto& row) { return value < row.first; });
    const std::size_t index = static_cast<std::size_t>(upper - mRows.begin());
    if (index == 0) return 0;
    return std::min(index - 1, mRows.size() - 2);
}

double Table::GetValue(double x) const {
    CONTACT_CHECK(!mRows.empty(), InputError, "table ", mInputVariable, " -> ", mOutputVariable,
                  " is empty\n  fix: give it at least one row");
    if (mRows.size() == 1) return mRows.front().second;
    const std::size_t i = Segment(x);
    const auto& [x0, y0] = mRows[i];
    const auto& [x1, y1] = mRows[i + 1];
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
}

double Table::GetDerivative(double x) const {
    if (mRows.size() < 2) return 0.0;
    const std::size_t i = Segment(x);
    return (mRows[i + 1].second - mRows[i].second) / (mRows[i + 1].first - mRows[i].first);
}

}  // namespace contact_app
