// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "contact_app/kernel/data_value_container.h"
#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/flags.h"

namespace contact_app::detail {

/// Untagged binary output of ModelPartCheckpoint: trivially copyable values in native order, strings and
/// matrices with their sizes, and four-character section markers that the reader checks.
class CheckpointWriter {
public:
    template <class T>
    void Put(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        mBuffer.append(reinterpret_cast<const char*>(&value), sizeof(T));
    }
    void PutSize(std::size_t value) { Put(static_cast<std::uint64_t>(value)); }
    void PutString(const std::string& value);
    void PutMatrix(const Matrix& value);
    void PutVector(const Vector& value);
    void PutFlags(const Flags& flags);
    void PutArray3(const Array3& value) { mBuffer.append(reinterpret_cast<const char*>(value.data()), 3 * sizeof(double)); }
    void Section(const char (&marker)[5]) { mBuffer.append(marker, 4); }
    std::string& Buffer() { return mBuffer; }

private:
    std::string mBuffer;
};

/// Input side of CheckpointWriter: every read is bounds-checked and a failure is an InputError naming the
/// checkpoint file and the byte offset.
class CheckpointReader {
public:
    CheckpointReader(const std::string& data, std::size_t begin, const std::string& source)
        : mData(data), mPosition(begin), mSource(source) {}

    template <class T>
    T Get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T value;
        Need(sizeof(T), "a value");
        std::memcpy(&value, mData.data() + mPosition, sizeof(T));
        mPosition += sizeof(T);
        return value;
    }
    /// A count of items of at least @p item_bytes each (bounded by what is left).
    std::size_t GetCount(std::size_t item_bytes);
    std::string GetString();
    Matrix GetMatrix();
    Vector GetVector();
    Flags GetFlags();
    Array3 GetArray3() {
        Array3 value;
        GetDoubles(value.data(), 3);
        return value;
    }
    /// Reads @p count doubles into @p out.
    void GetDoubles(double* out, std::size_t count);
    void Section(const char (&marker)[5]);
    [[noreturn]] void Fail(const std::string& what) const;
    bool AtEnd() const { return mPosition == mData.size(); }
    const std::string& Source() const { return mSource; }

private:
    void Need(std::size_t bytes, const char* what) const;

    const std::string& mData;
    std::size_t mPosition;
    const std::string& mSource;
};

}  // namespace contact_app::detail
