// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <string>

#include <Eigen/Core>

#include "contact_app/kernel/exceptions.h"

namespace contact_app {

/// A minimal binary archive for restarting per-entity state (Kratos Serializer, save/load of the members a
/// restart needs). Every value is written as [tag, type code, payload]; Load reads in the same order and checks
/// the tag and the type, so a buffer from another class, another version or a corrupted file is an InputError
/// naming the expected and the found tag instead of silently wrong state. Not portable across endianness.
class Serializer {
public:
    Serializer() = default;
    /// Loading archive over @p data (as returned by Data()).
    explicit Serializer(std::string data) : mBuffer(std::move(data)) {}

    /// The bytes written so far.
    const std::string& Data() const { return mBuffer; }
    /// True once every byte has been read.
    bool AtEnd() const { return mPosition == mBuffer.size(); }

    void Save(const char* tag, bool value);
    void Save(const char* tag, int value);
    void Save(const char* tag, std::size_t value);
    void Save(const char* tag, double value);
    /// Any double Eigen matrix or vector, fixed or dynamic (Array3 included): rows, cols, column-major data.
    template <int R, int C, int O, int MR, int MC>
    void Save(const char* tag, const Eigen::Matrix<double, R, C, O, MR, MC>& value) {
        WriteHeader(tag, 'm');
        WriteSize(static_cast<std::size_t>(value.rows()));
        WriteSize(static_cast<std::size_t>(value.cols()));
        for (Eigen::Index c = 0; c < value.cols(); ++c)
            for (Eigen::Index r = 0; r < value.rows(); ++r) WriteDouble(value(r, c));
    }

    /// @throws InputError on a tag or type mismatch or a truncated buffer
    void Load(const char* tag, bool& value);
    void Load(const char* tag, int& value);
    void Load(const char* tag, std::size_t& value);
    void Load(const char* tag, double& value);
    /// @throws InputError also when a fixed-size destination does not have the stored shape
    template <int R, int C, int O, int MR, int MC>
    void Load(const char* tag, Eigen::Matrix<double, R, C, O, MR, MC>& value) {
        ReadHeader(tag, 'm');
        const std::size_t rows = ReadSize(), cols = ReadSize();
        CONTACT_CHECK((R == Eigen::Dynamic || rows == static_cast<std::size_t>(R)) &&
                          (C == Eigen::Dynamic || cols == static_cast<std::size_t>(C)),
                      InputError, "Serializer: entry '", tag, "' stores a ", rows, "x", cols, " matrix, expected ", R,
                      "x", C, " (-1 = any)\n  fix: load the buffer into the same class that saved it");
        value.resize(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
        for (Eigen::Index c = 0; c < value.cols(); ++c)
            for (Eigen::Index r = 0; r < value.rows(); ++r) value(r, c) = ReadDouble();
    }

private:
    void WriteHeader(const char* tag, char type);
    void ReadHeader(const char* tag, char type);
    void WriteSize(std::size_t value);
    std::size_t ReadSize();
    void WriteDouble(double value);
    double ReadDouble();
    void Write(const void* data, std::size_t size);
    void Read(void* data, std::size_t size, const char* what);

    std::string mBuffer;
    std::size_t mPosition = 0;
};

}  // namespace contact_app
