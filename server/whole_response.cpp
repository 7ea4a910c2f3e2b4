#include "server/whole_response.h"

#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

namespace vibro::server {
namespace {

thread_local int held = -1;

}  // namespace

void hold_if_whole(const Connection& connection, std::size_t bytes) {
  held = -1;
  const int fd = socket_of(connection);
  int segment = 0;
  socklen_t size = sizeof segment;
  if (fd < 0 || ::getsockopt(fd, IPPROTO_TCP, TCP_MAXSEG, &segment, &size) != 0 || segment <= 0 ||
      bytes > static_cast<std::size_t>(segment))
    return;
  const int on = 1;
  const linger reset{1, 0};
  if (::setsockopt(fd, IPPROTO_TCP, TCP_CORK, &on, sizeof on) != 0 ||
      ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset) != 0)
    return;
  held = fd;
}

void release_held() {
  if (held < 0) return;
  // The linger first: a process that dies between the two calls closes normally and flushes
  // the whole response; the other order could reset a response already sent.
  const linger normal{0, 0};
  const int off = 0;
  ::setsockopt(held, SOL_SOCKET, SO_LINGER, &normal, sizeof normal);
  ::setsockopt(held, IPPROTO_TCP, TCP_CORK, &off, sizeof off);
  held = -1;
}

}  // namespace vibro::server
