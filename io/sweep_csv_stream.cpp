#include "io/sweep_csv_stream.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>

#include "io/sweep_json.h"

namespace vibro {
namespace {

constexpr std::size_t kPiece = 1 << 16;

}  // namespace

SweepCsvStream::SweepCsvStream(const std::string& path, const Model& model, const SweepSpec& spec)
    : path_(path),
      classify_(spec.classify_attractor),
      out_(std::make_unique<WholeFileWriter>(path)) {
  out_->append(sweep_csv_header(spec));
  if (!classify_) return;
  table_.emplace(model);
  rows_path_ = path + ".rows-" + std::to_string(::getpid());
  rows_fd_ = ::open(rows_path_.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (rows_fd_ < 0) rows_error_ = errno;
}

SweepCsvStream::~SweepCsvStream() {
  if (rows_fd_ >= 0) {
    ::close(rows_fd_);
    ::unlink(rows_path_.c_str());
  }
}

// Writes the runs' lines: to the file, or with their provisional classes to the rows file.
void SweepCsvStream::release(std::vector<SweepRun>& runs) {
  order_sweep_runs(runs);
  for (const SweepRun& run : runs) {
    buffer_ += sweep_run_csv(run, table_ ? std::optional<int>(table_->add(run)) : std::nullopt);
    if (buffer_.size() < kPiece) continue;
    ok_ = table_ ? (rows_error_ == 0 && (rows_error_ = write_all(rows_fd_, buffer_)) == 0)
                 : out_->append(buffer_);
    buffer_.clear();
  }
}

bool SweepCsvStream::add(int chain, std::vector<SweepRun> runs) {
  const std::lock_guard lock(mutex_);
  if (!ok_) return false;
  if (chain != next_) {
    waiting_.emplace(chain, std::move(runs));
    return true;
  }
  release(runs);
  ++next_;
  for (auto it = waiting_.begin(); it != waiting_.end() && it->first == next_;
       it = waiting_.erase(it), ++next_)
    release(it->second);
  return ok_;
}

// Copies the rows file into the output, each line's last field (its provisional class) replaced
// by the attractor's id.
std::optional<FileProblem> SweepCsvStream::renumber_into_place() {
  std::vector<int> id_of;
  table_->finish(id_of);
  if (rows_error_ != 0 || ::lseek(rows_fd_, 0, SEEK_SET) != 0)
    return FileProblem{
        rows_path_ + " cannot be written: " + std::strerror(rows_error_ ? rows_error_ : errno),
        rows_error_};
  std::string carry, out;
  char piece[kPiece];
  for (;;) {
    const ssize_t n = ::read(rows_fd_, piece, sizeof piece);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return FileProblem{rows_path_ + " cannot be read: " + std::strerror(errno), errno};
    if (n == 0) break;
    carry.append(piece, static_cast<std::size_t>(n));
    std::size_t start = 0;
    for (std::size_t end; (end = carry.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::size_t comma = carry.rfind(',', end);
      int k = -1;
      std::from_chars(carry.data() + comma + 1, carry.data() + end, k);
      out.append(carry, start, comma + 1 - start);
      out += std::to_string(k < 0 ? -1 : id_of[k]);
      out += '\n';
    }
    carry.erase(0, start);
    if (!out_->append(out)) break;
    out.clear();
  }
  return out_->commit();
}

std::optional<FileProblem> SweepCsvStream::finish(std::vector<Attractor>* attractors) {
  const std::lock_guard lock(mutex_);
  if (!waiting_.empty())  // a chain before them never came: the file would miss its rows
    return FileProblem{
        path_ + " cannot be written: chain " + std::to_string(next_) + " of the sweep is missing",
        0};
  if (table_) {
    if (rows_error_ == 0 && !buffer_.empty()) rows_error_ = write_all(rows_fd_, buffer_);
    buffer_.clear();
    if (attractors) {
      std::vector<int> unused;
      *attractors = table_->finish(unused);
    }
    return renumber_into_place();
  }
  out_->append(buffer_);
  buffer_.clear();
  return out_->commit();
}

}  // namespace vibro
