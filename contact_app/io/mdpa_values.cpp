// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/io/mdpa_values.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <tuple>
#include <vector>

#include "contact_app/kernel/exceptions.h"

namespace contact_app::mdpa {

namespace {

/// Numbers between the outermost parentheses, split at commas (nested groups kept whole).
std::vector<std::string> SplitGroup(const std::string& text, char open, char close) {
    std::vector<std::string> parts;
    CONTACT_CHECK(text.size() >= 2 && text.front() == open && text.back() == close, InputError, "malformed value ",
                  Quoted(text), "\n  expected: a list in ", open, "...", close);
    int depth = 0;
    std::string current;
    for (std::size_t i = 1; i + 1 < text.size(); ++i) {
        const char c = text[i];
        if (c == '(' || c == '[') ++depth;
        if (c == ')' || c == ']') --depth;
        if (c == ',' && depth == 0) {
            parts.push_back(current);
            current.clear();
        } else {
            current.push_back(c);
        }
    }
    if (!current.empty() || !parts.empty()) parts.push_back(current);
    return parts;
}

/// Splits "[n](...)" into the size part "n" and the list "(...)"; "(...)" alone has no size.
std::pair<std::string, std::string> SplitSized(const std::string& token) {
    if (!token.empty() && token.front() == '[') {
        const auto close = token.find(']');
        CONTACT_CHECK(close != std::string::npos, InputError, "malformed value ", Quoted(token), ": missing ']'");
        return {token.substr(1, close - 1), token.substr(close + 1)};
    }
    return {"", token};
}

}  // namespace

std::string Quoted(const std::string& token) {
    constexpr std::size_t kLimit = 200;
    std::string text = "\"";
    for (std::size_t i = 0; i < token.size() && i < kLimit; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c != 0x7f) {
            text.push_back(static_cast<char>(c));
            continue;
        }
        constexpr const char* kHex = "0123456789abcdef";
        text += "\\x";
        text.push_back(kHex[c >> 4]);
        text.push_back(kHex[c & 15]);
    }
    if (token.size() > kLimit) text += "… (" + std::to_string(token.size()) + " characters)";
    return text + "\"";
}

double ParseDouble(const std::string& token, const char* what) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    // strtod's ERANGE also flags underflow, which rounds to a (sub)normal or zero and is kept.
    CONTACT_CHECK(!token.empty() && end == token.c_str() + token.size(), InputError, Quoted(token),
                  " is not a valid ", what, "\n  expected: a real number such as 1.5 or 2.0e-3");
    CONTACT_CHECK(std::isfinite(value), InputError, "non-finite ", what, " ", Quoted(token),
                  "\n  expected: a finite real number (nan, inf and magnitudes beyond 1.8e308 are refused)",
                  "\n  fix:      write the intended value");
    return value;
}

IndexType ParseId(const std::string& token, const char* what) {
    const bool digits = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    CONTACT_CHECK(digits, InputError, Quoted(token), " is not a valid ", what,
                  "\n  expected: a non-negative integer");
    errno = 0;
    const unsigned long long value = std::strtoull(token.c_str(), nullptr, 10);
    CONTACT_CHECK(errno != ERANGE && value <= kMaxId, InputError, what, " ", Quoted(token),
                  " is beyond the largest id ", kMaxId,
                  "\n  expected: at most 2^63 - 1 (the signed 64-bit range the JSON layer and the outputs store)",
                  "\n  fix:      renumber the mesh");
    return static_cast<IndexType>(value);
}

int ParseInt(const std::string& token, const char* what) {
    errno = 0;
    char* end = nullptr;
    const long value = std::strtol(token.c_str(), &end, 10);
    CONTACT_CHECK(!token.empty() && end == token.c_str() + token.size(), InputError, Quoted(token),
                  " is not a valid ", what, "\n  expected: an integer");
    CONTACT_CHECK(errno != ERANGE && value >= std::numeric_limits<int>::min() &&
                      value <= std::numeric_limits<int>::max(),
                  InputError, what, " ", Quoted(token), " is beyond the range of an integer",
                  "\n  expected: from ", std::numeric_limits<int>::min(), " to ", std::numeric_limits<int>::max());
    return static_cast<int>(value);
}

bool ParseBool(const std::string& token, const char* what) {
    if (token == "1" || token == "true" || token == "True") return true;
    if (token == "0" || token == "false" || token == "False") return false;
    CONTACT_THROW(InputError, Quoted(token), " is not a valid ", what, "\n  expected: 0, 1, true or false");
}

Array3 ParseArray3(const std::string& token) {
    const auto [size, list] = SplitSized(token);
    const auto parts = SplitGroup(list, '(', ')');
    CONTACT_CHECK(parts.size() == 3 && (size.empty() || size == "3"), InputError, Quoted(token),
                  " is not a 3-vector\n  expected: [3](x,y,z)");
    return Array3(ParseDouble(parts[0], "vector component"), ParseDouble(parts[1], "vector component"),
                  ParseDouble(parts[2], "vector component"));
}

Vector ParseVector(const std::string& token) {
    std::vector<std::string> parts;
    std::string size;
    if (token.find('(') == std::string::npos) {
        parts = SplitGroup(token, '[', ']');  // [a, b, c]
    } else {
        std::string list;
        std::tie(size, list) = SplitSized(token);
        parts = SplitGroup(list, '(', ')');
    }
    Vector vector(static_cast<Eigen::Index>(parts.size()));
    for (std::size_t i = 0; i < parts.size(); ++i) vector[i] = ParseDouble(parts[i], "vector component");
    if (!size.empty()) {
        CONTACT_CHECK(ParseId(size, "vector size") == parts.size(), InputError, "vector ", Quoted(token), " declares ",
                      size, " components but lists ", parts.size());
    }
    return vector;
}

Matrix ParseMatrix(const std::string& token) {
    const auto [size, list] = SplitSized(token);
    const auto comma = size.find(',');
    CONTACT_CHECK(comma != std::string::npos, InputError, Quoted(token),
                  " is not a matrix\n  expected: [rows,cols]((a,b),(c,d))");
    const IndexType rows = ParseId(size.substr(0, comma), "matrix row count");
    const IndexType cols = ParseId(size.substr(comma + 1), "matrix column count");
    const auto row_texts = SplitGroup(list, '(', ')');
    CONTACT_CHECK(row_texts.size() == rows, InputError, "matrix ", Quoted(token), " declares ", rows, " rows but lists ",
                  row_texts.size());
    // Entries are counted before the matrix is allocated: the declared size may be absurd.
    std::vector<double> values;
    for (std::size_t r = 0; r < rows; ++r) {
        const auto entries = SplitGroup(row_texts[r], '(', ')');
        CONTACT_CHECK(entries.size() == cols, InputError, "row ", r + 1, " of matrix ", Quoted(token), " has ",
                      entries.size(), " entries, expected ", cols);
        for (const auto& entry : entries) values.push_back(ParseDouble(entry, "matrix entry"));
    }
    Matrix matrix(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(rows == 0 ? 0 : cols));
    for (std::size_t r = 0; r < rows; ++r)
        for (std::size_t c = 0; c < cols; ++c) matrix(r, c) = values[r * cols + c];
    return matrix;
}

void SetParsedValue(DataValueContainer& data, const VariableData& variable, const std::string& token) {
    switch (variable.Type()) {
        case VariableType::Bool:
            data.SetValue(static_cast<const Variable<bool>&>(variable), ParseBool(token, "boolean value"));
            return;
        case VariableType::Integer:
            data.SetValue(static_cast<const Variable<int>&>(variable), ParseInt(token, "integer value"));
            return;
        case VariableType::Double:
        case VariableType::Component:
            data.SetValue(static_cast<const Variable<double>&>(variable), ParseDouble(token, "real value"));
            return;
        case VariableType::Array:
            data.SetValue(static_cast<const Variable<Array3>&>(variable), ParseArray3(token));
            return;
        case VariableType::Vector:
            data.SetValue(static_cast<const Variable<Vector>&>(variable), ParseVector(token));
            return;
        case VariableType::Matrix:
            data.SetValue(static_cast<const Variable<Matrix>&>(variable), ParseMatrix(token));
            return;
        case VariableType::String: {
            std::string text = token;
            if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
            data.SetValue(static_cast<const Variable<std::string>&>(variable), text);
            return;
        }
        case VariableType::Pointer: break;
    }
    CONTACT_THROW(InputError, "variable ", variable.Name(), " holds an object and cannot be given a value in an mdpa file");
}

}  // namespace contact_app::mdpa
