#include "server/response_cache.h"

namespace vibro::server {

ResponseCache::ResponseCache(std::size_t capacity_bytes) : capacity_(capacity_bytes) {}

std::shared_ptr<const CachedResponse> ResponseCache::find(std::string_view key) {
  std::lock_guard lock(mutex_);
  const auto it = index_.find(key);
  if (it == index_.end()) return nullptr;
  entries_.splice(entries_.begin(), entries_, it->second);
  return it->second->second;
}

void ResponseCache::insert(std::string key, std::shared_ptr<const CachedResponse> value) {
  Entry entry(std::move(key), std::move(value));
  if (cost(entry) > capacity_ / 4) return;
  std::lock_guard lock(mutex_);
  if (index_.count(entry.first)) return;  // two requests raced to compute the same answer
  bytes_ += cost(entry);
  entries_.push_front(std::move(entry));
  index_.emplace(entries_.front().first, entries_.begin());
  while (bytes_ > capacity_) {
    const Entry& oldest = entries_.back();
    bytes_ -= cost(oldest);
    index_.erase(oldest.first);
    entries_.pop_back();
  }
}

std::size_t ResponseCache::size_bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

}  // namespace vibro::server
