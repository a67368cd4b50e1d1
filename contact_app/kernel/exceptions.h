// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace contact_app {

/// Bad user input: JSON, mesh files, properties, names. Mapped to Python `InputError(ValueError)`.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Options that cannot be combined. Mapped to Python `ConfigurationError`.
class ConfigurationError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A non-linear or linear solve that did not converge. Mapped to Python `ConvergenceError`.
class ConvergenceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A broken internal invariant: a bug in contact_app, not in the user's input.
class InternalError : public std::runtime_error {
public:
    explicit InternalError(const std::string& what)
        : std::runtime_error(what + "\n  this is a bug in contact_app; please report it with the input that triggered it") {}
};

namespace detail {
/// Streams every argument into one string (the message builder of CONTACT_CHECK / CONTACT_THROW).
template <class... TArgs>
std::string Concat(const TArgs&... args) {
    std::ostringstream stream;
    (stream << ... << args);
    return stream.str();
}
}  // namespace detail

}  // namespace contact_app

/// Always-on check of anything a user, a mesh or a JSON file can cause.
#define CONTACT_CHECK(condition, ErrorType, ...)                                     \
    do {                                                                             \
        if (!(condition)) throw ErrorType(::contact_app::detail::Concat(__VA_ARGS__)); \
    } while (false)

/// Unconditional throw with a streamed message.
#define CONTACT_THROW(ErrorType, ...) throw ErrorType(::contact_app::detail::Concat(__VA_ARGS__))

/// Internal invariant, compiled out in release builds (NDEBUG).
#ifdef NDEBUG
#define CONTACT_ASSERT(condition, ...) ((void)0)
#else
#define CONTACT_ASSERT(condition, ...)                                                       \
    do {                                                                                     \
        if (!(condition))                                                                    \
            throw ::contact_app::InternalError(::contact_app::detail::Concat(               \
                "assertion `" #condition "` failed at " __FILE__ ":", __LINE__, ": ", __VA_ARGS__)); \
    } while (false)
#endif
