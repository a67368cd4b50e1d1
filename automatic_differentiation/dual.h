// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>

namespace contact_app {

/// Forward-mode AD scalar with a compile-time number of partial derivatives: a value v and a gradient
/// ∂v/∂x ∈ ℝ^N (Eigen fixed-size vector). Arithmetic propagates the chain rule; comparisons look at the
/// value only, so branches (clipping, sorting, pivoting) follow the primal computation. Compared with
/// Eigen's AutoDiffScalar in benchmarks/ad_benchmark.cpp (figures in docs/theory/mortar.md, "AD scalar").
/// @tparam N number of independent variables (e.g. d·(n_s+n_m) coordinates of a mortar pair)
template <int N>
class Dual {
public:
    using Gradient = Eigen::Matrix<double, N, 1>;
    static constexpr int Size = N;

    Dual() : mValue(0.0), mGradient(Gradient::Zero()) {}
    /// A constant (zero gradient); implicit so that double literals mix with Dual.
    Dual(double value) : mValue(value), mGradient(Gradient::Zero()) {}  // NOLINT(google-explicit-constructor)
    /// @param[in] gradient any Eigen expression of size N (evaluated once, directly into the member)
    template <class TDerived>
    Dual(double value, const Eigen::MatrixBase<TDerived>& gradient) : mValue(value), mGradient(gradient) {}
    /// @brief The independent variable number @p index (0 ≤ index < N) with value @p value.
    static Dual Variable(double value, int index) {
        Dual result(value);
        result.mGradient[index] = 1.0;
        return result;
    }

    double Value() const { return mValue; }
    const Gradient& Derivatives() const { return mGradient; }
    Gradient& Derivatives() { return mGradient; }

    Dual& operator+=(const Dual& b) { mValue += b.mValue; mGradient += b.mGradient; return *this; }
    Dual& operator-=(const Dual& b) { mValue -= b.mValue; mGradient -= b.mGradient; return *this; }
    Dual& operator*=(const Dual& b) {
        mGradient = mGradient * b.mValue + b.mGradient * mValue;  // element-wise: in-place is alias-safe
        mValue *= b.mValue;
        return *this;
    }
    Dual& operator/=(const Dual& b) {
        const double inv = 1.0 / b.mValue;
        mValue *= inv;
        mGradient = (mGradient - b.mGradient * mValue) * inv;
        return *this;
    }
    Dual& operator+=(double b) { mValue += b; return *this; }
    Dual& operator-=(double b) { mValue -= b; return *this; }
    Dual& operator*=(double b) { mValue *= b; mGradient *= b; return *this; }
    Dual& operator/=(double b) { return *this *= (1.0 / b); }
    Dual operator-() const { return Dual(-mValue, -mGradient); }
    Dual operator+() const { return *this; }

private:
    double mValue;
    Gradient mGradient;
};

/// True for Dual<N>, false for double.
template <class T>
struct IsDual : std::false_type {};
template <int N>
struct IsDual<Dual<N>> : std::true_type {};

// -- Value access that works for double and Dual alike --
inline double Value(double x) { return x; }
template <int N>
double Value(const Dual<N>& x) { return x.Value(); }

// -- Arithmetic (each result is built directly from one Eigen expression: no temporaries) --
template <int N>
Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) { return Dual<N>(a.Value() + b.Value(), a.Derivatives() + b.Derivatives()); }
template <int N>
Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) { return Dual<N>(a.Value() - b.Value(), a.Derivatives() - b.Derivatives()); }
template <int N>
Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) {
    return Dual<N>(a.Value() * b.Value(), a.Derivatives() * b.Value() + b.Derivatives() * a.Value());
}
template <int N>
Dual<N> operator/(const Dual<N>& a, const Dual<N>& b) {
    const double inv = 1.0 / b.Value();
    const double v = a.Value() * inv;
    return Dual<N>(v, (a.Derivatives() - b.Derivatives() * v) * inv);
}
template <int N> Dual<N> operator+(const Dual<N>& a, double b) { return Dual<N>(a.Value() + b, a.Derivatives()); }
template <int N> Dual<N> operator-(const Dual<N>& a, double b) { return Dual<N>(a.Value() - b, a.Derivatives()); }
template <int N> Dual<N> operator*(const Dual<N>& a, double b) { return Dual<N>(a.Value() * b, a.Derivatives() * b); }
template <int N> Dual<N> operator/(const Dual<N>& a, double b) { return a * (1.0 / b); }
template <int N> Dual<N> operator+(double a, const Dual<N>& b) { return b + a; }
template <int N> Dual<N> operator-(double a, const Dual<N>& b) { return Dual<N>(a - b.Value(), -b.Derivatives()); }
template <int N> Dual<N> operator*(double a, const Dual<N>& b) { return b * a; }
template <int N>
Dual<N> operator/(double a, const Dual<N>& b) {
    const double v = a / b.Value();
    return Dual<N>(v, b.Derivatives() * (-v / b.Value()));
}

// -- Comparisons (on the value) --
#define CONTACT_APP_DUAL_COMPARISON(OP)                                                                  \
    template <int N> bool operator OP(const Dual<N>& a, const Dual<N>& b) { return a.Value() OP b.Value(); } \
    template <int N> bool operator OP(const Dual<N>& a, double b) { return a.Value() OP b; }               \
    template <int N> bool operator OP(double a, const Dual<N>& b) { return a OP b.Value(); }
CONTACT_APP_DUAL_COMPARISON(<)
CONTACT_APP_DUAL_COMPARISON(>)
CONTACT_APP_DUAL_COMPARISON(<=)
CONTACT_APP_DUAL_COMPARISON(>=)
CONTACT_APP_DUAL_COMPARISON(==)
CONTACT_APP_DUAL_COMPARISON(!=)
#undef CONTACT_APP_DUAL_COMPARISON

// -- Elementary functions (f(v), f'(v)·∇v) --
template <int N>
Dual<N> sqrt(const Dual<N>& x) {
    const double s = std::sqrt(x.Value());
    return Dual<N>(s, x.Derivatives() * (s > 0.0 ? 0.5 / s : 0.0));  // ∇√0 := 0 instead of ∞ (no NaN)
}
template <int N>
Dual<N> abs(const Dual<N>& x) { return x.Value() < 0.0 ? -x : x; }
template <int N>
Dual<N> fabs(const Dual<N>& x) { return abs(x); }
template <int N>
Dual<N> pow(const Dual<N>& x, double p) {
    const double v = std::pow(x.Value(), p);
    return Dual<N>(v, x.Derivatives() * (p * std::pow(x.Value(), p - 1.0)));
}
template <int N>
Dual<N> sin(const Dual<N>& x) { return Dual<N>(std::sin(x.Value()), x.Derivatives() * std::cos(x.Value())); }
template <int N>
Dual<N> cos(const Dual<N>& x) { return Dual<N>(std::cos(x.Value()), x.Derivatives() * -std::sin(x.Value())); }
template <int N>
Dual<N> exp(const Dual<N>& x) {
    const double e = std::exp(x.Value());
    return Dual<N>(e, x.Derivatives() * e);
}
template <int N>
Dual<N> log(const Dual<N>& x) { return Dual<N>(std::log(x.Value()), x.Derivatives() / x.Value()); }
template <int N>
Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
    const double r2 = x.Value() * x.Value() + y.Value() * y.Value();
    const double scale = r2 > 0.0 ? 1.0 / r2 : 0.0;
    return Dual<N>(std::atan2(y.Value(), x.Value()),
                   (y.Derivatives() * x.Value() - x.Derivatives() * y.Value()) * scale);
}
template <int N>
bool isfinite(const Dual<N>& x) { return std::isfinite(x.Value()) && x.Derivatives().allFinite(); }
template <int N>
Dual<N> abs2(const Dual<N>& x) { return x * x; }
template <int N>
const Dual<N>& conj(const Dual<N>& x) { return x; }
template <int N>
const Dual<N>& real(const Dual<N>& x) { return x; }
template <int N>
Dual<N> imag(const Dual<N>&) { return Dual<N>(0.0); }

}  // namespace contact_app

namespace Eigen {
template <int N>
struct NumTraits<contact_app::Dual<N>> : NumTraits<double> {
    using Real = contact_app::Dual<N>;
    using NonInteger = contact_app::Dual<N>;
    using Nested = contact_app::Dual<N>;
    using Literal = double;
    enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = N + 1,
           AddCost = N + 1, MulCost = 2 * N + 1 };
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<contact_app::Dual<N>, double, BinaryOp> {
    using ReturnType = contact_app::Dual<N>;
};
template <int N, typename BinaryOp>
struct ScalarBinaryOpTraits<double, contact_app::Dual<N>, BinaryOp> {
    using ReturnType = contact_app::Dual<N>;
};
}  // namespace Eigen
