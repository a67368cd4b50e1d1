// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace contact_app {

/// Splits an `.mdpa` file into lines of whitespace-separated tokens, dropping `//` comments and
/// blank lines. A bracketed value such as `[3] (1.0, 2.0, 3.0)` or `[0.25, 0.25]` is one token
/// (inner whitespace removed), so values with spaces parse like compact ones.
class MdpaLineReader {
public:
    /// @throws InputError if the file cannot be opened.
    explicit MdpaLineReader(const std::string& file_name);

    /// Advances to the next non-empty line. Returns false at the end of the file.
    bool Next();
    const std::vector<std::string>& Tokens() const { return mTokens; }
    /// 1-based number of the current line.
    std::size_t LineNumber() const { return mLineNumber; }
    const std::string& FileName() const { return mFileName; }
    /// "<file>:<line>: " prefix for messages about the current line.
    std::string Where() const;

private:
    void Tokenize(const std::string& line);

    std::string mFileName;
    std::ifstream mStream;
    std::string mLine;
    std::vector<std::string> mTokens;
    std::size_t mLineNumber = 0;
};

}  // namespace contact_app
