#include "io/whole_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace vibro {
namespace {

namespace fs = std::filesystem;

FileProblem problem(const std::string& path, const char* what, int error) {
  return {path + " " + what + ": " + std::strerror(error), error};
}

// The file a write replaces: the target of a symbolic link, so that the link stays.
std::string file_replaced(const std::string& path) {
  std::error_code ec;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    const fs::path target = fs::canonical(path, ec);
    if (!ec) return target.string();
  }
  return path;
}

// A name beside `path` that no other writer uses: hidden, with the process id and a counter.
std::string temporary_beside(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path p(path);
  std::string name = ".";
  name += p.filename().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return (p.parent_path() / name).string();
}

// Makes the rename itself durable; a directory that cannot be synced is not an error, its file
// is already in place.
void sync_directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  const int fd = ::open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

int write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

std::variant<std::string, FileProblem> read_whole_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) return FileProblem{path + " does not exist", ENOENT};
    return problem(path, "cannot be opened", errno);
  }
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISDIR(st.st_mode)) {
    ::close(fd);
    return FileProblem{path + " is a directory, not a file", EISDIR};
  }
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int error = errno;
      ::close(fd);
      return problem(path, "cannot be read", error);
    }
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return bytes;
}

WholeFileWriter::WholeFileWriter(const std::string& path)
    : path_(path), target_(file_replaced(path)), temporary_(temporary_beside(target_)) {
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) {
    error_ = errno;
    return;
  }
  struct stat st {};
  if (::stat(target_.c_str(), &st) == 0 && S_ISREG(st.st_mode)) ::fchmod(fd_, st.st_mode & 07777);
}

WholeFileWriter::~WholeFileWriter() {
  if (fd_ < 0) return;
  ::close(fd_);
  ::unlink(temporary_.c_str());
}

bool WholeFileWriter::append(std::string_view bytes) {
  if (error_ == 0) error_ = write_all(fd_, bytes);
  return error_ == 0;
}

std::optional<FileProblem> WholeFileWriter::commit() {
  if (fd_ < 0) return problem(path_, "cannot be written", error_);
  int error = error_;
  if (error == 0 && ::fsync(fd_) != 0) error = errno;
  if (::close(fd_) != 0 && error == 0) error = errno;
  fd_ = -1;
  if (error == 0 && ::rename(temporary_.c_str(), target_.c_str()) != 0) error = errno;
  if (error != 0) {
    ::unlink(temporary_.c_str());
    error_ = error;
    return problem(path_, "cannot be written", error);
  }
  sync_directory_of(target_);
  return std::nullopt;
}

std::optional<FileProblem> write_whole_file(const std::string& path, std::string_view bytes) {
  WholeFileWriter file(path);
  file.append(bytes);
  return file.commit();
}

}  // namespace vibro
