// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/string_utilities.h"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace contact_app {

namespace {
std::string Lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}
}  // namespace

std::size_t EditDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), std::size_t{0});
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

std::vector<std::string> ClosestNames(const std::string& name, const std::vector<std::string>& candidates,
                                      std::size_t max_results) {
    const std::string lowered = Lower(name);
    // A typo changes a few characters; allow about a third of the name, at least 2.
    const std::size_t limit = std::max<std::size_t>(2, lowered.size() / 3);
    std::vector<std::pair<std::size_t, std::string>> scored;
    for (const auto& candidate : candidates) {
        const std::size_t distance = EditDistance(lowered, Lower(candidate));
        if (distance <= limit) scored.emplace_back(distance, candidate);
    }
    std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::string> result;
    for (std::size_t i = 0; i < scored.size() && i < max_results; ++i) result.push_back(scored[i].second);
    return result;
}

std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates,
                       const std::string& fallback) {
    const auto close = ClosestNames(name, candidates);
    if (close.empty()) return fallback;
    std::string text = "did you mean ";
    for (std::size_t i = 0; i < close.size(); ++i) {
        if (i > 0) text += " or ";
        text += "\"" + close[i] + "\"";
    }
    return text + "?";
}

std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates) {
    const std::string suggestion = DidYouMean(name, candidates, "");
    return suggestion.empty() ? suggestion : "\n  fix:      " + suggestion;
}

std::string QuotedList(const std::vector<std::string>& names) {
    std::string text;
    for (const auto& name : names) text += (text.empty() ? "\"" : ", \"") + name + "\"";
    return text;
}

}  // namespace contact_app
