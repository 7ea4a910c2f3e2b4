#include "server/router.h"

#include <cctype>
#include <charconv>
#include <optional>
#include <string>

#include "server/api_error.h"

namespace vibro::server {
namespace {

using Result = httplib::Server::HandlerResponse;

bool matches(const Route& route, const std::string& path) {
  if (route.path.ends_with('/')) return path.starts_with(route.path);
  return path == route.path;
}

bool under_api(const std::string& path) { return path == "/api" || path.starts_with("/api/"); }

// The media type without parameters ("application/json; charset=utf-8" → "application/json").
std::string media_type(const std::string& content_type) {
  std::string type = content_type.substr(0, content_type.find(';'));
  while (!type.empty() && type.back() == ' ') type.pop_back();
  for (char& c : type) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return type;
}

// The query as sent: each parameter split at its first '=' (cpp-httplib 0.11 keeps what follows
// the last one: "method=a=b" read as "b"), and a parameter given twice refused, naming it: which
// value the client meant would be a guess, as for a JSON key given twice.
std::optional<ApiError> read_query(const std::string& target, httplib::Params& params) {
  const std::size_t q = target.find('?');
  if (q == std::string::npos) return std::nullopt;
  const std::string query = target.substr(q + 1);
  for (std::size_t at = 0; at <= query.size();) {
    std::size_t end = query.find('&', at);
    if (end == std::string::npos) end = query.size();
    const std::string piece = query.substr(at, end - at);
    at = end + 1;
    if (piece.empty()) continue;
    const std::size_t eq = piece.find('=');
    const std::string key = httplib::detail::decode_url(piece.substr(0, eq), true);
    const std::string value =
        eq == std::string::npos ? "" : httplib::detail::decode_url(piece.substr(eq + 1), true);
    if (params.count(key)) return ApiError{400, key, "is given twice"};
    params.emplace(key, value);
  }
  return std::nullopt;
}

}  // namespace

Result Router::route(const httplib::Request& req, httplib::Response& res) const {
  // Two Content-Length headers: which one frames the body is the parser's guess, and a proxy in
  // front may guess the other (request smuggling). Refused before the body is read.
  if (req.get_header_value_count("Content-Length") > 1) {
    send_error(res, {400, "Content-Length", "is given more than once"}, true);
    return Result::Handled;
  }
  // A refusal sent before the body is read must also end the connection: the unread body
  // would otherwise be taken for the next request.
  const std::string length_text = req.get_header_value("Content-Length");
  const bool has_body =
      req.has_header("Transfer-Encoding") || (!length_text.empty() && length_text != "0");
  const std::string method = req.method == "HEAD" ? "GET" : req.method;
  httplib::Params params;
  if (auto error = read_query(req.target, params)) {
    send_error(res, *error, has_body);
    return Result::Handled;
  }
  // The request is cpp-httplib's own non-const object, handed to this handler as const.
  const_cast<httplib::Request&>(req).params = std::move(params);

  const Route* found = nullptr;
  std::string allowed;
  const auto consider = [&](const Route& r) {
    if (r.method == method)
      found = &r;
    else if (allowed.find(r.method) == std::string::npos)
      allowed += (allowed.empty() ? "" : ", ") + r.method;
  };
  for (const Route& r : routes_) {
    if (!found && matches(r, req.path)) consider(r);
  }
  if (!found && allowed.empty() && !under_api(req.path)) consider(pages_);
  if (!found && allowed.empty()) {
    send_error(res, {404, "path", "no such endpoint: " + req.path}, has_body);
    return Result::Handled;
  }
  if (!found) {
    res.set_header("Allow", allowed);
    send_error(res, {405, "method", req.method + " is not allowed here; use " + allowed}, has_body);
    return Result::Handled;
  }
  if (method != "POST") {
    if (has_body) {
      send_error(res, {400, "body", "a " + req.method + " request takes no body"}, true);
    } else {
      found->handler(req, res);
    }
    return Result::Handled;
  }

  if (req.has_header("Transfer-Encoding") || !req.has_header("Content-Length")) {
    send_error(res, {411, "body", "send the scene with a Content-Length, not chunked"}, true);
    return Result::Handled;
  }
  std::size_t length = 0;
  const auto [end, ec] =
      std::from_chars(length_text.data(), length_text.data() + length_text.size(), length);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && length > max_body_bytes_)) {
    send_error(
        res,
        {413, "body",
         "the body is over the server's limit of " + std::to_string(max_body_bytes_) + " bytes"},
        true);
    return Result::Handled;
  }
  if (ec != std::errc() || end != length_text.data() + length_text.size()) {
    send_error(res, {400, "Content-Length", "must be a byte count"}, true);
    return Result::Handled;
  }
  if (media_type(req.get_header_value("Content-Type")) != "application/json") {
    send_error(res, {415, "Content-Type", "must be application/json"}, true);
    return Result::Handled;
  }
  return Result::Unhandled;
}

}  // namespace vibro::server
