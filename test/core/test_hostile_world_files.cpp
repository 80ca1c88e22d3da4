// Hostile world files (issue 49): a FIFO where a file is expected, shapes of absurd or
// non-positive sizes, shapes far from the origin, a grid too large to hold: each is refused in
// bounded time naming the file (and line) and the collision, never a hang, a crash or gigabytes.
// Each case prints its time and the process's peak memory as FIGURE lines.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>

#include "jetbot_rl/errors.h"
#include "jetbot_rl/robot/robot_model.h"
#include "jetbot_rl/world/gazebo/mesh_loader.h"
#include "jetbot_rl/world/gazebo/sdf_world_reader.h"
#include "jetbot_rl/world/occupancy_map.h"
#include "jetbot_rl/world/world_model.h"
#include "test_util.h"

namespace jetbot_rl {
namespace {

using test::sdfWorld;

/// The error text of `load` (which must throw an Error), with its time and the peak memory as a
/// FIGURE line; fails when it does not throw.
std::string refusal(const std::string& what, const std::function<void()>& load) {
  const auto start = std::chrono::steady_clock::now();
  std::string text = "accepted";
  try {
    load();
  } catch (const Error& e) {
    text = e.what();
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("FIGURE: %s refused in %.3f s, peak memory %.0f MB: %s\n", what.c_str(), s,
              usage.ru_maxrss / 1024.0, text.c_str());
  EXPECT_LT(s, 5.0) << what;
  EXPECT_NE(text, "accepted") << what;
  return text;
}

/// A FIFO at `path` with a writer waiting on it, so that a reader that opens it anyway gets an
/// empty file (and the test a wrong message) instead of blocking for ever.
class Fifo {
 public:
  explicit Fifo(const std::string& path) : path_(path) {
    ::unlink(path.c_str());
    EXPECT_EQ(::mkfifo(path.c_str(), 0600), 0);
    writer_ = std::thread([this] {
      const int fd = ::open(path_.c_str(), O_WRONLY);  // until a reader opens it
      if (fd >= 0) ::close(fd);
    });
  }
  ~Fifo() {
    const int fd = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK);  // releases the writer
    writer_.join();
    if (fd >= 0) ::close(fd);
    ::unlink(path_.c_str());
  }

 private:
  std::string path_;
  std::thread writer_;
};

std::string boxModel(const std::string& name, const std::string& pose, const std::string& size) {
  return "<model name=\"" + name + "\"><static>true</static><pose>" + pose +
         "</pose><link name=\"link\"><collision name=\"c\"><geometry><box><size>" + size +
         "</size></box></geometry></collision></link></model>\n";
}

std::string worldRefusal(const std::string& what, const std::string& file) {
  WorldConfig config;
  config.gazebo_world = file;
  return refusal(what, [&] {
    validateConfig(config);
    WorldModel world(config, 0.1);
  });
}

TEST(HostileWorldFiles, AFifoWhereAFileIsExpectedIsRefusedWithoutOpeningIt) {
  const std::string fifo = ::testing::TempDir() + "a_fifo";
  {
    Fifo f(fifo + ".stl");
    const std::string e = refusal("a FIFO mesh", [&] { loadMeshTriangles(fifo + ".stl"); });
    EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
    EXPECT_NE(e.find("a_fifo.stl"), std::string::npos) << e;
  }
  {
    Fifo f(fifo + ".pgm");
    const std::string yaml = test::writeTempFile(
        "fifo_map.yaml", "image: " + fifo +
                             ".pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                             "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
    const std::string e = refusal("a FIFO map image", [&] { OccupancyMap::fromYamlFile(yaml); });
    EXPECT_NE(e.find("invalid image = '" + fifo + ".pgm'"), std::string::npos) << e;
    EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
  }
  {
    Fifo f(fifo + ".yaml");
    const std::string e =
        refusal("a FIFO map YAML", [&] { OccupancyMap::fromYamlFile(fifo + ".yaml"); });
    EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
  }
  {
    Fifo f(fifo + ".world");
    const std::string e = worldRefusal("a FIFO world file", fifo + ".world");
    EXPECT_NE(e.find("a_fifo.world: is a FIFO"), std::string::npos) << e;
  }
  {
    Fifo f(fifo + ".urdf");
    const std::string e = refusal("a FIFO URDF", [&] { RobotModel::fromUrdfFile(fifo + ".urdf"); });
    EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
  }
}

TEST(HostileWorldFiles, ShapesOfNoOrAbsurdSizeAreRefusedNamingTheCollisionFileAndLine) {
  for (const auto& [size, shown] : {std::make_pair("1 -1 1", "-1"), std::make_pair("0 1 1", "0"),
                                    std::make_pair("1e300 1 1", "1e+300")}) {
    const std::string file = sdfWorld("bad_size.world", boxModel("ok", "0 0 0.5 0 0 0", "1 1 1") +
                                                            boxModel("bad", "3 0 0.5 0 0 0", size));
    const std::string e = worldRefusal(std::string("a box of size ") + size, file);
    EXPECT_NE(e.find("bad_size.world:5: collision 'bad::link::c': its box size " +
                     std::string(shown) + " must be in (0, 1000] m"),
              std::string::npos)
        << e;
  }
  const std::string cylinder =
      sdfWorld("bad_cylinder.world",
               "<model name=\"m\"><static>true</static><link name=\"link\"><collision name=\"c\">"
               "<geometry><cylinder><radius>1e300</radius><length>1</length></cylinder></geometry>"
               "</collision></link></model>\n");
  const std::string e = worldRefusal("a cylinder of radius 1e300", cylinder);
  EXPECT_NE(e.find("collision 'm::link::c': its cylinder radius and length 1e+300"),
            std::string::npos)
      << e;
}

TEST(HostileWorldFiles, AShapeFarOutOrAGridTooLargeIsRefusedNamingTheShape) {
  std::string e =
      worldRefusal("a box 100 km out",
                   sdfWorld("far.world", boxModel("ok", "0 0 0.5 0 0 0", "1 1 1") +
                                             boxModel("far", "100000 0 0.5 0 0 0", "1 1 1")));
  EXPECT_NE(e.find("collision 'far::link::c': its pose in the world (100000"), std::string::npos)
      << e;  // a repeat of 'ok' (folded, then moved): checked where it lies
  EXPECT_NE(e.find("must lie within 10000 m of the origin"), std::string::npos) << e;
  // A pose at 1e300 (a size of its own, so that it is read, not folded as a repeat): the pose
  // named, not the spawn point.
  e = worldRefusal("a box at x = 1e300",
                   sdfWorld("huge_pose.world", boxModel("ok", "0 0 0.5 0 0 0", "1 1 1") +
                                                   boxModel("far", "1e300 0 0.5 0 0 0", "2 1 1")));
  EXPECT_NE(e.find("huge_pose.world:5: collision 'far::link::c': its pose in the world (1e+300"),
            std::string::npos)
      << e;
  EXPECT_EQ(e.find("spawn"), std::string::npos) << e;
  // Within the bounds, but 402 x 402 m at 0.05 m: 65 million cells.
  e = worldRefusal("a 400 m wide world",
                   sdfWorld("wide.world", boxModel("a", "-200 -200 0.5 0 0 0", "1 1 1") +
                                              boxModel("b", "200 200 0.5 0 0 0", "1 1 1") +
                                              boxModel("c", "0 0 0.5 0 0 0", "1 1 1")));
  EXPECT_NE(e.find("invalid world/gazebo_world"), std::string::npos) << e;
  EXPECT_NE(e.find("more than the 2.5e+07 its grid may hold"), std::string::npos) << e;
  EXPECT_NE(e.find("the farthest from the origin is 'a::link::c'"), std::string::npos) << e;
}

/// A model folder `models/name` (model.config, model.sdf) whose link holds a box and `includes`.
void writeModel(const std::string& models, const std::string& name, const std::string& includes) {
  std::filesystem::create_directories(models + "/" + name);
  std::ofstream(models + "/" + name + "/model.config")
      << "<?xml version=\"1.0\"?>\n<model><name>" << name
      << "</name><sdf version=\"1.6\">model.sdf</sdf></model>\n";
  std::ofstream(models + "/" + name + "/model.sdf")
      << "<?xml version=\"1.0\"?>\n<sdf version=\"1.6\">\n<model name=\"" << name
      << "\"><static>true</static><link name=\"link\"><collision name=\"c\"><geometry><box>"
         "<size>1 1 1</size></box></geometry></collision></link>\n"
      << includes << "</model>\n</sdf>\n";
}

std::string include(const std::string& uri, const std::string& pose) {
  return "<include><uri>" + uri + "</uri><pose>" + pose + "</pose></include>\n";
}

class IncludedModels : public ::testing::Test {
 protected:
  void SetUp() override {
    models_ = ::testing::TempDir() + "hostile_models";
    std::filesystem::remove_all(models_);
    const char* before = std::getenv("GAZEBO_MODEL_PATH");
    had_ = before != nullptr;
    if (had_) before_ = before;
    ::setenv("GAZEBO_MODEL_PATH", models_.c_str(), 1);
  }
  void TearDown() override {  // the other tests' model path back
    if (had_) {
      ::setenv("GAZEBO_MODEL_PATH", before_.c_str(), 1);
    } else {
      ::unsetenv("GAZEBO_MODEL_PATH");
    }
  }
  std::string models_, before_;
  bool had_ = false;
};

TEST_F(IncludedModels, AModelThatIncludesItselfOrItsIncluderIsRefusedNamingTheChain) {
  writeModel(models_, "selfie", include(models_ + "/selfie", "2 0 0 0 0 0"));  // absolute path
  std::string e = worldRefusal("a model that includes itself",
                               sdfWorld("selfie.world", include("model://selfie", "0 0 0 0 0 0")));
  EXPECT_NE(e.find("selfie.world:4: <include> of model://selfie"), std::string::npos) << e;
  EXPECT_NE(e.find("(a model cannot include itself)"), std::string::npos) << e;
  writeModel(models_, "ping", include("model://pong", "2 0 0 0 0 0"));
  writeModel(models_, "pong", include("model://ping", "2 0 0 0 0 0"));
  e = worldRefusal("two models that include each other",
                   sdfWorld("ping.world", include("model://ping", "0 0 0 0 0 0")));
  EXPECT_NE(e.find("<include> of model://pong"), std::string::npos) << e;
  EXPECT_NE(e.find("ping/model.sdf"), std::string::npos) << e;
  EXPECT_NE(e.find("(a model cannot include itself)"), std::string::npos) << e;
}

TEST_F(IncludedModels, AModelIncludedByAnIncludedModelKeepsItsShapes) {
  writeModel(models_, "inner", "");
  writeModel(models_, "outer", include("model://inner", "2 0 0 0 0 0"));
  const GazeboWorld world =
      loadGazeboWorld(sdfWorld("nested.world", include("model://outer", "0 0 0.5 0 0 0")));
  ASSERT_EQ(world.solids.size(), 2u);  // the outer box and the inner one
  EXPECT_NEAR(world.solids[1].upright->center.x(), 2.0, 1e-9) << world.solids[1].name;
}

}  // namespace
}  // namespace jetbot_rl
