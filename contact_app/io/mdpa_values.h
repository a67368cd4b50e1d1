// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/data_value_container.h"
#include "contact_app/kernel/types.h"

namespace contact_app::mdpa {

// Parsers of the value spellings of `.mdpa` files. Each throws InputError with a message that
// says what was expected; the reader prefixes it with the file and line.

/// Largest id or count read: the signed 64-bit range, which the JSON layer and the outputs store.
inline constexpr IndexType kMaxId = 9223372036854775807ULL;

/// @p token between quotes for a message: at most 200 characters, control characters escaped.
std::string Quoted(const std::string& token);

/// A finite real number; nan, inf and values beyond the double range are refused as non-finite.
double ParseDouble(const std::string& token, const char* what);
/// A non-negative integer id (or count) of at most kMaxId. @p what names the field in messages.
IndexType ParseId(const std::string& token, const char* what);
/// An integer in the range of int.
int ParseInt(const std::string& token, const char* what);
/// 0/1/true/false.
bool ParseBool(const std::string& token, const char* what);
/// `[3](a,b,c)`, `[3] (a, b, c)` or `(a,b,c)`.
Array3 ParseArray3(const std::string& token);
/// `[n](a,...)` or `[a, b, ...]` (the constraint-weight spelling).
Vector ParseVector(const std::string& token);
/// `[r,c]((a,b),(c,d))`.
Matrix ParseMatrix(const std::string& token);

/// Parses @p token as a value of @p variable and stores it in @p data (strings: the token, unquoted).
/// @throws InputError for pointer variables (except via the caller) and malformed values.
void SetParsedValue(DataValueContainer& data, const VariableData& variable, const std::string& token);

}  // namespace contact_app::mdpa
