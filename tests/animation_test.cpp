// The animation page of `tumble run --animate`: written whole, offline (no URL it would fetch),
// with every row embedded, and names that cannot break out of the data element. The browser
// test (tests/browser/) opens the pages and checks what they draw.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "test_files.hpp"
#include "tumble/output/animation_html.hpp"
#include "tumble/scenario/scenario.hpp"

namespace tumble {
namespace {

namespace fs = std::filesystem;
using test::read_file;

fs::path fresh_directory(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("tumble_animation_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The exit status of `tumble run ARGUMENTS`, its output discarded.
int tumble_run_status(const std::string& arguments) {
  const std::string command = std::string(TUMBLE_EXE) + " run " + arguments + " > /dev/null 2>&1";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// The JSON inside <script type="application/json" id="tumble-data">.
std::string embedded_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"tumble-data\">";
  const auto begin = html.find(open);
  if (begin == std::string::npos) return {};
  const auto end = html.find("</script>", begin);
  return html.substr(begin + open.size(), end - begin - open.size());
}

TEST(AnimationHtml, JsonStringsCannotCloseTheScriptElement) {
  EXPECT_EQ(json_string("prism"), "\"prism\"");
  EXPECT_EQ(json_string("</script><script>alert(1)</script>"),
            "\"\\u003c/script\\u003e\\u003cscript\\u003ealert(1)\\u003c/script\\u003e\"");
  EXPECT_EQ(json_string("a\"b\\c\n&"), "\"a\\\"b\\\\c\\u000a\\u0026\"");
  EXPECT_EQ(json_string("\xE2\x80\xA8"), "\"\\u2028\"");
  EXPECT_EQ(json_string("\xC3\xA9t\xC3\xA9"), "\"\xC3\xA9t\xC3\xA9\"");  // UTF-8 passes
}

TEST(AnimationHtml, ThePrismPageEmbedsEveryRowAndFetchesNothing) {
  const fs::path dir = fresh_directory("prism");
  ASSERT_EQ(tumble_run_status(std::string(TUMBLE_SOURCE_DIR) +
                              "/examples/tumbling_prism.yaml --out " + dir.string() + " --animate"),
            0);
  ASSERT_TRUE(fs::exists(dir / "tumbling_prism.csv"));
  const fs::path page = dir / "tumbling_prism.html";
  ASSERT_TRUE(fs::exists(page));
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
  }
  const std::string html = read_file(page);
  EXPECT_NE(html.find("<title>tumbling prism</title>"), std::string::npos);
  const std::string data = embedded_data(html);
  EXPECT_NE(data.find("\"rows\":401,"), std::string::npos);
  EXPECT_NE(data.find("\"shape\":\"box\""), std::string::npos);
  // 401 rows of t as float64, base64: ceil(401 * 8 / 3) * 4 characters.
  const std::string time_key = "\"time\":\"";
  const std::size_t time_begin = data.find(time_key);
  ASSERT_NE(time_begin, std::string::npos);
  const std::size_t time_end = data.find('"', time_begin + time_key.size());
  ASSERT_NE(time_end, std::string::npos);
  EXPECT_EQ(time_end - (time_begin + time_key.size()), std::size_t{(401 * 8 + 2) / 3 * 4});

  // Nothing the browser would fetch: every http(s) URL in the page is three.js's XHTML
  // namespace name, an identifier that is never loaded (so no src/href/url()/import to one).
  std::size_t at = 0;
  while ((at = html.find("http", at)) != std::string::npos) {
    const std::string rest = html.substr(at, 40);
    if (rest.rfind("http://", 0) == 0 || rest.rfind("https://", 0) == 0) {
      EXPECT_TRUE(rest.rfind("http://www.w3.org/", 0) == 0) << rest;
    }
    at += 4;
  }
}

TEST(AnimationHtml, OutputAnimationNamesThePageAndNamesStayText) {
  const fs::path dir = fresh_directory("named");
  const fs::path scenario = dir / "named.yaml";
  std::ofstream(scenario) << "tumble: 1\n"
                             "name: \"</script><script>alert(1)</script> & <b>\"\n"
                             "bodies:\n"
                             "  \"<img/src=x/onerror=alert(1)>\": {shape: sphere, radius: 0.2, "
                             "mass: 1}\n"
                             "simulate: {duration: 1, output_every: 0.25}\n"
                             "output: {trajectory: run.csv, animation: pages/run.html}\n";
  ASSERT_EQ(tumble_run_status(scenario.string() + " --out " + (dir / "out").string()), 0);
  const std::string html = read_file(dir / "out" / "pages" / "run.html");
  ASSERT_FALSE(html.empty());
  EXPECT_NE(html.find("<title>&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt; &amp; "
                      "&lt;b&gt;</title>"),
            std::string::npos);
  const std::string data = embedded_data(html);
  EXPECT_NE(data.find("\"rows\":5,"), std::string::npos);
  EXPECT_EQ(data.find('<'), std::string::npos);
  EXPECT_NE(data.find("\\u003cimg/src=x/onerror=alert(1)\\u003e"), std::string::npos);
  // Exactly two script elements: the data and the bundle.
  std::size_t scripts = 0;
  for (std::size_t at = 0; (at = html.find("<script", at)) != std::string::npos; ++at) ++scripts;
  EXPECT_EQ(scripts, 2u);
}

TEST(AnimationHtml, EveryContactsPlaneIsInTheSceneOnce) {
  // The ramp race: three bodies, each with a contact on the one ramp; boxes on ramps: two
  // ramps. Each distinct plane is drawn once, through its point with its unit normal.
  for (const auto& [example, distinct] :
       {std::pair{"ramp_race", 1u}, std::pair{"boxes_on_ramps", 2u}}) {
    const std::string path = std::string(TUMBLE_SOURCE_DIR) + "/examples/" + example + ".yaml";
    const Scenario scenario = load_scenario(path, {});
    const AnimationScene scene = make_animation_scene(scenario);
    ASSERT_EQ(scene.planes.size(), distinct) << example;
    EXPECT_EQ(scene.planes[0].name, scenario.contacts[0].name);
    for (const AnimationPlane& plane : scene.planes) {
      EXPECT_NEAR(plane.normal_W.norm(), 1.0, 1e-15);
      const bool given = std::any_of(
          scenario.contacts.begin(), scenario.contacts.end(), [&](const ContactSpec& c) {
            return c.plane_point_W == plane.point_W && c.plane_normal_W == plane.normal_W;
          });
      EXPECT_TRUE(given) << example;
    }
    const fs::path dir = fresh_directory(std::string("planes_") + example);
    ASSERT_EQ(tumble_run_status(path + " --out " + dir.string() + " --animate"), 0);
    fs::path page;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.path().extension() == ".html") page = entry.path();
    }
    ASSERT_FALSE(page.empty());
    const std::string data = embedded_data(read_file(page));
    EXPECT_NE(data.find("\"planes\":[{\"name\":\"" + scenario.contacts[0].name + "\""),
              std::string::npos);
    std::size_t normals = 0;
    for (std::size_t at = 0; (at = data.find("\"normal\":", at)) != std::string::npos; ++at) {
      ++normals;
    }
    EXPECT_EQ(normals, distinct) << example;
  }
}

TEST(AnimationHtml, AnUnwritablePageIsExitStatus5) {
  const fs::path dir = fresh_directory("unwritable");
  const fs::path scenario = dir / "blocked.yaml";
  std::ofstream(scenario) << "tumble: 1\nname: blocked\nbodies:\n  b: {shape: sphere, radius: "
                             "0.2, mass: 1}\nsimulate: {duration: 1}\noutput: {animation: "
                             "page.html}\n";
  // A directory where the page should go: the rename cannot replace it.
  fs::create_directories(dir / "out" / "page.html" / "inside");
  EXPECT_EQ(tumble_run_status(scenario.string() + " --out " + (dir / "out").string()), 5);
}

TEST(AnimationHtml, RecordedRowsMustMatchTheScene) {
  RecordedTrajectory rows(1);
  const BodyState state;
  rows.record(0.0, std::span<const BodyState>(&state, 1), SystemQuantities{});
  AnimationScene scene;
  scene.name = "empty";
  EXPECT_THROW(write_animation_html(fs::temp_directory_path() / "never.html", scene, rows),
               std::invalid_argument);
}

}  // namespace
}  // namespace tumble
