// A saved world's <state> applied as Gazebo 11 applies it at load (issue 48): model and link
// poses in the world frame (a link the state does not name moves with its model, a nested model
// at its own saved pose), inserted models added, deleted ones removed; what the state names and
// the world lacks warned of; a pose that is not six numbers refused naming the file and line.
#include <gtest/gtest.h>

#include <cmath>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/numeric.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "world_test_util.h"

namespace jetbot_rl {
namespace {

std::string boxLink(const std::string& name, const std::string& pose) {
  return "<link name=\"" + name + "\"><pose>" + pose +
         "</pose><collision name=\"c\"><pose>0 0 0.25 0 0 0</pose><geometry><box><size>0.4 0.2 "
         "0.5</size></box></geometry></collision></link>";
}

std::string model(const std::string& name, const std::string& pose, const std::string& body) {
  return "<model name=\"" + name + "\"><static>true</static><pose>" + pose + "</pose>" + body +
         "</model>\n";
}

/// crate: links body at (1, 0) and lid at (0, 1); moved: one link at (1, 0); outer with a nested
/// inner; gone. Then `state`.
std::string world(const std::string& state) {
  return test::sdfWorld(
      "saved.world", model("crate", "0 0 0 0 0 0",
                           boxLink("body", "1 0 0 0 0 0") + boxLink("lid", "0 1 0 0 0 0")) +
                         model("moved", "0 3 0 0 0 0", boxLink("link", "1 0 0 0 0 0")) +
                         model("outer", "0 -3 0 0 0 0",
                               boxLink("base", "0 0 0 0 0 0") +
                                   model("inner", "1 0 0 0 0 0", boxLink("link", "0 0 0 0 0 0"))) +
                         model("gone", "3 3 0 0 0 0", boxLink("link", "0 0 0 0 0 0")) + state);
}

const WorldSolid* find(const GazeboWorld& w, const std::string& name) {
  for (const WorldSolid& s : w.solids) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

void expectAt(const GazeboWorld& w, const std::string& name, double x, double y, double yaw) {
  const WorldSolid* s = find(w, name);
  ASSERT_NE(s, nullptr) << name;
  ASSERT_TRUE(s->upright) << name;
  EXPECT_NEAR(s->upright->center.x(), x, 1e-9) << name;
  EXPECT_NEAR(s->upright->center.y(), y, 1e-9) << name;
  EXPECT_NEAR(std::remainder(s->upright->yaw - yaw, kPi), 0.0, 1e-9) << name;
}

TEST(SavedState, ModelsAndLinksStandWhereTheStateSaysAsGazeboPutsThem) {
  const std::string half_pi = "1.5707963267948966";  // as Gazebo saves it, to the last digit
  const GazeboWorld w = loadGazeboWorld(
      world("<state world_name=\"w\"><sim_time>116 345000000</sim_time>"
            "<model name=\"crate\"><pose frame=\"\">5 5 0 0 0 0</pose><scale>1 1 1</scale>"
            "<link name=\"body\"><pose frame=\"\">-2 -2 0 0 0 " +
            half_pi +
            "</pose>"
            "<velocity>0 0 0 0 0 0</velocity></link></model>"
            "<model name=\"moved\"><pose>2 3 0 0 0 " +
            half_pi +
            "</pose></model>"
            "<model name=\"outer\"><pose>0 -3 0 0 0 0</pose>"
            "<model name=\"inner\"><pose>-4 -4 0 0 0 0</pose></model></model>"
            "<model name=\"ghost\"><pose>0 0 0 0 0 0</pose></model>"
            "<insertions><model name=\"added\"><static>true</static><pose>-3 0 0 0 0 0</pose>" +
            boxLink("link", "0 0 0 0 0 0") +
            "</model></insertions>"
            "<deletions><name>gone</name></deletions></state>\n"));
  expectAt(w, "crate::body::c", -2, -2, kPi / 2);  // the link's saved pose
  expectAt(w, "crate::lid::c", 5, 6, 0);           // not named: with its model, (5, 5) + (0, 1)
  expectAt(w, "moved::link::c", 2, 4, kPi / 2);    // its model turned a quarter at (2, 3)
  expectAt(w, "outer::base::c", 0, -3, 0);
  expectAt(w, "outer::inner::link::c", -4, -4, 0);  // the nested model's own saved pose
  expectAt(w, "added::link::c", -3, 0, 0);
  EXPECT_EQ(find(w, "gone::link::c"), nullptr);
  ASSERT_EQ(w.warnings.size(), 1u);
  EXPECT_NE(w.warnings[0].find("model 'ghost'"), std::string::npos) << w.warnings[0];
  EXPECT_EQ(w.skipped.find("state"), std::string::npos) << w.skipped;
}

TEST(SavedState, WithoutAStateTheModelsStandWhereTheirPosesSay) {
  const GazeboWorld w = loadGazeboWorld(world(""));
  expectAt(w, "crate::body::c", 1, 0, 0);
  expectAt(w, "crate::lid::c", 0, 1, 0);
  expectAt(w, "moved::link::c", 1, 3, 0);
  expectAt(w, "outer::inner::link::c", 1, -3, 0);
  EXPECT_NE(find(w, "gone::link::c"), nullptr);
  EXPECT_TRUE(w.warnings.empty());
}

TEST(SavedState, RepeatedModelsTheStatePosesAreReadEachAtItsSavedPose) {
  // Two like posts are folded into one read (prepassWorld) unless the state poses them.
  const std::string post = boxLink("link", "0 0 0 0 0 0");
  const GazeboWorld w = loadGazeboWorld(test::sdfWorld(
      "posts.world", model("post_a", "0 0 0 0 0 0", post) + model("post_b", "1 0 0 0 0 0", post) +
                         model("post_c", "2 0 0 0 0 0", post) +
                         "<state world_name=\"w\"><model name=\"post_b\"><pose>1 2 0 0 0 0</pose>"
                         "</model></state>\n"));
  expectAt(w, "post_a::link::c", 0, 0, 0);
  expectAt(w, "post_b::link::c", 1, 2, 0);
  expectAt(w, "post_c::link::c", 2, 0, 0);
}

TEST(SavedState, APoseThatIsNotSixNumbersIsRefusedNamingTheFileAndLine) {
  const std::string path = world(
      "<state world_name=\"w\">\n<model name=\"crate\">\n<pose>5 5 zero 0 0 0</pose></model>"
      "</state>\n");
  try {
    loadGazeboWorld(path);
    ADD_FAILURE() << "accepted a state pose of 'zero'";
  } catch (const ConfigError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path + ":"), std::string::npos) << m;
    EXPECT_NE(m.find("5 5 zero 0 0 0"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace jetbot_rl
