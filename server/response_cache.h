// Finished answers (run results, images) by their canonical request key, in a bounded
// least-recently-used cache measured in bytes. The simulator is deterministic, so one key has
// one answer, and a cache hit gives the same bytes as the first run.
#pragma once

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace vibro::server {

struct CachedResponse {
  std::string body;
  std::string content_type;
  std::string etag;
  std::vector<std::pair<std::string, std::string>> headers;  // the answer's own, e.g. its axes
};

class ResponseCache {
 public:
  // capacity_bytes counts bodies and keys; 0 turns the cache off. An answer larger than a
  // quarter of the capacity is not kept, so one large image cannot flush everything else.
  explicit ResponseCache(std::size_t capacity_bytes);

  std::shared_ptr<const CachedResponse> find(std::string_view key);
  void insert(std::string key, std::shared_ptr<const CachedResponse> value);

  std::size_t size_bytes() const;

 private:
  using Entry = std::pair<std::string, std::shared_ptr<const CachedResponse>>;
  static std::size_t cost(const Entry& e) { return e.first.size() + e.second->body.size(); }

  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::list<Entry> entries_;  // most recently used first
  std::unordered_map<std::string_view, std::list<Entry>::iterator> index_;  // keys in entries_
  std::size_t bytes_ = 0;
};

}  // namespace vibro::server
