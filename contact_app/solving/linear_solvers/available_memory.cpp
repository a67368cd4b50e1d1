// SPDX-License-Identifier: BSD-3-Clause
#include "contact_app/solving/linear_solvers/available_memory.h"

#include <fstream>
#include <string>

namespace contact_app {

double AvailableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string key, unit;
    double kilobytes = 0.0;
    while (meminfo >> key >> kilobytes >> unit)
        if (key == "MemAvailable:") return 1024.0 * kilobytes;
    return -1.0;
}

}  // namespace contact_app
