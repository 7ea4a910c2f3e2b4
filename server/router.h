// Which handler answers a request, decided before cpp-httplib reads any body: unknown paths
// (404) and methods (405) are refused at once, and a POST must announce a JSON body of a known,
// bounded length (cpp-httplib 0.11 would otherwise read chunked or length-less bodies without
// limit). GET and HEAD are answered here; a POST that passes goes on to read its body.
#pragma once

#include <string>
#include <vector>

#include "server/http.h"

namespace vibro::server {

struct Route {
  std::string method;  // "GET" (which also answers HEAD), "POST" or "DELETE"
  std::string path;    // exact, or every path under it when it ends with "/"
  httplib::Server::Handler handler;
};

class Router {
 public:
  // `pages` answers GET for every path outside /api/ (the static files).
  Router(std::vector<Route> routes, httplib::Server::Handler pages, std::size_t max_body_bytes)
      : routes_(std::move(routes)),
        pages_{"GET", "/", std::move(pages)},
        max_body_bytes_(max_body_bytes) {}

  // For set_pre_routing_handler: Handled when answered (or refused) here; Unhandled for a POST
  // that may read its body and go on to the handler registered for it with Server::Post.
  httplib::Server::HandlerResponse route(const httplib::Request& req, httplib::Response& res) const;

  const std::vector<Route>& routes() const { return routes_; }

 private:
  std::vector<Route> routes_;
  Route pages_;
  std::size_t max_body_bytes_;
};

}  // namespace vibro::server
