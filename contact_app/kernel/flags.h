// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace contact_app {

/// A set of up to 64 tri-state flags (undefined / true / false), as Kratos Flags.
/// A named flag (ACTIVE, SLIP, ...) is a Flags value with one bit defined and set;
/// `ACTIVE.AsFalse()` has the bit defined and reset. Undefined bits read as false.
class Flags {
public:
    constexpr Flags() = default;

    /// The flag with bit @p position defined and set.
    static constexpr Flags Create(int position) {
        Flags flag;
        flag.mIsDefined = std::uint64_t(1) << position;
        flag.mFlags = flag.mIsDefined;
        return flag;
    }

    /// True if every bit defined in @p flag has the value @p flag gives it.
    constexpr bool Is(const Flags& flag) const {
        return ((mFlags ^ flag.mFlags) & flag.mIsDefined) == 0;
    }
    constexpr bool IsNot(const Flags& flag) const { return !Is(flag); }
    /// True if every bit of @p flag is defined here (set or reset).
    constexpr bool IsDefined(const Flags& flag) const {
        return (mIsDefined & flag.mIsDefined) == flag.mIsDefined;
    }
    constexpr bool IsNotDefined(const Flags& flag) const { return !IsDefined(flag); }

    /// Defines the bits of @p flag and gives them its values (value = true) or their negation.
    void Set(const Flags& flag, bool value = true) {
        const std::uint64_t bits = flag.mIsDefined;
        mIsDefined |= bits;
        const std::uint64_t wanted = value ? flag.mFlags : ~flag.mFlags;
        mFlags = (mFlags & ~bits) | (wanted & bits);
    }
    /// Makes the bits of @p flag undefined again.
    void Reset(const Flags& flag) {
        mIsDefined &= ~flag.mIsDefined;
        mFlags &= ~flag.mIsDefined;
    }
    void Flip(const Flags& flag) {
        mIsDefined |= flag.mIsDefined;
        mFlags ^= flag.mIsDefined;
    }
    void Clear() { mIsDefined = mFlags = 0; }

    /// The same bits, defined and reset (Kratos `flag.AsFalse()`).
    constexpr Flags AsFalse() const {
        Flags result = *this;
        result.mFlags = ~mFlags & mIsDefined;
        return result;
    }
    constexpr Flags operator|(const Flags& other) const {
        Flags result;
        result.mIsDefined = mIsDefined | other.mIsDefined;
        result.mFlags = mFlags | other.mFlags;
        return result;
    }
    constexpr bool operator==(const Flags& other) const {
        return mIsDefined == other.mIsDefined && mFlags == other.mFlags;
    }
    constexpr bool operator!=(const Flags& other) const { return !(*this == other); }

    constexpr std::uint64_t DefinedBits() const { return mIsDefined; }
    constexpr std::uint64_t ValueBits() const { return mFlags; }

private:
    std::uint64_t mIsDefined = 0;
    std::uint64_t mFlags = 0;
};

/// A named flag, for lookups by name (JSON `check_for_flag`, output, Python attributes).
struct NamedFlag {
    const char* name;
    Flags flag;
};

// Bit positions of Kratos' global flags (docs/input_layer.md §6).
#define CONTACT_APP_FLAGS(X)                                                                   \
    X(STRUCTURE, 32) X(FLUID, 33) X(THERMAL, 34) X(MARKER, 35) X(BLOCKED, 36) X(INLET, 37)      \
    X(OUTLET, 38) X(SLAVE, 39) X(MASTER, 40) X(ISOLATED, 41) X(INTERACTION, 42) X(TO_REFINE, 43) \
    X(NEW_ENTITY, 44) X(RIGID, 45) X(MODIFIED, 46) X(ACTIVE, 47) X(OLD_ENTITY, 48) X(SOLID, 49) \
    X(MPI_BOUNDARY, 50) X(TO_ERASE, 51) X(TO_SPLIT, 52) X(CONTACT, 53) X(INTERFACE, 54)        \
    X(SLIP, 55) X(INSIDE, 56) X(FREE_SURFACE, 57) X(BOUNDARY, 58) X(SELECTED, 59) X(VISITED, 60) \
    X(PERIODIC, 61)

#define CONTACT_APP_DECLARE_FLAG(name, bit) inline constexpr Flags name = Flags::Create(bit);
CONTACT_APP_FLAGS(CONTACT_APP_DECLARE_FLAG)
#undef CONTACT_APP_DECLARE_FLAG

/// Every named flag, in bit order.
const std::vector<NamedFlag>& RegisteredFlags();
/// The flag called @p name. @throws InputError for an unknown name (with suggestions).
Flags GetFlag(const std::string& name);

}  // namespace contact_app
