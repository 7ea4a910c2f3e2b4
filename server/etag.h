// Entity tags for cached answers. A tag is a hash of the request's canonical key and the
// server's version, so it is known before any work and stays the same across restarts.
#pragma once

#include <string>
#include <string_view>

namespace vibro::server {

// A strong tag, quoted: "\"3f2a...\"".
std::string etag_of(std::string_view key);

// Whether an If-None-Match header value ("*", or a list of tags, weak or strong) names `etag`.
bool etag_matches(std::string_view if_none_match, std::string_view etag);

}  // namespace vibro::server
