// SPDX-License-Identifier: BSD-3-Clause
/// Serializer: round trip of every supported type; tag, type, shape mismatches and truncation are InputErrors
/// that name what was expected and what was found.
#include <functional>

#include <gtest/gtest.h>

#include "contact_app/kernel/serializer.h"
#include "contact_app/kernel/types.h"

namespace contact_app::testing {
namespace {

TEST(ConditionSerializationArchive, RoundTripsEverySupportedType) {
    Serializer out;
    const Eigen::Matrix<double, 2, 3> fixed = (Eigen::Matrix<double, 2, 3>() << 1, 2, 3, 4, 5, 6).finished();
    const Matrix dynamic = Matrix::Random(4, 2);
    out.Save("flag", true);
    out.Save("count", -7);
    out.Save("size", std::size_t(123456789012));
    out.Save("value", 0.1);
    out.Save("vector", Array3(1.0, -2.0, 3.5));
    out.Save("fixed", fixed);
    out.Save("dynamic", dynamic);
    out.Save("empty", Vector());
    Serializer in(out.Data());
    bool flag = false;
    int count = 0;
    std::size_t size = 0;
    double value = 0.0;
    Array3 vector;
    Eigen::Matrix<double, 2, 3> fixed_in;
    Matrix dynamic_in;
    Vector empty_in = Vector::Ones(3);
    in.Load("flag", flag);
    in.Load("count", count);
    in.Load("size", size);
    in.Load("value", value);
    in.Load("vector", vector);
    in.Load("fixed", fixed_in);
    in.Load("dynamic", dynamic_in);
    in.Load("empty", empty_in);
    EXPECT_TRUE(in.AtEnd());
    EXPECT_TRUE(flag);
    EXPECT_EQ(count, -7);
    EXPECT_EQ(size, std::size_t(123456789012));
    EXPECT_EQ(value, 0.1);
    EXPECT_EQ(vector, Array3(1.0, -2.0, 3.5));
    EXPECT_EQ(fixed_in, fixed);
    EXPECT_EQ(dynamic_in, dynamic);
    EXPECT_EQ(empty_in.size(), 0);
}

std::string MessageOf(const std::function<void()>& body) {
    try {
        body();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no InputError";
}

TEST(ConditionSerializationArchive, MismatchesAndCorruptionAreInputErrorsNamingBothSides) {
    Serializer out;
    out.Save("PreviousD", Matrix(Matrix::Identity(2, 2)));
    out.Save("Overlap", true);
    {
        Serializer in(out.Data());
        Matrix m;
        const std::string message = MessageOf([&] { in.Load("PairedNormal", m); });
        EXPECT_NE(message.find("expected entry 'PairedNormal' but found 'PreviousD'"), std::string::npos) << message;
    }
    {
        Serializer in(out.Data());
        Eigen::Matrix3d m;
        const std::string message = MessageOf([&] { in.Load("PreviousD", m); });
        EXPECT_NE(message.find("stores a 2x2 matrix, expected 3x3"), std::string::npos) << message;
    }
    {
        Serializer in(out.Data());
        Matrix m;
        double d = 0.0;
        in.Load("PreviousD", m);
        const std::string message = MessageOf([&] { in.Load("Overlap", d); });
        EXPECT_NE(message.find("type code"), std::string::npos) << message;
    }
    {
        Serializer in(out.Data().substr(0, out.Data().size() - 20));
        Matrix m;
        const std::string message = MessageOf([&] { in.Load("PreviousD", m); });
        EXPECT_NE(message.find("truncated"), std::string::npos) << message;
    }
    {
        std::string corrupted = out.Data();
        corrupted[0] = '\x7f';  // garbage tag length
        Serializer in(corrupted);
        Matrix m;
        const std::string message = MessageOf([&] { in.Load("PreviousD", m); });
        EXPECT_NE(message.find("corrupted"), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace contact_app::testing
