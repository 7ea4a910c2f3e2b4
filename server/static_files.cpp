#include "server/static_files.h"

#include <array>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>
#include <vector>

namespace vibro::server {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxFileBytes = 16 << 20;

// The path's segments, or nothing if any could step outside the root or name a hidden file.
std::optional<std::vector<std::string_view>> safe_segments(std::string_view path) {
  if (!path.starts_with('/')) return std::nullopt;
  if (path.find_first_of(std::string_view("\\\0:", 3)) != std::string_view::npos) {
    return std::nullopt;
  }
  std::vector<std::string_view> segments;
  path.remove_prefix(1);
  while (!path.empty()) {
    const std::size_t slash = path.find('/');
    const std::string_view segment = path.substr(0, slash);
    // Empty ("//"), ".", ".." and hidden names (".git") are all refused by the leading dot.
    if (segment.empty() || segment.front() == '.') return std::nullopt;
    segments.push_back(segment);
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
  }
  return segments;
}

}  // namespace

std::string_view static_content_type(std::string_view file_name) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 11> types = {{
      {".html", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".svg", "image/svg+xml"},
      {".png", "image/png"},
      {".ico", "image/x-icon"},
      {".json", "application/json"},
      {".txt", "text/plain; charset=utf-8"},
      {".woff2", "font/woff2"},
      {".webmanifest", "application/manifest+json"},
  }};
  for (const auto& [ext, type] : types) {
    if (file_name.ends_with(ext)) return type;
  }
  return {};
}

StaticFiles::StaticFiles(fs::path root) {
  std::error_code ec;
  const fs::path canonical = fs::canonical(root, ec);
  root_ = ec ? std::move(root) : canonical;
}

std::optional<StaticFile> StaticFiles::find(std::string_view url_path) const {
  const auto segments = safe_segments(url_path);
  if (!segments) return std::nullopt;
  fs::path file = root_;
  std::error_code ec;
  for (std::string_view s : *segments) {
    file /= s;
    // A symlink could point anywhere: web/ holds none, and any found is treated as absent.
    const fs::file_type type = fs::symlink_status(file, ec).type();
    if (type != fs::file_type::regular && type != fs::file_type::directory) return std::nullopt;
  }
  if (url_path.ends_with('/')) file /= "index.html";
  if (fs::symlink_status(file, ec).type() != fs::file_type::regular) return std::nullopt;
  const std::string_view type = static_content_type(file.filename().native());
  if (type.empty() || fs::file_size(file, ec) > kMaxFileBytes || ec) return std::nullopt;
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  return StaticFile{std::string(std::istreambuf_iterator<char>(in), {}), std::string(type)};
}

}  // namespace vibro::server
