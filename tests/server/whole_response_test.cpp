// A small response leaves whole or not at all (server/whole_response.h), tested on a loopback
// connection of this process: the "replica" end is held, written to, and then either released
// or closed as a killed process's sockets are.
#include "server/whole_response.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <string>

namespace vibro::server {
namespace {

// Both ends of a loopback TCP connection, and the replica end's name as cpp-httplib gives it.
struct Pair {
  int client = -1, replica = -1;
  Connection connection;
  Pair() {
    const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof a;
    ::bind(listener, reinterpret_cast<sockaddr*>(&a), sizeof a);
    ::listen(listener, 1);
    ::getsockname(listener, reinterpret_cast<sockaddr*>(&a), &size);
    client = ::socket(AF_INET, SOCK_STREAM, 0);
    ::connect(client, reinterpret_cast<sockaddr*>(&a), sizeof a);
    replica = ::accept(listener, nullptr, nullptr);
    ::close(listener);
    sockaddr_in peer{};
    size = sizeof peer;
    ::getsockname(client, reinterpret_cast<sockaddr*>(&peer), &size);
    connection = {"127.0.0.1", ntohs(peer.sin_port), ntohs(a.sin_port)};
  }
  ~Pair() {
    ::close(client);
    if (replica >= 0) ::close(replica);
  }
  void write(const std::string& s) const {
    ASSERT_EQ(::send(replica, s.data(), s.size(), 0), static_cast<ssize_t>(s.size()));
  }
  bool client_has_data() const {
    pollfd p{client, POLLIN, 0};
    return ::poll(&p, 1, 0) == 1;
  }
  // What the client reads until the end or an error, and the error.
  std::pair<std::string, int> read_all() const {
    std::string got;
    char buffer[4096];
    for (;;) {
      const ssize_t n = ::recv(client, buffer, sizeof buffer, 0);
      if (n > 0)
        got.append(buffer, static_cast<std::size_t>(n));
      else
        return {got, n == 0 ? 0 : errno};
    }
  }
};

const std::string kHeader = "HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\n";

TEST(WholeResponse, AHeldReplicaThatDiesSendsNothingAndResets) {
  Pair p;
  hold_if_whole(p.connection, 200);
  p.write(kHeader);  // killed before its body
  EXPECT_FALSE(p.client_has_data());
  ::close(p.replica);  // what the kernel does for a killed process
  p.replica = -1;
  const auto [got, error] = p.read_all();
  EXPECT_EQ(got, "");
  EXPECT_EQ(error, ECONNRESET);  // the proxy sees an error before any header, and retries
  release_held();
}

TEST(WholeResponse, AReleasedResponseLeavesWholeAndTheConnectionClosesNormally) {
  Pair p;
  hold_if_whole(p.connection, 200);
  p.write(kHeader);
  p.write("hello");
  release_held();
  ::close(p.replica);
  p.replica = -1;
  const auto [got, error] = p.read_all();
  EXPECT_EQ(got, kHeader + "hello");
  EXPECT_EQ(error, 0);
}

TEST(WholeResponse, AResponseLargerThanASegmentIsNotHeld) {
  Pair p;
  hold_if_whole(p.connection, 1 << 20);
  p.write(kHeader);
  ::close(p.replica);
  p.replica = -1;
  const auto [got, error] = p.read_all();
  EXPECT_EQ(got, kHeader);  // leaves as before: the header, then the end
  EXPECT_EQ(error, 0);
  release_held();
}

TEST(WholeResponse, AnUnknownConnectionIsLeftAlone) {
  Pair p;
  Connection other = p.connection;
  other.remote_port = p.connection.remote_port == 1 ? 2 : 1;
  hold_if_whole(other, 200);
  p.write(kHeader);
  ::close(p.replica);
  p.replica = -1;
  EXPECT_EQ(p.read_all().first, kHeader);
  release_held();
}

}  // namespace
}  // namespace vibro::server
