// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#if defined(__GNUC__) || defined(__clang__)
#define CONTACT_APP_AD_INLINE __attribute__((always_inline)) inline
#define CONTACT_APP_AD_LAMBDA_INLINE __attribute__((always_inline))
#else
#define CONTACT_APP_AD_INLINE EIGEN_STRONG_INLINE
#define CONTACT_APP_AD_LAMBDA_INLINE
#endif

namespace contact_app {

namespace detail {
/// SIMD packet of doubles of the target (SSE2: 2, AVX: 4, AVX-512: 8) and its width.
using DualPacket = Eigen::internal::packet_traits<double>::type;
constexpr int kDualPacketSize = Eigen::internal::packet_traits<double>::size;

template <class TBody, int... TPackets>
CONTACT_APP_AD_INLINE void ForEachPacket(TBody& body, std::integer_sequence<int, TPackets...>) noexcept {
    (body(TPackets * kDualPacketSize, DualPacket{}), ...);
}
template <int TOffset, class TBody, int... TEntries>
CONTACT_APP_AD_INLINE void ForEachEntry(TBody& body, std::integer_sequence<int, TEntries...>) noexcept {
    (body(TOffset + TEntries, double{}), ...);
}

/// Calls body(i, DualPacket{}) for every full packet of a length-N gradient, then body(i, double{}) for the
/// remaining entries, fully unrolled at compile time; body is written once for both (Eigen's packet
/// primitives are overloaded for double).
template <int N, class TBody>
CONTACT_APP_AD_INLINE void ForEachGradientPacket(TBody&& body) noexcept {
    constexpr int packets = kDualPacketSize > 1 ? N / kDualPacketSize : 0;
    constexpr int tail_start = packets * kDualPacketSize;
    ForEachPacket(body, std::make_integer_sequence<int, packets>{});
    ForEachEntry<tail_start>(body, std::make_integer_sequence<int, N - tail_start>{});
}
}  // namespace detail

/// Forward-mode AD scalar with a compile-time number of partial derivatives: a value v and a gradient
/// ∂v/∂x ∈ ℝ^N (a plain array, seen as an Eigen vector through Derivatives()). Arithmetic propagates the
/// chain rule; comparisons look at the value only, so branches (clipping, sorting, pivoting) follow the
/// primal computation. Every operation is
/// a forced-inline, fully unrolled sequence of SIMD packet operations writing the result's gradient once
/// (no out-of-line Eigen assignment loops, no runtime loop, no zero-filled temporaries). Faster than Eigen's
/// AutoDiffScalar in benchmarks/ad_benchmark.cpp and mortar_benchmark.cpp (docs/theory/mortar.md, "AD scalar").
/// @tparam N number of independent variables (e.g. d·(n_s+n_m) coordinates of a mortar pair)
template <int N>
class Dual {
public:
    using Gradient = Eigen::Matrix<double, N, 1>;
    static constexpr int Size = N;

    /// Like double: `Dual x;` leaves value and gradient uninitialised (cheap element construction inside Eigen
    /// matrices, which are always assigned before use); `Dual{}` / `Dual()` value-initialise to zero.
    Dual() = default;
    /// A constant (zero gradient); implicit so that double literals mix with Dual.
    CONTACT_APP_AD_INLINE Dual(double value) noexcept : mValue(value) {
        SetZero();
    }  // NOLINT(google-explicit-constructor)
    /// @param[in] value the primal value v
    /// @param[in] gradient any Eigen expression of size N (evaluated once, directly into the member)
    template <class TDerived>
    Dual(double value, const Eigen::MatrixBase<TDerived>& gradient) : mValue(value) {
        Derivatives() = gradient;
    }
    /// @brief The independent variable number @p index (0 ≤ index < N) with value @p value.
    static Dual Variable(double value, int index) {
        Dual result(value);
        result.mGradient[index] = 1.0;
        return result;
    }

    CONTACT_APP_AD_INLINE double Value() const noexcept { return mValue; }
    /// The gradient as an Eigen vector view (valid while this Dual lives; copy it into a Gradient to keep it).
    CONTACT_APP_AD_INLINE Eigen::Map<const Gradient, Eigen::Aligned16> Derivatives() const noexcept {
        return Eigen::Map<const Gradient, Eigen::Aligned16>(mGradient);
    }
    CONTACT_APP_AD_INLINE Eigen::Map<Gradient, Eigen::Aligned16> Derivatives() noexcept {
        return Eigen::Map<Gradient, Eigen::Aligned16>(mGradient);
    }

    // -- Gradient kernels: r = op(a, b) element-wise, r may alias a or b (each entry is read before written) --
    /// Result with value @p value and gradient α·a (uninitialised until the kernel writes it).
    static CONTACT_APP_AD_INLINE Dual Scaled(double value, const Dual& a, double alpha) noexcept {
        Dual r(value, Uninitialised{});
        r.AssignScaled(a, alpha);
        return r;
    }
    /// Result with value @p value and gradient α·a + β·b.
    static CONTACT_APP_AD_INLINE Dual Combined(double value, const Dual& a, double alpha, const Dual& b,
                                               double beta) noexcept {
        Dual r(value, Uninitialised{});
        r.AssignCombined(a, alpha, b, beta);
        return r;
    }
    static CONTACT_APP_AD_INLINE Dual Sum(double value, const Dual& a, const Dual& b) noexcept {
        Dual r(value, Uninitialised{});
        const double *ga = a.mGradient, *gb = b.mGradient;
        double* gr = r.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(gr + i, ei::padd(ei::ploadu<P>(ga + i), ei::ploadu<P>(gb + i)));
        });
        return r;
    }
    static CONTACT_APP_AD_INLINE Dual Difference(double value, const Dual& a, const Dual& b) noexcept {
        Dual r(value, Uninitialised{});
        const double *ga = a.mGradient, *gb = b.mGradient;
        double* gr = r.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(gr + i, ei::psub(ei::ploadu<P>(ga + i), ei::ploadu<P>(gb + i)));
        });
        return r;
    }
    /// Result with value @p value and gradient (a − v·b)·inv (the quotient rule with v = a/b, inv = 1/b).
    static CONTACT_APP_AD_INLINE Dual Quotient(double value, const Dual& a, const Dual& b, double inv) noexcept {
        Dual r(value, Uninitialised{});
        const double *ga = a.mGradient, *gb = b.mGradient;
        double* gr = r.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(gr + i,
                        ei::pmul(ei::psub(ei::ploadu<P>(ga + i), ei::pmul(ei::ploadu<P>(gb + i), ei::pset1<P>(value))),
                                 ei::pset1<P>(inv)));
        });
        return r;
    }

    CONTACT_APP_AD_INLINE Dual& operator+=(const Dual& b) noexcept {
        mValue += b.mValue;
        double* g = mGradient;
        const double* gb = b.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(g + i, ei::padd(ei::ploadu<P>(g + i), ei::ploadu<P>(gb + i)));
        });
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator-=(const Dual& b) noexcept {
        mValue -= b.mValue;
        double* g = mGradient;
        const double* gb = b.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(g + i, ei::psub(ei::ploadu<P>(g + i), ei::ploadu<P>(gb + i)));
        });
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator*=(const Dual& b) noexcept {
        AssignCombined(*this, b.mValue, b, mValue);  // element-wise: in-place is alias-safe
        mValue *= b.mValue;
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator/=(const Dual& b) noexcept {
        const double inv = 1.0 / b.mValue;
        mValue *= inv;
        const double v = mValue;
        double* g = mGradient;
        const double* gb = b.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(g + i,
                        ei::pmul(ei::psub(ei::ploadu<P>(g + i), ei::pmul(ei::ploadu<P>(gb + i), ei::pset1<P>(v))),
                                 ei::pset1<P>(inv)));
        });
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator+=(double b) noexcept {
        mValue += b;
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator-=(double b) noexcept {
        mValue -= b;
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator*=(double b) noexcept {
        mValue *= b;
        AssignScaled(*this, b);
        return *this;
    }
    CONTACT_APP_AD_INLINE Dual& operator/=(double b) noexcept { return *this *= (1.0 / b); }
    CONTACT_APP_AD_INLINE Dual operator-() const noexcept { return Scaled(-mValue, *this, -1.0); }
    CONTACT_APP_AD_INLINE Dual operator+() const noexcept { return *this; }

private:
    struct Uninitialised {};
    CONTACT_APP_AD_INLINE Dual(double value, Uninitialised) noexcept : mValue(value) {}

    CONTACT_APP_AD_INLINE void SetZero() noexcept {
        double* g = mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            Eigen::internal::pstoreu(g + i, Eigen::internal::pset1<P>(0.0));
        });
    }
    CONTACT_APP_AD_INLINE void AssignScaled(const Dual& a, double alpha) noexcept {
        double* g = mGradient;
        const double* ga = a.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(g + i, ei::pmul(ei::ploadu<P>(ga + i), ei::pset1<P>(alpha)));
        });
    }
    CONTACT_APP_AD_INLINE void AssignCombined(const Dual& a, double alpha, const Dual& b, double beta) noexcept {
        double* g = mGradient;
        const double *ga = a.mGradient, *gb = b.mGradient;
        detail::ForEachGradientPacket<N>([&](int i, auto p) CONTACT_APP_AD_LAMBDA_INLINE {
            using P = decltype(p);
            namespace ei = Eigen::internal;
            ei::pstoreu(g + i, ei::padd(ei::pmul(ei::ploadu<P>(ga + i), ei::pset1<P>(alpha)),
                                        ei::pmul(ei::ploadu<P>(gb + i), ei::pset1<P>(beta))));
        });
    }

    // Plain members (no Eigen::Matrix) keep Dual trivially default-constructible and trivially copyable:
    // `Dual x;` is as cheap as `double x;` (Eigen matrices of Duals construct their elements this way) and
    // `Dual{}` / `Dual()` value-initialise to exactly zero, both like double.
    double mValue;
    alignas(16) double mGradient[N];
};

static_assert(std::is_trivially_default_constructible<Dual<3>>::value && std::is_trivially_copyable<Dual<3>>::value,
              "Dual must construct and copy like a plain double aggregate");

/// True for Dual<N>, false for double.
template <class T>
struct IsDual : std::false_type {};
template <int N>
struct IsDual<Dual<N>> : std::true_type {};

// -- Value access that works for double and Dual alike --
inline double Value(double x) {
    return x;
}
template <int N>
CONTACT_APP_AD_INLINE double Value(const Dual<N>& x) noexcept {
    return x.Value();
}

// -- Arithmetic (each result's gradient is written once by one SIMD loop: no temporaries) --
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator+(const Dual<N>& a, const Dual<N>& b) noexcept {
    return Dual<N>::Sum(a.Value() + b.Value(), a, b);
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator-(const Dual<N>& a, const Dual<N>& b) noexcept {
    return Dual<N>::Difference(a.Value() - b.Value(), a, b);
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator*(const Dual<N>& a, const Dual<N>& b) noexcept {
    return Dual<N>::Combined(a.Value() * b.Value(), a, b.Value(), b, a.Value());
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator/(const Dual<N>& a, const Dual<N>& b) noexcept {
    const double inv = 1.0 / b.Value();
    const double v = a.Value() * inv;
    return Dual<N>::Quotient(v, a, b, inv);
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator+(const Dual<N>& a, double b) noexcept {
    Dual<N> r(a);
    r += b;
    return r;
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator-(const Dual<N>& a, double b) noexcept {
    Dual<N> r(a);
    r -= b;
    return r;
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator*(const Dual<N>& a, double b) noexcept {
    return Dual<N>::Scaled(a.Value() * b, a, b);
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator/(const Dual<N>& a, double b) noexcept {
    return a * (1.0 / b);
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator+(double a, const Dual<N>& b) noexcept {
    return b + a;
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator-(double a, const Dual<N>& b) noexcept {
    return Dual<N>::Scaled(a - b.Value(), b, -1.0);
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator*(double a, const Dual<N>& b) noexcept {
    return b * a;
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> operator/(double a, const Dual<N>& b) noexcept {
    const double v = a / b.Value();
    return Dual<N>::Scaled(v, b, -v / b.Value());
}

// -- Comparisons (on the value) --
#define CONTACT_APP_DUAL_COMPARISON(OP)                                                   \
    template <int N>                                                                      \
    CONTACT_APP_AD_INLINE bool operator OP(const Dual<N>& a, const Dual<N>& b) noexcept { \
        return a.Value() OP b.Value();                                                    \
    }                                                                                     \
    template <int N>                                                                      \
    CONTACT_APP_AD_INLINE bool operator OP(const Dual<N>& a, double b) noexcept {         \
        return a.Value() OP b;                                                            \
    }                                                                                     \
    template <int N>                                                                      \
    CONTACT_APP_AD_INLINE bool operator OP(double a, const Dual<N>& b) noexcept {         \
        return a OP b.Value();                                                            \
    }
CONTACT_APP_DUAL_COMPARISON(<)
CONTACT_APP_DUAL_COMPARISON(>)
CONTACT_APP_DUAL_COMPARISON(<=)
CONTACT_APP_DUAL_COMPARISON(>=)
CONTACT_APP_DUAL_COMPARISON(==)
CONTACT_APP_DUAL_COMPARISON(!=)
#undef CONTACT_APP_DUAL_COMPARISON

// -- Elementary functions (f(v), f'(v)·∇v) --
template <int N>
CONTACT_APP_AD_INLINE Dual<N> sqrt(const Dual<N>& x) noexcept {
    const double s = std::sqrt(x.Value());
    return Dual<N>::Scaled(s, x, s > 0.0 ? 0.5 / s : 0.0);  // ∇√0 := 0 instead of ∞ (no NaN)
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> abs(const Dual<N>& x) noexcept {
    return x.Value() < 0.0 ? -x : x;
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> fabs(const Dual<N>& x) noexcept {
    return abs(x);
}
template <int N>
Dual<N> pow(const Dual<N>& x, double p) {
    const double v = std::pow(x.Value(), p);
    return Dual<N>::Scaled(v, x, p * std::pow(x.Value(), p - 1.0));
}
template <int N>
Dual<N> sin(const Dual<N>& x) {
    return Dual<N>::Scaled(std::sin(x.Value()), x, std::cos(x.Value()));
}
template <int N>
Dual<N> cos(const Dual<N>& x) {
    return Dual<N>::Scaled(std::cos(x.Value()), x, -std::sin(x.Value()));
}
template <int N>
Dual<N> exp(const Dual<N>& x) {
    const double e = std::exp(x.Value());
    return Dual<N>::Scaled(e, x, e);
}
template <int N>
Dual<N> log(const Dual<N>& x) {
    return Dual<N>::Scaled(std::log(x.Value()), x, 1.0 / x.Value());
}
template <int N>
Dual<N> atan2(const Dual<N>& y, const Dual<N>& x) {
    const double r2 = x.Value() * x.Value() + y.Value() * y.Value();
    const double scale = r2 > 0.0 ? 1.0 / r2 : 0.0;
    return Dual<N>::Combined(std::atan2(y.Value(), x.Value()), y, x.Value() * scale, x, -y.Value() * scale);
}
template <int N>
bool isfinite(const Dual<N>& x) {
    return std::isfinite(x.Value()) && x.Derivatives().allFinite();
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> abs2(const Dual<N>& x) noexcept {
    return x * x;
}
template <int N>
CONTACT_APP_AD_INLINE const Dual<N>& conj(const Dual<N>& x) noexcept {
    return x;
}
template <int N>
CONTACT_APP_AD_INLINE const Dual<N>& real(const Dual<N>& x) noexcept {
    return x;
}
template <int N>
CONTACT_APP_AD_INLINE Dual<N> imag(const Dual<N>&) noexcept {
    return Dual<N>(0.0);
}

}  // namespace contact_app

namespace Eigen {
template <int N>
struct NumTraits<contact_app::Dual<N>> : NumTraits<double> {
    using Real = contact_app::Dual<N>;
    using NonInteger = contact_app::Dual<N>;
    using Nested = contact_app::Dual<N>;
    using Literal = double;
    enum {
        IsComplex = 0,
        IsInteger = 0,
        IsSigned = 1,
        RequireInitialization = 1,
        ReadCost = N + 1,
        AddCost = N + 1,
        MulCost = 2 * N + 1
    };
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
