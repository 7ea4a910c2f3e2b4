#include "server/connection.h"

#include <dirent.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <cstdlib>

namespace vibro::server {
namespace {

int port_of(const sockaddr_storage& a) {
  if (a.ss_family == AF_INET) return ntohs(reinterpret_cast<const sockaddr_in&>(a).sin_port);
  if (a.ss_family == AF_INET6) return ntohs(reinterpret_cast<const sockaddr_in6&>(a).sin6_port);
  return -1;
}

}  // namespace

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

}  // namespace vibro::server
