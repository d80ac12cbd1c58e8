#pragma once
// Generation-checked handles. A handle is (slot index, generation); freeing a slot
// bumps its generation, so every later use of an old handle is detected and
// reported as a GpuError instead of touching whatever reuses the slot.
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include <sherpa/gpu/gpu_error.h>

namespace sherpa::gpu {

template <typename Tag> struct Handle {
    std::uint32_t index = 0;
    std::uint32_t generation = 0; // 0 never names a live object
    bool valid() const { return generation != 0; }
    bool operator==(const Handle&) const = default;
};

template <typename T, typename Tag> class HandlePool {
public:
    explicit HandlePool(const char* kind) : kind_(kind) {}

    Handle<Tag> insert(T&& value) {
        std::uint32_t index;
        if (!free_.empty()) {
            index = free_.back();
            free_.pop_back();
        } else {
            index = static_cast<std::uint32_t>(slots_.size());
            slots_.push_back(Slot{});
        }
        slots_[index].value.emplace(std::move(value));
        ++live_;
        return Handle<Tag>{index, slots_[index].generation};
    }

    T& get(Handle<Tag> h) { return *slot(h).value; }
    const T& get(Handle<Tag> h) const { return *const_cast<HandlePool*>(this)->slot(h).value; }
    bool alive(Handle<Tag> h) const {
        return h.valid() && h.index < slots_.size() && slots_[h.index].generation == h.generation &&
               slots_[h.index].value.has_value();
    }

    // Removes the object and invalidates every copy of `h`.
    T take(Handle<Tag> h) {
        Slot& s = slot(h);
        T value = std::move(*s.value);
        s.value.reset();
        if (++s.generation == 0) s.generation = 1; // skip 0: reserved for "no handle"
        free_.push_back(h.index);
        --live_;
        return value;
    }

    std::size_t live() const { return live_; }
    std::uint64_t stale_uses() const { return stale_uses_; }

private:
    struct Slot {
        std::optional<T> value;
        std::uint32_t generation = 1;
    };

    Slot& slot(Handle<Tag> h) {
        if (!alive(h)) {
            ++stale_uses_;
            throw GpuError(
                std::string("stale or invalid ") + kind_ + " handle (slot " +
                std::to_string(h.index) + ", generation " + std::to_string(h.generation) +
                (h.index < slots_.size()
                     ? ", slot is at generation " + std::to_string(slots_[h.index].generation)
                     : std::string(", no such slot")) +
                ")");
        }
        return slots_[h.index];
    }

    const char* kind_;
    std::deque<Slot> slots_; // deque: references from get() survive later inserts
    std::vector<std::uint32_t> free_;
    std::size_t live_ = 0;
    std::uint64_t stale_uses_ = 0;
};

} // namespace sherpa::gpu
