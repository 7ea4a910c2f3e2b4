// Same scene, same bytes: answers are cached by the canonical scene, tagged, and revalidated.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/presets.h"
#include "tests/server/test_server.h"

namespace vibro::testing {
namespace {

class Caching : public SharedServerTest {};

TEST_F(Caching, TheSameSceneGivesTheSameBytesFromTheCache) {
  const std::string scene = paper_scene(6.0);
  auto first = server->client().Post("/api/render", scene, "application/json");
  auto second = server->client().Post("/api/render", scene, "application/json");
  ASSERT_TRUE(first && second);
  ASSERT_EQ(first->status, 200) << first->body;
  ASSERT_EQ(second->status, 200);
  EXPECT_EQ(first->body, second->body);
  EXPECT_EQ(first->get_header_value("X-Vibro-Cache"), "miss");
  EXPECT_EQ(second->get_header_value("X-Vibro-Cache"), "hit");
  EXPECT_FALSE(first->get_header_value("ETag").empty());
  EXPECT_EQ(first->get_header_value("ETag"), second->get_header_value("ETag"));
  EXPECT_EQ(first->get_header_value("Cache-Control"), "public, max-age=3600");
  // Where the phase portraits and φ(t) lie comes with the image, from the cache too: one per
  // panel, inside the image, with axes that span something.
  const std::string axes = first->get_header_value("X-Vibro-Plot-Axes");
  EXPECT_EQ(second->get_header_value("X-Vibro-Plot-Axes"), axes);
  const nlohmann::json list = nlohmann::json::parse(axes);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0]["kind"], "phase");
  EXPECT_EQ(list[0]["pellet"], 0);
  EXPECT_EQ(list[1]["pellet"], 1);
  EXPECT_EQ(list[2]["kind"], "time");
  EXPECT_EQ(list[2]["x"][1], 6.0);  // φ(t) to t_end
  for (const auto& a : list) {
    EXPECT_GT(a["left"].get<double>(), 0.0);
    EXPECT_LT(a["left"].get<double>() + a["width"].get<double>(), 1200.0);
    EXPECT_LT(a["x"][0].get<double>(), a["x"][1].get<double>());
    EXPECT_LT(a["y"][0].get<double>(), a["y"][1].get<double>());
  }
}

TEST_F(Caching, RunResultsAreCachedToo) {
  auto first = server->client().Get("/api/simulate?preset=paper&t_end=7");
  auto second = server->client().Get("/api/simulate?preset=paper&t_end=7");
  ASSERT_TRUE(first && second);
  ASSERT_EQ(first->status, 200) << first->body;
  EXPECT_EQ(first->body, second->body);  // wall_ms included: the second is the first's bytes
  EXPECT_EQ(second->get_header_value("X-Vibro-Cache"), "hit");
}

TEST_F(Caching, IfNoneMatchGives304) {
  auto first = server->client().Get("/api/render?preset=paper&width=500&height=400");
  ASSERT_TRUE(first);
  ASSERT_EQ(first->status, 200);
  const std::string etag = first->get_header_value("ETag");
  auto again = server->client().Get("/api/render?preset=paper&width=500&height=400",
                                    {{"If-None-Match", "W/\"other\", " + etag}});
  ASSERT_TRUE(again);
  EXPECT_EQ(again->status, 304);
  EXPECT_TRUE(again->body.empty());
  EXPECT_EQ(again->get_header_value("ETag"), etag);

  auto other = server->client().Get("/api/render?preset=paper&width=500&height=401",
                                    {{"If-None-Match", etag}});
  ASSERT_TRUE(other);
  EXPECT_EQ(other->status, 200);
}

TEST_F(Caching, FormatsAndScenesHaveTheirOwnTags) {
  auto png = server->client().Get("/api/render?preset=paper&width=400&height=300&format=png");
  auto svg = server->client().Get("/api/render?preset=paper&width=400&height=300&format=svg");
  auto later = server->client().Get("/api/render?preset=paper&width=400&height=300&t_end=9");
  ASSERT_TRUE(png && svg && later);
  EXPECT_NE(png->get_header_value("ETag"), svg->get_header_value("ETag"));
  EXPECT_NE(png->get_header_value("ETag"), later->get_header_value("ETag"));
}

TEST_F(Caching, APresetAndTheSameScenePostedShareAnEntry) {
  auto get = server->client().Get("/api/render?preset=paper-fig4&format=png");
  ASSERT_TRUE(get);
  ASSERT_EQ(get->status, 200) << get->body;
  auto post = server->client().Post("/api/render?format=png",
                                    std::string(*preset_json("paper-fig4")), "application/json");
  ASSERT_TRUE(post);
  ASSERT_EQ(post->status, 200);
  EXPECT_EQ(post->get_header_value("X-Vibro-Cache"), "hit");
  EXPECT_EQ(post->body, get->body);
}

TEST_F(Caching, AnswersAreSentAsCachedWithoutCompressingEachTime) {
  for (const char* encoding : {"br", "gzip, deflate, br"}) {
    auto res = server->client().Get("/api/render?preset=paper&format=svg&width=400&height=300",
                                    {{"Accept-Encoding", encoding}});
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
    EXPECT_FALSE(res->has_header("Content-Encoding")) << encoding;
    EXPECT_NE(res->body.find("<svg"), std::string::npos);
  }
}

TEST_F(Caching, ErrorsAreNotCached) {
  auto res = server->client().Get("/api/render?preset=nope");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->get_header_value("Cache-Control"), "no-store");
  EXPECT_TRUE(res->get_header_value("ETag").empty());
}

}  // namespace
}  // namespace vibro::testing
