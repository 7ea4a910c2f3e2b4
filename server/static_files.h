// The web page's files (web/): only regular files of known types under the root, never through
// a symlink, "..", a hidden name or a directory listing. "/" and "dir/" mean their index.html.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vibro::server {

struct StaticFile {
  std::string body;
  std::string content_type;
};

class StaticFiles {
 public:
  // The root need not exist yet (the page may be written later); until it does, nothing is found.
  explicit StaticFiles(std::filesystem::path root);

  // `url_path` as the HTTP layer gives it: percent-decoded, starting with "/".
  std::optional<StaticFile> find(std::string_view url_path) const;

  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

// The media type for a file name by its extension, or empty for a type the server does not serve.
std::string_view static_content_type(std::string_view file_name);

}  // namespace vibro::server
