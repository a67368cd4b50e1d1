// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/kernel/element.h"

namespace contact_app {

std::string Element::WhyStiffnessVaries() const {
    return "is a " + Info() + ", which does not declare a constant stiffness";
}

}  // namespace contact_app
