// The connection a request came on, and its socket. cpp-httplib hands neither its socket nor a
// connection id to a handler, only the two ends' addresses; the socket is found from them.
#pragma once

#include <string>

namespace vibro::server {

struct Connection {
  std::string remote_addr;
  int remote_port = -1;
  int local_port = -1;
};

// Whether socket `fd` is `c`, its addresses read as cpp-httplib reads them.
bool is_connection(int fd, const Connection& c);

// The socket of `c`, or -1: the one found last on this thread (a keep-alive connection's
// requests come on the same thread), else a look through the process's open descriptors.
int socket_of(const Connection& c);

}  // namespace vibro::server
