// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace contact_app {

/// Edit (Levenshtein) distance between two strings, case-sensitive.
std::size_t EditDistance(const std::string& a, const std::string& b);

/// Up to @p max_results candidates closest to @p name (by case-insensitive edit distance),
/// best first; only candidates within a distance that still looks like a typo are returned.
std::vector<std::string> ClosestNames(const std::string& name, const std::vector<std::string>& candidates,
                                      std::size_t max_results = 3);

/// "\n  fix:      did you mean \"X\"?" (or "X" or "Y"), or "" when nothing is close. Appended to
/// unknown-name messages.
std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates);

/// `did you mean "X"?` when a candidate is close, else @p fallback (no prefix, for "fix: ..." lines).
std::string DidYouMean(const std::string& name, const std::vector<std::string>& candidates,
                       const std::string& fallback);

/// `"a", "b", "c"`: the names quoted and comma-separated, for "expected: one of ..." lines.
std::string QuotedList(const std::vector<std::string>& names);

}  // namespace contact_app
