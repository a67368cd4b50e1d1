// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <memory>
#include <optional>
#include <vector>

#include "contact_app/kernel/types.h"

namespace contact_app {

/// Entities of one kind kept sorted by id (Kratos PointerVectorSet): a vector of shared
/// pointers, looked up by binary search. Single insertions keep the order; bulk insertion
/// (mesh reading) sorts once. Ids are unique; inserting the same object twice is a no-op.
template <class T>
class EntityContainer {
public:
    using Pointer = std::shared_ptr<T>;
    using iterator = typename std::vector<Pointer>::const_iterator;

    /// Inserts @p entity. Returns false if a different entity with the same id is present.
    bool Insert(Pointer entity) {
        const auto position = LowerBound(entity->Id());
        if (position != mEntities.end() && (*position)->Id() == entity->Id()) return *position == entity;
        mEntities.insert(position, std::move(entity));
        return true;
    }
    /// Inserts many entities at once (one sort). Returns the first clashing id (a different
    /// entity with an id already present or repeated) and leaves the container unchanged then.
    std::optional<IndexType> InsertMany(std::vector<Pointer> incoming) {
        std::stable_sort(incoming.begin(), incoming.end(), [](const Pointer& a, const Pointer& b) { return a->Id() < b->Id(); });
        std::vector<Pointer> merged;
        merged.reserve(mEntities.size() + incoming.size());
        auto a = mEntities.begin();
        auto b = incoming.begin();
        while (a != mEntities.end() || b != incoming.end()) {
            const bool take_a = b == incoming.end() || (a != mEntities.end() && (*a)->Id() <= (*b)->Id());
            Pointer next = take_a ? *a++ : *b++;
            if (!merged.empty() && merged.back()->Id() == next->Id()) {
                if (merged.back() != next) return next->Id();
                continue;
            }
            merged.push_back(std::move(next));
        }
        mEntities = std::move(merged);
        return std::nullopt;
    }
    /// The entity with @p id or nullptr.
    T* Find(IndexType id) const {
        const auto found = LowerBound(id);
        return (found != mEntities.end() && (*found)->Id() == id) ? found->get() : nullptr;
    }
    Pointer FindPointer(IndexType id) const {
        const auto found = LowerBound(id);
        return (found != mEntities.end() && (*found)->Id() == id) ? *found : nullptr;
    }
    bool Contains(IndexType id) const { return Find(id) != nullptr; }
    /// Removes the entity with @p id; returns whether it was present.
    bool Erase(IndexType id) {
        const auto found = LowerBound(id);
        if (found == mEntities.end() || (*found)->Id() != id) return false;
        mEntities.erase(found);
        return true;
    }
    /// Removes every entity for which @p predicate is true; returns how many.
    template <class TPredicate>
    std::size_t EraseIf(TPredicate predicate) {
        const auto old_size = mEntities.size();
        mEntities.erase(std::remove_if(mEntities.begin(), mEntities.end(),
                                       [&](const Pointer& entity) { return predicate(*entity); }),
                        mEntities.end());
        return old_size - mEntities.size();
    }
    void Clear() { mEntities.clear(); }
    std::size_t size() const { return mEntities.size(); }
    bool empty() const { return mEntities.empty(); }
    iterator begin() const { return mEntities.begin(); }
    iterator end() const { return mEntities.end(); }
    /// The i-th entity in id order.
    T& operator[](std::size_t i) const { return *mEntities[i]; }
    const std::vector<Pointer>& Pointers() const { return mEntities; }
    /// Largest id, 0 when empty.
    IndexType MaxId() const { return mEntities.empty() ? 0 : mEntities.back()->Id(); }

private:
    typename std::vector<Pointer>::iterator LowerBound(IndexType id) {
        return std::lower_bound(mEntities.begin(), mEntities.end(), id,
                                [](const Pointer& entity, IndexType value) { return entity->Id() < value; });
    }
    typename std::vector<Pointer>::const_iterator LowerBound(IndexType id) const {
        return std::lower_bound(mEntities.begin(), mEntities.end(), id,
                                [](const Pointer& entity, IndexType value) { return entity->Id() < value; });
    }

    std::vector<Pointer> mEntities;
};

}  // namespace contact_app
