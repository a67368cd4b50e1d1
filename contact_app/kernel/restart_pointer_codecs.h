// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "contact_app/kernel/data_value_container.h"

namespace contact_app {

/// How a checkpoint stores the value of one pointer variable (INDEX_MAP, CONSTITUTIVE_LAW, ...):
/// the layer that declares the pointee registers it, so the checkpoint code (contact_app/io) needs
/// no contact header. `save` turns the pointee into bytes; `load` decodes them and stores the
/// result in the container under the variable, typed (a bad buffer is an InputError).
struct RestartPointerCodec {
    std::function<std::string(const std::shared_ptr<void>& value)> save;
    std::function<void(DataValueContainer& container, const std::string& bytes)> load;
};

/// @brief Registers the codec of the pointer variable @p variable_name (a later call replaces it).
void RegisterRestartPointerCodec(const std::string& variable_name, RestartPointerCodec codec);
/// @brief The codec of @p variable_name, or nullptr when none is registered.
const RestartPointerCodec* FindRestartPointerCodec(const std::string& variable_name);

}  // namespace contact_app
