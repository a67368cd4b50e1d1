// SPDX-License-Identifier: BSD-3-Clause
#include "custom_processes/master_slave_process.h"

#include "contact_app/kernel/model_part.h"

namespace contact_app {

void MasterSlaveProcess::Execute() {
    for (const auto& condition : mrModelPart.Conditions()) {
        Geometry& geometry = condition->GetGeometry();
        if (geometry.NumberOfGeometryParts() != 0) continue;
        bool is_slave = true;
        for (std::size_t i = 0; i < geometry.size(); ++i) is_slave = is_slave && geometry[i].Is(SLAVE);
        condition->Set(SLAVE, is_slave);
        condition->Set(MASTER, !is_slave);
        if (is_slave) continue;
        // The master side is whatever is not slave: flag its nodes too (a node shared with a slave face stays slave).
        for (std::size_t i = 0; i < geometry.size(); ++i) {
            if (geometry[i].Is(SLAVE)) continue;
            geometry[i].Set(MASTER, true);
            geometry[i].Set(SLAVE, false);
        }
    }
}

}  // namespace contact_app
