// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/serializer.h"

#include <cstdint>
#include <cstring>

namespace contact_app {

void Serializer::Write(const void* data, std::size_t size) {
    mBuffer.append(static_cast<const char*>(data), size);
}

void Serializer::Read(void* data, std::size_t size, const char* what) {
    CONTACT_CHECK(mPosition + size <= mBuffer.size(), InputError, "Serializer: buffer truncated while reading ", what,
                  " at byte ", mPosition, " of ", mBuffer.size(),
                  "\n  fix: pass the complete bytes returned by Save() of the same class");
    std::memcpy(data, mBuffer.data() + mPosition, size);
    mPosition += size;
}

void Serializer::WriteSize(std::size_t value) {
    const auto v = static_cast<std::uint64_t>(value);
    Write(&v, sizeof(v));
}

std::size_t Serializer::ReadSize() {
    std::uint64_t v = 0;
    Read(&v, sizeof(v), "a size");
    return static_cast<std::size_t>(v);
}

void Serializer::WriteDouble(double value) {
    Write(&value, sizeof(value));
}

double Serializer::ReadDouble() {
    double value = 0.0;
    Read(&value, sizeof(value), "a double");
    return value;
}

void Serializer::WriteHeader(const char* tag, char type) {
    const std::size_t length = std::strlen(tag);
    WriteSize(length);
    Write(tag, length);
    Write(&type, 1);
}

void Serializer::ReadHeader(const char* tag, char type) {
    const std::size_t length = ReadSize();
    // A garbage length (corrupted buffer) must not allocate: it cannot exceed what is left.
    CONTACT_CHECK(length <= mBuffer.size() - mPosition, InputError, "Serializer: expected entry '", tag,
                  "' but the buffer holds a corrupted tag (length ", length, " at byte ", mPosition - 8,
                  ")\n  fix: pass the unmodified bytes returned by Save() of the same class");
    std::string found(length, '\0');
    Read(found.data(), length, "a tag");
    CONTACT_CHECK(found == tag, InputError, "Serializer: expected entry '", tag, "' but found '", found,
                  "'\n  fix: load the buffer into an object of the class (and version) that saved it");
    char stored = 0;
    Read(&stored, 1, "a type code");
    CONTACT_CHECK(stored == type, InputError, "Serializer: entry '", tag, "' has type code '", stored, "', expected '",
                  type, "'\n  fix: load the buffer into an object of the class that saved it");
}

void Serializer::Save(const char* tag, bool value) {
    WriteHeader(tag, 'b');
    const char v = value ? 1 : 0;
    Write(&v, 1);
}

void Serializer::Save(const char* tag, int value) {
    WriteHeader(tag, 'i');
    const auto v = static_cast<std::int64_t>(value);
    Write(&v, sizeof(v));
}

void Serializer::Save(const char* tag, std::size_t value) {
    WriteHeader(tag, 'z');
    WriteSize(value);
}

void Serializer::Save(const char* tag, double value) {
    WriteHeader(tag, 'd');
    WriteDouble(value);
}

void Serializer::Load(const char* tag, bool& value) {
    ReadHeader(tag, 'b');
    char v = 0;
    Read(&v, 1, tag);
    value = v != 0;
}

void Serializer::Load(const char* tag, int& value) {
    ReadHeader(tag, 'i');
    std::int64_t v = 0;
    Read(&v, sizeof(v), tag);
    value = static_cast<int>(v);
}

void Serializer::Load(const char* tag, std::size_t& value) {
    ReadHeader(tag, 'z');
    value = ReadSize();
}

void Serializer::Load(const char* tag, double& value) {
    ReadHeader(tag, 'd');
    value = ReadDouble();
}

}  // namespace contact_app
