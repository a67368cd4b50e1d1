// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>

#include "contact_app/kernel/data_value_container.h"
#include "contact_app/kernel/types.h"

namespace contact_app::mdpa {

// Parsers of the value spellings of `.mdpa` files. Each throws InputError with a message that
// says what was expected; the reader prefixes it with the file and line.

double ParseDouble(const std::string& token, const char* what);
/// A non-negative integer id (or count). @p what names the field in messages.
IndexType ParseId(const std::string& token, const char* what);
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
