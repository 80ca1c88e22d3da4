// Plain models (plain_models.h): the world-level models scripts write by the thousand, read
// without sdformat, give the solids and visuals sdformat gives, bit for bit, keep their place
// among sdformat's models, leave everything else to sdformat, and let a world of 20,000 distinct
// models start in seconds (sdformat alone: about 13 ms and 2.5 MB per model).
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "gazebo_test_util.h"
#include "jetbot_rl/errors.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using test::sdfWorld;

/// The text of the Error `load` throws ("accepted" when it throws none).
template <typename F>
std::string errorOf(const F& load) {
  try {
    load();
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

/// Models of random boxes, cylinders and spheres in one or two links, at random poses (turned
/// about every axis), with visuals of colours, Gazebo scripts or neither; `extra` goes into every
/// model (a <self_collide> there makes
/// each one sdformat's).
std::string randomModels(int count, const std::string& extra) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(-3.0, 3.0), turn(-3.2, 3.2), size(0.05, 0.5);
  const auto pose = [&] {
    std::ostringstream s;
    s.precision(17);
    s << "<pose>" << at(rng) << " " << at(rng) << " " << at(rng) / 3 << " " << turn(rng) << " "
      << (rng() % 2 ? 0.0 : turn(rng)) << " " << turn(rng) << "</pose>";
    return s.str();
  };
  const auto geometry = [&] {
    std::ostringstream s;
    s.precision(17);
    switch (rng() % 3) {
      case 0:
        s << "<box><size>" << size(rng) << " " << size(rng) << " " << size(rng) << "</size></box>";
        break;
      case 1:
        s << "<cylinder><radius>" << size(rng) << "</radius><length>" << size(rng)
          << "</length></cylinder>";
        break;
      default:
        s << "<sphere><radius>" << size(rng) << "</radius></sphere>";
    }
    return "<geometry>" + s.str() + "</geometry>";
  };
  std::string out;
  for (int m = 0; m < count; ++m) {
    out += "<model name=\"m" + std::to_string(m) + "\">" + extra + pose();
    for (int l = 0; l < 1 + m % 2; ++l) {
      out += "<link name=\"l" + std::to_string(l) + "\">" + (l ? pose() : "");
      if (m % 3 == 0) out += "<inertial><mass>2</mass><inertia><ixx>0.1</ixx></inertia></inertial>";
      for (int c = 0; c < 1 + m % 3; ++c) {
        out += "<collision name=\"c" + std::to_string(c) + "\">" + pose() + geometry() +
               "</collision>";
      }
      const char* materials[] = {"", "<material><diffuse>0.25 0.5 0.75 1</diffuse></material>",
                                 "<material><ambient>0.1 0.1 0.1</ambient><diffuse>0.9 0.3 0.1"
                                 "</diffuse></material>",
                                 "<material><script><uri>file://media/materials/scripts/"
                                 "gazebo.material</uri><name>Gazebo/Wood</name></script>"
                                 "</material>",
                                 "<material><script><uri>x.material</uri><name>Gazebo/Unknown"
                                 "</name></script></material>"};
      out +=
          "<visual name=\"v\">" + pose() + geometry() + materials[(m + l) % 5] + "</visual></link>";
    }
    out += "</model>\n";
  }
  return out;
}

void expectSame(const GazeboWorld& a, const GazeboWorld& b) {
  ASSERT_EQ(a.solids.size(), b.solids.size());
  for (std::size_t k = 0; k < a.solids.size(); ++k) {
    const WorldSolid &s = a.solids[k], &t = b.solids[k];
    EXPECT_EQ(s.name, t.name);
    ASSERT_EQ(bool(s.upright), bool(t.upright)) << s.name;
    if (s.upright) {
      EXPECT_EQ(s.upright->center, t.upright->center) << s.name;
      EXPECT_EQ(s.upright->yaw, t.upright->yaw) << s.name;
      EXPECT_EQ(s.upright->radius, t.upright->radius) << s.name;
      EXPECT_EQ(s.upright->half_extents, t.upright->half_extents) << s.name;
    }
    EXPECT_EQ(s.triangles, t.triangles) << s.name;
    EXPECT_EQ(s.bottom, t.bottom) << s.name;
    EXPECT_EQ(s.top, t.top) << s.name;
    EXPECT_EQ(s.bounds.min(), t.bounds.min()) << s.name;
    EXPECT_EQ(s.bounds.max(), t.bounds.max()) << s.name;
  }
  ASSERT_EQ(a.visuals.size(), b.visuals.size());
  for (std::size_t k = 0; k < a.visuals.size(); ++k) {
    EXPECT_EQ(a.visuals[k].name, b.visuals[k].name);
    EXPECT_EQ(a.visuals[k].triangles, b.visuals[k].triangles) << a.visuals[k].name;
    EXPECT_EQ(a.visuals[k].colour, b.visuals[k].colour) << a.visuals[k].name;
  }
  EXPECT_EQ(a.models, b.models);
  EXPECT_EQ(a.warnings, b.warnings);
}

TEST(PlainModels, GiveBitForBitTheSolidsAndVisualsSdformatGives) {
  const std::string plain = sdfWorld("plain.world", randomModels(40, ""), "1.7");
  const std::string sdformat =
      sdfWorld("sdformat.world", randomModels(40, "<self_collide>false</self_collide>"), "1.7");
  const GazeboWorld a = loadGazeboWorld(plain, nullptr, /*visuals=*/true);
  const GazeboWorld b = loadGazeboWorld(sdformat, nullptr, true);
  EXPECT_EQ(a.plain_models, 40);  // each read here ...
  EXPECT_EQ(b.plain_models, 0);   // ... and there by sdformat
  EXPECT_EQ(a.visuals.size(), 60u);
  // The materials made colours: a diffuse one, a script's, the grey of an unknown script.
  std::set<std::vector<float>> colours;
  for (const WorldVisual& v : a.visuals) colours.insert({v.colour.x(), v.colour.y(), v.colour.z()});
  EXPECT_EQ(colours.size(), 4u);
  EXPECT_NE(a.skipped.find("material 'Gazebo/Unknown'"), std::string::npos) << a.skipped;
  expectSame(a, b);
  // Without visuals, the same solids.
  const GazeboWorld c = loadGazeboWorld(plain);
  EXPECT_EQ(c.plain_models, 40);
  EXPECT_TRUE(c.visuals.empty());
  EXPECT_EQ(c.solids.size(), a.solids.size());
}

TEST(PlainModels, KeepTheirPlaceAmongSdformatsModels) {
  // sdformat's models (a <self_collide> each), plain ones between them, and an include of a
  // light (no model: it takes no place) before one of them.
  const std::string models = ::testing::TempDir() + "plain_place_models";
  std::filesystem::create_directories(models + "/lamp");
  std::ofstream(models + "/lamp/model.config")
      << "<?xml version=\"1.0\"?><model><name>lamp</name><sdf version=\"1.6\">model.sdf</sdf>"
         "</model>\n";
  std::ofstream(models + "/lamp/model.sdf")
      << "<?xml version=\"1.0\"?><sdf version=\"1.6\"><light type=\"point\" name=\"lamp\">"
         "<pose>0 0 2 0 0 0</pose></light></sdf>\n";
  const char* before = std::getenv("GAZEBO_MODEL_PATH");
  const std::string had = before ? before : "";
  ::setenv("GAZEBO_MODEL_PATH", models.c_str(), 1);
  const auto model = [](const std::string& name, double x, const std::string& extra) {
    return "<model name=\"" + name + "\">" + extra + "<pose>" + std::to_string(x) +
           " 0 0.5 0 0 0</pose><link name=\"l\"><collision name=\"c\"><geometry><box><size>0.1 " +
           std::to_string(0.1 + x / 100) +
           " 1</size></box></geometry></collision></link></model>\n";
  };
  const std::string own = "<self_collide>false</self_collide>";
  const GazeboWorld w = loadGazeboWorld(sdfWorld(
      "places.world", model("p", 0, "") + model("a", 1, own) + model("q", 2, "") +
                          "<include><uri>model://lamp</uri></include>\n" + model("r", 3, "") +
                          model("b", 4, own) + model("s", 5, "") + model("t", 6, "")));
  if (before) {  // the other tests' model path back
    ::setenv("GAZEBO_MODEL_PATH", had.c_str(), 1);
  } else {
    ::unsetenv("GAZEBO_MODEL_PATH");
  }
  EXPECT_EQ(w.plain_models, 5);
  std::string order;
  for (const WorldSolid& s : w.solids) order += s.name.substr(0, 1);
  EXPECT_EQ(order, "paqrbst");
}

TEST(PlainModels, WhatIsMoreThanPlainIsLeftToSdformat) {
  // A script without a file is sdformat's to refuse.
  const std::string no_uri =
      sdfWorld("no_uri.world",
               "<model name=\"m\"><link name=\"l\"><visual name=\"v\"><geometry><box><size>"
               "1 1 1</size></box></geometry><material><script><name>Gazebo/Wood</name>"
               "</script></material></visual></link></model>\n");
  const std::string e = errorOf([&] { loadGazeboWorld(no_uri, nullptr, true); });
  EXPECT_NE(e.find("missing a child <uri>"), std::string::npos) << e;
  // A pose in degrees or relative to a frame, a material with more than colours: read by
  // sdformat, with its meaning (a plain reader taking them would turn 90 radians).
  const std::string body =
      "<frame name=\"f\"><pose>5 0 0 0 0 0</pose></frame>\n"
      "<model name=\"deg\"><pose degrees=\"true\">0 0 0.5 0 0 90</pose><link name=\"l\">"
      "<collision name=\"c\"><geometry><box><size>2 1 1</size></box></geometry></collision>"
      "</link></model>\n"
      "<model name=\"rel\"><pose relative_to=\"f\">1 0 0.5 0 0 0</pose><link name=\"l\">"
      "<collision name=\"c\"><geometry><box><size>1 3 1</size></box></geometry></collision>"
      "</link></model>\n"
      "<model name=\"red\"><pose>0 4 0.5 0 0 0</pose><link name=\"l\"><collision name=\"c\">"
      "<geometry><box><size>1 1 2</size></box></geometry></collision><visual name=\"v\">"
      "<geometry><box><size>1 1 2</size></box></geometry><material><lighting>true</lighting>"
      "<diffuse>1 0 0 1</diffuse></material></visual></link></model>\n";
  const GazeboWorld w = loadGazeboWorld(sdfWorld("more.world", body, "1.9"), nullptr, true);
  EXPECT_EQ(w.plain_models, 0);
  ASSERT_EQ(w.solids.size(), 3u);
  EXPECT_NEAR(w.solids[0].upright->yaw, 1.5707963267948966, 1e-12);
  EXPECT_NEAR(w.solids[1].upright->center.x(), 6.0, 1e-12);
  ASSERT_EQ(w.visuals.size(), 1u);
  EXPECT_EQ(w.visuals[0].colour, Eigen::Vector3f(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(loadGazeboWorld(sdfWorld("more.world", body, "1.9")).plain_models, 0);
}

TEST(PlainModels, WhatSdformatRefusesIsStillRefusedNamingTheLine) {
  const auto box = [](const std::string& name, const std::string& size) {
    return "<model name=\"" + name +
           "\"><link name=\"l\"><collision name=\"c\"><geometry><box>"
           "<size>" +
           size + "</size></box></geometry></collision></link></model>\n";
  };
  // Two models of one name: sdformat's error, though both are plain.
  std::string e = errorOf(
      [&] { loadGazeboWorld(sdfWorld("twice.world", box("a", "1 1 1") + box("a", "1 2 1"))); });
  EXPECT_NE(e.find("twice.world"), std::string::npos) << e;
  EXPECT_NE(e.find("model with name[a] already exists"), std::string::npos) << e;
  // A plain model named as an included model (an include without <name>: its model's name).
  std::filesystem::create_directories(::testing::TempDir() + "dup_post");
  std::ofstream(::testing::TempDir() + "dup_post/model.config")
      << "<?xml version=\"1.0\"?><model><name>post</name><sdf version=\"1.6\">model.sdf</sdf>"
         "</model>\n";
  std::ofstream(::testing::TempDir() + "dup_post/model.sdf")
      << "<?xml version=\"1.0\"?><sdf version=\"1.6\">" << box("a", "1 1 1") << "</sdf>\n";
  e = errorOf([&] {
    loadGazeboWorld(sdfWorld(
        "twice_included.world",
        "<include><uri>dup_post</uri><pose>3 0 0 0 0 0</pose></include>\n" + box("a", "1 2 1")));
  });
  EXPECT_NE(e.find("model with name[a] already exists"), std::string::npos) << e;
  // A size that is not three numbers: sdformat reads it and names the line.
  e = errorOf(
      [&] { loadGazeboWorld(sdfWorld("words.world", box("a", "1 1 1") + box("b", "1 one 1"))); });
  EXPECT_NE(e.find("words.world:5"), std::string::npos) << e;
  // A plain model's size out of range: refused here naming the file, line and collision.
  e = errorOf(
      [&] { loadGazeboWorld(sdfWorld("neg.world", box("a", "1 1 1") + box("b", "1 -2 1"))); });
  EXPECT_NE(e.find("neg.world:5: collision 'b::l::c': its box size -2 must be in (0, 1000] m"),
            std::string::npos)
      << e;
}

TEST(PlainModels, AWorldOf20000DistinctModelsStartsInSeconds) {
  // 20,000 boxes, no two alike (sdformat alone: 13 ms and 2.5 MB each, minutes and 50 GB), and
  // 20,000 like ones (folded: sdformat resolved their frames in time growing with the square).
  for (const bool distinct : {true, false}) {
    std::string body;
    for (int k = 0; k < 20000; ++k) {
      const double size = distinct ? 0.1 + k * 1e-5 : 0.2;
      body += "<model name=\"b" + std::to_string(k) + "\"><static>true</static><pose>" +
              std::to_string(k % 150) + " " + std::to_string(k / 150) +
              " 0.5 0 0 0.3</pose><link name=\"link\"><collision name=\"c\"><geometry><box><size>" +
              std::to_string(size) + " " + std::to_string(size) +
              " 1</size></box></geometry></collision></link></model>\n";
    }
    const std::string file = sdfWorld("boxes20000.world", body);
    const auto start = std::chrono::steady_clock::now();
    const GazeboWorld w = loadGazeboWorld(file);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("FIGURE: 20,000 %s box models read in %.2f s, peak memory %.0f MB\n",
                distinct ? "distinct" : "like", s, usage.ru_maxrss / 1024.0);
    ASSERT_EQ(w.solids.size(), 20000u);
    EXPECT_EQ(w.models, 20000);
    EXPECT_EQ(w.plain_models, distinct ? 20000 : 1);
    EXPECT_EQ(w.repeated_models, distinct ? 0 : 19999);
    EXPECT_NEAR(test::solid(w, "b19999::link::c").upright->center.x(), 19999 % 150, 1e-12);
  }
}

}  // namespace
}  // namespace jetbot_rl
