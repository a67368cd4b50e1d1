// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace contact_app {

/// Splits an `.mdpa` file into lines of whitespace-separated tokens, dropping `//` comments and
/// blank lines. A bracketed value such as `[3] (1.0, 2.0, 3.0)` or `[0.25, 0.25]` is one token
/// (inner whitespace removed), so values with spaces parse like compact ones. Every line read is
/// checked to be UTF-8 text without NUL bytes (names and comments included).
class MdpaLineReader {
public:
    /// @throws InputError if the file is missing, unreadable, or not a regular file (a folder, a
    /// device such as /dev/zero, a FIFO).
    explicit MdpaLineReader(const std::string& file_name);

    /// Advances to the next non-empty line. Returns false at the end of the file.
    /// @throws InputError for bytes that are not UTF-8 or a NUL byte (line, byte offset), and read errors.
    bool Next();
    const std::vector<std::string>& Tokens() const { return mTokens; }
    /// 1-based number of the current line.
    std::size_t LineNumber() const { return mLineNumber; }
    const std::string& FileName() const { return mFileName; }
    /// "<file>:<line>: " prefix for messages about the current line.
    std::string Where() const;

private:
    void Tokenize(const std::string& line);
    void CheckText() const;

    std::string mFileName;
    std::ifstream mStream;
    std::string mLine;
    std::vector<std::string> mTokens;
    std::size_t mLineNumber = 0;
    std::size_t mLineOffset = 0;  // byte offset of the current line in the file
};

}  // namespace contact_app
