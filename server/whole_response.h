// A small response leaves a replica whole or not at all. cpp-httplib writes a response's
// headers and its body in two writes; a replica killed between them (SIGKILL under load, the
// front door's test) sent nginx a header it could not retry, and the client read 0 of 5300
// bytes. While a response that fits in one TCP segment is written, its socket is corked (the
// kernel holds partial segments) and resets on close (a process that dies drops what it held,
// and the proxy, having read nothing, retries the request on another replica). Once the body is
// written the socket closes normally again and is uncorked: the response leaves in one segment.
// A larger response leaves as before: its first full segment cannot be held back.
#pragma once

#include <cstddef>

#include "server/connection.h"

namespace vibro::server {

// Before a response of about `bytes` (headers and body) is written on the connection.
void hold_if_whole(const Connection& connection, std::size_t bytes);
// After its body is written, on the same thread.
void release_held();

}  // namespace vibro::server
