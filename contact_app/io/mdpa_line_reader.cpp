// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/io/mdpa_line_reader.h"

#include <cctype>
#include <filesystem>

#include "contact_app/io/mdpa_values.h"
#include "contact_app/kernel/exceptions.h"

namespace contact_app {

MdpaLineReader::MdpaLineReader(const std::string& file_name) : mFileName(file_name) {
    // A folder opens and reads as empty; a device or FIFO is read forever: refuse both up front.
    std::error_code error;
    const auto status = std::filesystem::status(file_name, error);
    CONTACT_CHECK(!std::filesystem::exists(status) || std::filesystem::is_regular_file(status), InputError,
                  "the mesh file ", mdpa::Quoted(file_name), " is ",
                  std::filesystem::is_directory(status) ? "a folder" : "not a regular file",
                  "\n  expected: a file on disk (not a folder, device, FIFO or socket: /dev/zero would be read forever)",
                  "\n  fix:      name the .mdpa file itself");
    mStream.open(file_name, std::ios::binary);
    CONTACT_CHECK(mStream.good(), InputError, "cannot open the mesh file ", mdpa::Quoted(file_name),
                  "\n  fix: check the path (model_import_settings.input_filename is given without the .mdpa extension)");
}

std::string MdpaLineReader::Where() const { return mFileName + ":" + std::to_string(mLineNumber) + ": "; }

bool MdpaLineReader::Next() {
    while (std::getline(mStream, mLine)) {
        ++mLineNumber;
        CheckText();
        mLineOffset += mLine.size() + 1;
        Tokenize(mLine);
        if (!mTokens.empty()) return true;
    }
    CONTACT_CHECK(!mStream.bad(), InputError, "cannot read the mesh file ", mdpa::Quoted(mFileName), " after line ",
                  mLineNumber, "\n  fix: check the file and the device it is on");
    return false;
}

namespace {

/// Length of the UTF-8 sequence starting at text[i], or 0 if it is not a valid one.
std::size_t Utf8SequenceLength(const std::string& text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return k < text.size() ? static_cast<unsigned char>(text[k]) : 0u; };
    const unsigned lead = byte(i);
    const auto continuation = [&](std::size_t k, unsigned low, unsigned high) {
        return byte(k) >= low && byte(k) <= high;
    };
    if (lead >= 0xC2 && lead <= 0xDF) return continuation(i + 1, 0x80, 0xBF) ? 2 : 0;
    if (lead >= 0xE0 && lead <= 0xEF) {
        // E0 excludes overlong forms, ED the UTF-16 surrogates.
        const unsigned low = lead == 0xE0 ? 0xA0 : 0x80, high = lead == 0xED ? 0x9F : 0xBF;
        return continuation(i + 1, low, high) && continuation(i + 2, 0x80, 0xBF) ? 3 : 0;
    }
    if (lead >= 0xF0 && lead <= 0xF4) {
        const unsigned low = lead == 0xF0 ? 0x90 : 0x80, high = lead == 0xF4 ? 0x8F : 0xBF;
        return continuation(i + 1, low, high) && continuation(i + 2, 0x80, 0xBF) && continuation(i + 3, 0x80, 0xBF)
                   ? 4
                   : 0;
    }
    return 0;
}

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

void MdpaLineReader::CheckText() const {
    for (std::size_t i = 0; i < mLine.size();) {
        const auto c = static_cast<unsigned char>(mLine[i]);
        if (c != 0 && c < 0x80) {
            ++i;
            continue;
        }
        const std::size_t length = c == 0 ? 0 : Utf8SequenceLength(mLine, i);
        if (length > 0) {
            i += length;
            continue;
        }
        static constexpr const char* kHex = "0123456789abcdef";
        const std::string hex{'0', 'x', kHex[c >> 4], kHex[c & 15]};
        CONTACT_THROW(InputError, Where(), c == 0 ? "a NUL byte" : "byte " + hex, " at byte offset ", mLineOffset + i,
                      " (column ", i + 1, ") ", c == 0 ? "is not text" : "is not UTF-8",
                      "\n  expected: a UTF-8 (or ASCII) text file, names and comments included",
                      "\n  fix:      save the mesh as UTF-8, or remove the stray bytes");
    }
}

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
