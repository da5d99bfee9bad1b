// Facts about registers for the forward passes over structured control flow
// (fold, copyprop). A nested block starts from its parent's facts and, at the
// join, the parent forgets every register the block may write. Copying the
// tables for each nested block made a chain of 10,000 `if`s quadratic;
// here every change is logged, so that entering a block costs nothing,
// leaving it undoes only what it did, and the undone log says what it wrote.
// A fact about a register is stamped with the register's version (bumped by
// every write, never reused), so a fact that mentions other registers is
// checked against their versions when it is read and never needs finding
// when they change; forgetting everything (at a call) raises a floor below
// which no version counts.
#pragma once
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ir/flow.h"
#include "ir/ir.h"

namespace glslrun::ir {

// What a nested block did, as its undone log tells it.
struct BlockWrites {
    std::vector<Reg> regs;
    bool forgot_all = false;
};

// One optional fact per register, valid until the register is written again.
template <class Fact>
class RegisterFacts {
public:
    explicit RegisterFacts(size_t regs) : slots_(regs) {}

    uint64_t version(Reg r) const { return r < slots_.size() ? slots_[r].version : 0; }
    // Whether a fact taken when r had version v still holds.
    bool current(Reg r, uint64_t v) const { return version(r) == v && v > floor_; }
    const Fact* find(Reg r) const {
        if (r >= slots_.size() || !slots_[r].fact) return nullptr;
        return slots_[r].version > floor_ ? &*slots_[r].fact : nullptr;
    }

    void write(Reg r, std::optional<Fact> fact = std::nullopt) {
        if (r >= slots_.size()) slots_.resize(size_t(r) + 1);
        log_.push_back({r, slots_[r]});
        slots_[r] = Slot{++next_, std::move(fact)};
    }
    void forget_all() {
        log_.push_back({kNoReg, Slot{floor_, std::nullopt}});
        floor_ = ++next_;
    }
    // Records that a fact taken now depends on r's version (a copy's source,
    // an expression's operand): forgetting r must then change its version.
    void reference(Reg r) {
        if (r < slots_.size()) slots_[r].referenced = true;
    }
    void forget(const flow::Writes& writes) {
        if (writes.calls) return forget_all();
        forget_each(writes.regs);
    }
    // After a join: forgets what the nested blocks wrote.
    void forget(const BlockWrites& writes) {
        if (writes.forgot_all) return forget_all();
        forget_each(writes.regs);
    }

    size_t mark() const { return log_.size(); }
    // Undoes every change since `mark`, adding the registers written to `out`.
    void undo(size_t mark, BlockWrites& out) {
        while (log_.size() > mark) {
            auto& [r, old] = log_.back();
            if (r == kNoReg) {
                floor_ = old.version;
                out.forgot_all = true;
            } else {
                slots_[r] = std::move(old);
                out.regs.push_back(r);
            }
            log_.pop_back();
        }
    }

private:
    struct Slot {
        uint64_t version = 0;
        std::optional<Fact> fact;
        bool referenced = false;  // by a fact taken since `version`
    };

    // Only registers that some fact depends on change version: a loop nested
    // d deep forgets what its body writes at each level, and logging every
    // register again at every level made the log quadratic in d.
    void forget_each(const std::vector<Reg>& regs) {
        uint64_t start = next_;
        for (Reg r : regs) {
            if (r >= slots_.size() || version(r) > start) continue;
            const Slot& slot = slots_[r];
            if (slot.referenced || (slot.fact && slot.version > floor_)) write(r);
        }
    }
    std::vector<Slot> slots_;
    std::vector<std::pair<Reg, Slot>> log_;  // the register (kNoReg: the floor) and its previous state
    uint64_t next_ = 0, floor_ = 0;
};

// A hash map whose changes can be undone back to a mark.
template <class K, class V, class Hash>
class UndoMap {
public:
    const V* find(const K& k) const {
        auto it = map_.find(k);
        return it == map_.end() ? nullptr : &it->second;
    }
    void set(const K& k, V v) {
        auto [it, inserted] = map_.try_emplace(k, v);
        log_.emplace_back(k, inserted ? std::nullopt : std::optional<V>(it->second));
        it->second = std::move(v);
    }
    size_t mark() const { return log_.size(); }
    void undo(size_t mark) {
        while (log_.size() > mark) {
            auto& [k, old] = log_.back();
            if (old) map_[k] = std::move(*old);
            else map_.erase(k);
            log_.pop_back();
        }
    }

private:
    std::unordered_map<K, V, Hash> map_;
    std::vector<std::pair<K, std::optional<V>>> log_;
};

}  // namespace glslrun::ir
