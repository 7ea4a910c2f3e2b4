// The events of one instant, in order, in storage kept from one instant to the next: an event
// added in a place reuses the vectors (its pellets, its speeds) of the one that held that place
// before, so a run's instants stop allocating once it has met its largest.
#pragma once

#include <cstddef>
#include <span>
#include <utility>
#include <vector>

#include "core/events/event.h"

namespace vibro {

class EventList {
 public:
  // A new event at the end, every field at its default and its vectors empty. A reference
  // stays valid until the next add().
  Event& add() {
    if (size_ == slots_.size()) slots_.emplace_back();
    Event& e = slots_[size_++];
    std::vector<int> pellets = std::move(e.pellets);
    std::vector<double> before = std::move(e.dphi_before), after = std::move(e.dphi_after);
    e = Event{};
    e.pellets = std::move(pellets);
    e.dphi_before = std::move(before);
    e.dphi_after = std::move(after);
    e.pellets.clear();
    e.dphi_before.clear();
    e.dphi_after.clear();
    return e;
  }
  void clear() { size_ = 0; }
  // Keeps the first n events (n <= size()).
  void shrink_to(std::size_t n) { size_ = n; }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  Event& operator[](std::size_t k) { return slots_[k]; }
  const Event& operator[](std::size_t k) const { return slots_[k]; }
  Event* begin() { return slots_.data(); }
  Event* end() { return slots_.data() + size_; }
  const Event* begin() const { return slots_.data(); }
  const Event* end() const { return slots_.data() + size_; }
  std::span<const Event> view() const { return {slots_.data(), size_}; }

 private:
  std::vector<Event> slots_;  // the first size_ hold the events; the rest, storage
  std::size_t size_ = 0;
};

}  // namespace vibro
