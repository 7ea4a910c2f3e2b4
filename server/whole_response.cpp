#include "server/whole_response.h"

#include <dirent.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <cstdlib>

namespace vibro::server {
namespace {

int port_of(const sockaddr_storage& a) {
  if (a.ss_family == AF_INET) return ntohs(reinterpret_cast<const sockaddr_in&>(a).sin_port);
  if (a.ss_family == AF_INET6) return ntohs(reinterpret_cast<const sockaddr_in6&>(a).sin6_port);
  return -1;
}

// Whether socket `fd` is `c`, its addresses read as cpp-httplib reads them.
bool is_connection(int fd, const Connection& c) {
  sockaddr_storage peer{}, local{};
  socklen_t peer_size = sizeof peer, local_size = sizeof local;
  if (::getpeername(fd, reinterpret_cast<sockaddr*>(&peer), &peer_size) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&local), &local_size) != 0)
    return false;
  if (port_of(peer) != c.remote_port || port_of(local) != c.local_port) return false;
  char host[NI_MAXHOST];
  return ::getnameinfo(reinterpret_cast<sockaddr*>(&peer), peer_size, host, sizeof host, nullptr, 0,
                       NI_NUMERICHOST) == 0 &&
         c.remote_addr == host;
}

// The socket of `c`, or -1: the one found last on this thread (a keep-alive connection's
// requests come on the same thread), else a look through the open descriptors.
int socket_of(const Connection& c) {
  thread_local int last = -1;
  if (last >= 0 && is_connection(last, c)) return last;
  last = -1;
  DIR* fds = ::opendir("/proc/self/fd");
  if (!fds) return -1;
  while (const dirent* e = ::readdir(fds)) {
    const int fd = std::atoi(e->d_name);
    if (e->d_name[0] != '.' && fd != ::dirfd(fds) && is_connection(fd, c)) {
      last = fd;
      break;
    }
  }
  ::closedir(fds);
  return last;
}

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
