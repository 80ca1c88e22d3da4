#pragma once

// Fixtures of the world tests: map files written into gtest's temporary folder.

#include <stb/stb_image_write.h>

#include <fstream>
#include <string>
#include <vector>

#include "test_util.h"

namespace jetbot_rl {
namespace test {

/// A binary PGM (P5) of `rows` (top row first, one char per pixel: '#' 0 black, '.' 254 white,
/// '?' 205 grey, or the value of a digit x 25) at `name` in the temporary folder; its path.
inline std::string writePgm(const std::string& name, const std::vector<std::string>& rows) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << rows.at(0).size() << " " << rows.size() << "\n255\n";
  for (const std::string& row : rows) {
    for (char c : row) {
      const unsigned char v = c == '#' ? 0 : c == '.' ? 254 : c == '?' ? 205 : (c - '0') * 25;
      out.put(static_cast<char>(v));
    }
  }
  return path;
}

/// An RGBA PNG of `pixels` (w x h, top row first, 4 bytes each); its path.
inline std::string writePng(const std::string& name, int w, int h,
                            const std::vector<unsigned char>& pixels) {
  const std::string path = ::testing::TempDir() + name;
  stbi_write_png(path.c_str(), w, h, 4, pixels.data(), w * 4);
  return path;
}

/// A map YAML for `image` (a path or a name beside it) with the given fields; its path.
inline std::string writeMapYaml(const std::string& name, const std::string& image,
                                const std::string& fields =
                                    "resolution: 0.1\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                    "occupied_thresh: 0.65\nfree_thresh: 0.196\n") {
  return writeTempFile(name, "image: " + image + "\n" + fields);
}

}  // namespace test
}  // namespace jetbot_rl
