// The web page's files, with their types, and nothing outside web/ however the path is spelled.
#include <gtest/gtest.h>

#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

class StaticFiles : public SharedServerTest {};

TEST_F(StaticFiles, TheRootIsIndexHtml) {
  auto res = server->client().Get("/");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("Content-Type"), "text/html; charset=utf-8");
  EXPECT_NE(res->body.find("<title>vibro</title>"), std::string::npos);
}

TEST_F(StaticFiles, FilesHaveTheirContentTypes) {
  const std::pair<const char*, const char*> cases[] = {
      {"/index.html", "text/html; charset=utf-8"},
      {"/app.js", "text/javascript; charset=utf-8"},
      {"/style.css", "text/css; charset=utf-8"},
      {"/img/logo.svg", "image/svg+xml"},
  };
  for (const auto& [path, type] : cases) {
    auto res = server->client().Get(path);
    ASSERT_TRUE(res) << path;
    EXPECT_EQ(res->status, 200) << path;
    EXPECT_EQ(res->get_header_value("Content-Type"), type) << path;
  }
}

TEST_F(StaticFiles, NothingOutsideWebIsServed) {
  const char* attempts[] = {
      "/../secret.txt",
      "/%2e%2e/secret.txt",
      "/%2E%2E/secret.txt",
      "/img/../../secret.txt",
      "/img/%2e%2e/%2e%2e/secret.txt",
      "/..%2fsecret.txt",
      "/%2e%2e%2fsecret.txt",
      "/img/..%5c..%5csecret.txt",
      "//secret.txt",
      "/./index.html",
      "/link.txt",
      "/up/secret.txt",
      "/up/web/index.html",
      "/.hidden.txt",
      "/img/",
      "/img",
      "/index.html%00.png",
      "/api/../../secret.txt",
      "/etc/passwd",
      "/%252e%252e/secret.txt",
  };
  for (const char* path : attempts) {
    const RawReply reply = raw_exchange(server->port(), std::string("GET ") + path +
                                                            " HTTP/1.1\r\nHost: x\r\n"
                                                            "Connection: close\r\n\r\n");
    EXPECT_GE(reply.status(), 400) << path << "\n" << reply.bytes;
    EXPECT_LT(reply.status(), 500) << path;
    EXPECT_EQ(reply.bytes.find("secret outside"), std::string::npos) << path;
  }
}

TEST_F(StaticFiles, OnlyGetAndHead) {
  auto res = server->client().Post("/index.html", "{}", "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 405);
}

}  // namespace
}  // namespace vibro::testing
