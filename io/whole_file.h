// Files read and written whole, for the command line: a file is read in full or refused with a
// reason a person can act on (it does not exist, it is a directory, it cannot be read), and
// written whole or not at all: the bytes go to a temporary file beside the target, which is
// flushed, synced to the disk and renamed over the target only when every step succeeded; on
// any failure (a full disk, a file size limit, a directory in the way) the target is left as it
// was and the temporary file is removed.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace vibro {

// Why a file could not be read or written: a sentence naming the file, such as
// "out.csv cannot be written: No space left on device".
struct FileProblem {
  std::string message;
  int error = 0;  // the errno: ENOENT when the file does not exist
};

std::variant<std::string, FileProblem> read_whole_file(const std::string& path);

// Replaces `path` by `bytes` (atomically, as above). A target that is a symbolic link has the
// file it points to replaced; an existing target keeps its permissions, a new one gets the
// umask's.
std::optional<FileProblem> write_whole_file(const std::string& path, std::string_view bytes);

// A file written whole in pieces, as write_whole_file writes it: the pieces go to a temporary
// file beside the target, which commit() syncs and renames over it; a writer dropped without a
// commit (or after a failure) removes its temporary file and leaves the target as it was.
class WholeFileWriter {
 public:
  explicit WholeFileWriter(const std::string& path);
  ~WholeFileWriter();
  WholeFileWriter(const WholeFileWriter&) = delete;
  WholeFileWriter& operator=(const WholeFileWriter&) = delete;
  // Whether every piece so far was written; after a failure nothing more is.
  bool append(std::string_view bytes);
  // Puts the file in place, or says why it could not be written.
  std::optional<FileProblem> commit();

 private:
  std::string path_, target_, temporary_;
  int fd_ = -1;
  int error_ = 0;
};

// Writes all of `bytes` to the open descriptor `fd`, through short writes and interruptions;
// the errno of the failure, or 0.
int write_all(int fd, std::string_view bytes);

}  // namespace vibro
