// SPDX-License-Identifier: BSD-3-Clause
/// Helpers of the tests that check an error: its type and the fragments its message must hold (what failed, where,
/// the fix), not the whole text, which may gain detail.
#pragma once

#include <initializer_list>
#include <string>

#include <gtest/gtest.h>

#include "contact_app/kernel/exceptions.h"
#include "contact_app/kernel/process_info.h"

namespace contact_app::testing {

/// Runs @p action and expects a @p TError whose message contains every fragment.
template <class TError, class TAction>
void ExpectError(TAction&& action, std::initializer_list<std::string> fragments) {
    try {
        action();
        ADD_FAILURE() << "expected an exception";
    } catch (const TError& error) {
        const std::string message = error.what();
        for (const std::string& fragment : fragments)
            EXPECT_NE(message.find(fragment), std::string::npos) << "missing \"" << fragment << "\" in: " << message;
    }
}

/// The InputError message of @p entity's Check() with an empty ProcessInfo ("" when it passes).
template <class TEntity>
std::string CheckMessage(const TEntity& entity) {
    try {
        entity.Check(ProcessInfo());
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

}  // namespace contact_app::testing
