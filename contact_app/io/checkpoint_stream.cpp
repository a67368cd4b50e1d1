// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/io/checkpoint_stream.h"

namespace contact_app::detail {

void CheckpointWriter::PutString(const std::string& value) {
    PutSize(value.size());
    mBuffer.append(value);
}

void CheckpointWriter::PutMatrix(const Matrix& value) {
    PutSize(static_cast<std::size_t>(value.rows()));
    PutSize(static_cast<std::size_t>(value.cols()));
    mBuffer.append(reinterpret_cast<const char*>(value.data()), sizeof(double) * static_cast<std::size_t>(value.size()));
}

void CheckpointWriter::PutVector(const Vector& value) {
    PutSize(static_cast<std::size_t>(value.size()));
    mBuffer.append(reinterpret_cast<const char*>(value.data()), sizeof(double) * static_cast<std::size_t>(value.size()));
}

void CheckpointWriter::PutFlags(const Flags& flags) {
    Put(flags.DefinedBits());
    Put(flags.ValueBits());
}

void CheckpointReader::Need(std::size_t bytes, const char* what) const {
    if (bytes > mData.size() - mPosition)
        Fail(std::string("the data ends while reading ") + what);
}

void CheckpointReader::Fail(const std::string& what) const {
    CONTACT_THROW(InputError, "restart file \"", mSource, "\": ", what, " (payload byte ", mPosition,
                  ")\n  expected: a checkpoint written by this format version of contact_app",
                  "\n  fix: load an intact checkpoint (an earlier one of the same run, or run again from the mesh)");
}

std::size_t CheckpointReader::GetCount(std::size_t item_bytes) {
    const auto count = Get<std::uint64_t>();
    if (item_bytes > 0 && count > (mData.size() - mPosition) / item_bytes)
        Fail("a count of " + std::to_string(count) + " items does not fit in the rest of the data");
    return static_cast<std::size_t>(count);
}

std::string CheckpointReader::GetString() {
    const std::size_t size = GetCount(1);
    std::string value(mData.data() + mPosition, size);
    mPosition += size;
    return value;
}

Matrix CheckpointReader::GetMatrix() {
    const std::size_t rows = GetCount(0);
    const std::size_t cols = GetCount(0);
    if (rows != 0 && cols > (mData.size() - mPosition) / sizeof(double) / rows)
        Fail("a matrix of " + std::to_string(rows) + "x" + std::to_string(cols) + " does not fit in the data");
    Matrix value(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
    std::memcpy(value.data(), mData.data() + mPosition, sizeof(double) * rows * cols);
    mPosition += sizeof(double) * rows * cols;
    return value;
}

Vector CheckpointReader::GetVector() {
    const std::size_t size = GetCount(sizeof(double));
    Vector value(static_cast<Eigen::Index>(size));
    std::memcpy(value.data(), mData.data() + mPosition, sizeof(double) * size);
    mPosition += sizeof(double) * size;
    return value;
}

void CheckpointReader::GetDoubles(double* out, std::size_t count) {
    if (count > (mData.size() - mPosition) / sizeof(double)) Fail("the data ends inside a block of values");
    std::memcpy(out, mData.data() + mPosition, count * sizeof(double));
    mPosition += count * sizeof(double);
}

Flags CheckpointReader::GetFlags() {
    const auto defined = Get<std::uint64_t>();
    const auto values = Get<std::uint64_t>();
    Flags flags;
    for (int bit = 0; bit < 64; ++bit)
        if ((defined >> bit) & 1u) flags.Set(Flags::Create(bit), ((values >> bit) & 1u) != 0);
    return flags;
}

void CheckpointReader::Section(const char (&marker)[5]) {
    Need(4, "a section marker");
    if (std::memcmp(mData.data() + mPosition, marker, 4) != 0)
        Fail(std::string("expected the section \"") + marker + "\" but found other data");
    mPosition += 4;
}

}  // namespace contact_app::detail
