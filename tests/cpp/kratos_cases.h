// SPDX-License-Identifier: BSD-3-Clause
/// The skip of a test that reads the Kratos reference cases, CONTACT_APP_KRATOS_CASES (set by CMake to
/// ../shared/kratos_cases next to the source tree): a clone without that folder skips them, as the Python tests do.
#pragma once

#include <filesystem>

#include <gtest/gtest.h>

/// Skips the calling test when the folder of the Kratos reference cases is missing. Use it in the TEST body
/// itself: GTEST_SKIP() returns from the function it is written in.
#define CONTACT_SKIP_WITHOUT_KRATOS_CASES()                                                        \
    if (!std::filesystem::is_directory(CONTACT_APP_KRATOS_CASES))                                  \
    GTEST_SKIP() << "the Kratos reference cases are missing: no folder " CONTACT_APP_KRATOS_CASES  \
                    " (../shared/kratos_cases next to the source tree)"
