// The page helpers: escaping, base64, dotted keys into JSON, and how numbers are shown.
#include <gtest/gtest.h>

#include "reports/metrics.h"
#include "reports/page_util.h"

namespace rtsim::reports {
namespace {

using Json = nlohmann::ordered_json;

TEST(Pages, EscapesHtml) {
  EXPECT_EQ(html_escape("<a href=\"x\">&</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&lt;/a&gt;");
}

TEST(Pages, Base64OfTheRfc4648Vectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(Pages, DottedKeysReachObjectsAndArrays) {
  Json doc = Json::parse(R"({"a": {"b": [10, {"c": 3}]}})");
  EXPECT_EQ(at_key(doc, "a.b.0"), 10);
  EXPECT_EQ(at_key(doc, "a.b.1.c"), 3);
  EXPECT_TRUE(at_key(doc, "a.b.2").is_null()) << "past the end";
  EXPECT_TRUE(at_key(doc, "a.x").is_null()) << "missing key";
  EXPECT_TRUE(at_key(doc, "a.b.c").is_null()) << "a name into an array";
}

TEST(Pages, ShowsNumbersByStyle) {
  // One thousands rule for integers and reals alike: grouped from 10,000 up.
  EXPECT_EQ(show(Json(975104), Style::Integer), "975,104");
  EXPECT_EQ(show(Json(975104.0), Style::Integer), "975,104");
  EXPECT_EQ(show(Json(uint64_t(975104)), Style::Real), "975,104");
  EXPECT_EQ(show(Json(18446744073709551615u), Style::Integer), "18,446,744,073,709,551,615");
  EXPECT_EQ(show(Json(9999), Style::Integer), "9999");
  EXPECT_EQ(show(Json(10000), Style::Integer), "10,000");
  EXPECT_EQ(show(Json(1234.4), Style::Real), "1234") << "whole from 1,000 on";
  EXPECT_EQ(show(Json(-12), Style::Integer), "-12");
  EXPECT_EQ(show(Json(209.70255), Style::Real), "209.7");
  EXPECT_EQ(show(Json(11603.4), Style::Real), "11,603") << "plain, not 1.16e+04";
  EXPECT_EQ(show(Json(-1234567.0), Style::Real), "-1,234,567");
  EXPECT_EQ(show(Json(999.94), Style::Real), "999.9");
  EXPECT_EQ(show(Json(0.05772), Style::Real), "0.05772");
  EXPECT_EQ(show(Json(0.86088), Style::Percent), "86.09%");
  EXPECT_EQ(show(Json(), Style::Real), "n/a");
  EXPECT_EQ(show(Json(true), Style::Text), "true");
}

TEST(Pages, NumberCellsCarryTheirKeyAndRawValue) {
  Json doc = Json::parse(R"({"t": {"cycles": 1234.5}})");
  EXPECT_EQ(html_cell(doc, "t.cycles", Style::Integer),
            "<td data-key=\"t.cycles\" data-value=\"1234.5\">1234</td>");
}

TEST(Metrics, DirectionsSayWhichWayIsBetter) {
  EXPECT_EQ(metric_direction("cycles"), "lower");
  EXPECT_EQ(metric_direction("type.camera.dram_bytes_per_ray"), "lower");
  EXPECT_EQ(metric_direction("l1_hit_rate"), "higher");
  EXPECT_EQ(metric_direction("mrays_per_second"), "higher");
  EXPECT_EQ(metric_direction("rays"), "either");
  EXPECT_EQ(metric_direction("mrays_per_joule"), "higher");
  EXPECT_EQ(metric_direction("energy_nj_per_ray"), "lower");
  EXPECT_EQ(metric_direction("type.ao.dynamic_energy_nj_per_ray"), "lower");
  EXPECT_EQ(metric_direction("power_w"), "lower");
  EXPECT_EQ(metric_direction("sram_area_mm2"), "lower");
}

}  // namespace
}  // namespace rtsim::reports
