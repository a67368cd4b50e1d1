// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/io/mdpa_line_reader.h"

#include <cctype>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

MdpaLineReader::MdpaLineReader(const std::string& file_name) : mFileName(file_name), mStream(file_name) {
    CONTACT_CHECK(mStream.good(), InputError, "cannot open the mesh file \"", file_name, "\"",
                  "\n  fix: check the path (model_import_settings.input_filename is given without the .mdpa extension)");
}

std::string MdpaLineReader::Where() const { return mFileName + ":" + std::to_string(mLineNumber) + ": "; }

bool MdpaLineReader::Next() {
    while (std::getline(mStream, mLine)) {
        ++mLineNumber;
        Tokenize(mLine);
        if (!mTokens.empty()) return true;
    }
    return false;
}

namespace {

/// Appends the balanced group starting at line[i] ('[' or '(') to @p token without whitespace;
/// returns the index after it (or @p end if it is not closed on this line).
std::size_t TakeGroup(const std::string& line, std::size_t i, std::size_t end, std::string& token) {
    int depth = 0;
    for (; i < end; ++i) {
        const char c = line[i];
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        token.push_back(c);
        if (c == '[' || c == '(') ++depth;
        if (c == ']' || c == ')') --depth;
        if (depth == 0) return i + 1;
    }
    return end;
}

}  // namespace

void MdpaLineReader::Tokenize(const std::string& line) {
    mTokens.clear();
    const std::size_t comment = line.find("//");
    const std::size_t end = comment == std::string::npos ? line.size() : comment;
    std::size_t i = 0;
    while (true) {
        while (i < end && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= end) break;
        std::string token;
        if (line[i] == '[' || line[i] == '(') {
            // "[3] (1, 2, 3)", "[2,2]((1,0),(0,1))" and "[0.25, 0.25]" are single values.
            i = TakeGroup(line, i, end, token);
            std::size_t j = i;
            while (j < end && std::isspace(static_cast<unsigned char>(line[j]))) ++j;
            if (token.front() == '[' && j < end && line[j] == '(') i = TakeGroup(line, j, end, token);
        } else {
            while (i < end && !std::isspace(static_cast<unsigned char>(line[i]))) token.push_back(line[i++]);
        }
        mTokens.push_back(std::move(token));
    }
}

}  // namespace contact_app
