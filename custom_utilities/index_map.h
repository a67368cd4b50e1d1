// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include "contact_app/kernel/types.h"

namespace contact_app {

/// The pairs a skin condition takes part in as slave (Kratos IndexMap, stored in INDEX_MAP): master
/// condition id → id of the computing (paired) condition created for it, 0 while the candidate has no
/// condition yet (a MappingCheck candidate, or a search without condition_name). Ordered by master id so
/// that every loop over the pairs is deterministic.
class IndexMap {
public:
    using Container = std::map<IndexType, IndexType>;
    using const_iterator = Container::const_iterator;

    /// Records master @p master_id as a candidate without condition (no-op if already present).
    void AddId(IndexType master_id) { mPairs.emplace(master_id, 0); }
    /// Forgets master @p master_id (no-op if absent).
    void RemoveId(IndexType master_id) { mPairs.erase(master_id); }
    /// Stores the computing condition id @p condition_id for @p master_id (inserted if absent).
    void SetNewEntityId(IndexType master_id, IndexType condition_id) { mPairs[master_id] = condition_id; }
    /// Whether @p master_id is paired.
    bool Has(IndexType master_id) const { return mPairs.count(master_id) != 0; }
    /// The computing condition id of @p master_id, 0 if there is none (or the master is not paired).
    IndexType GetEntityId(IndexType master_id) const;
    std::size_t size() const { return mPairs.size(); }
    bool empty() const { return mPairs.empty(); }
    void clear() { mPairs.clear(); }
    const_iterator begin() const { return mPairs.begin(); }
    const_iterator end() const { return mPairs.end(); }
    /// "{master: condition, ...}", for messages and debugging.
    std::string Info() const;

private:
    Container mPairs;
};

}  // namespace contact_app
