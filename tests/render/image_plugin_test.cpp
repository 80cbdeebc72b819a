// Image files through the OpenImageIO module loaded on first use
// (src/render/image_plugin.cpp, oiio_plugin/oiio_plugin.cpp).
#include "render/image_plugin.hpp"

#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "stratum/render/compare.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"

namespace {

namespace fs = std::filesystem;
using stratum::render::Image;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("stratum_image_plugin_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

Image gradient(int width, int height) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(std::size_t(width) * height * 3);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = 0.013 * double(i) + 0.25 * double(i % 3);
  return image;
}

std::string message_of(const std::vector<std::string>& paths) {
  try {
    stratum::render::image_plugin::load_first(paths);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ImagePlugin, LoadsThisBuildsModuleFoundFromTheProgramsOwnPath) {
  if (std::getenv("STRATUM_OIIO_PLUGIN")) GTEST_SKIP() << "STRATUM_OIIO_PLUGIN is set: that module comes first";
  const std::string path = stratum::render::image_plugin::module_path();
  EXPECT_TRUE(fs::equivalent(path, STRATUM_OIIO_PLUGIN_BUILD_PATH)) << path;
  // The first candidate comes from /proc/self/exe (this test program, in
  // build/<preset>/bin/), not from argv[0], and is this build's module.
  const std::vector<std::string> candidates = stratum::render::image_plugin::candidate_paths();
  ASSERT_GE(candidates.size(), 3u);
  EXPECT_TRUE(fs::path(candidates[0]).is_absolute()) << candidates[0];
  EXPECT_EQ(path, candidates[0]);
  EXPECT_TRUE(fs::equivalent(candidates[0], STRATUM_OIIO_PLUGIN_BUILD_PATH)) << candidates[0];
}

TEST(ImagePlugin, PassesOverAbsentAndForeignFilesAndSaysWhy) {
  const std::string absent = scratch("absent.so").string();
  const fs::path text = scratch("not-a-library.so");
  std::ofstream(text) << "not an ELF file\n";
  Dl_info libc{};
  ASSERT_NE(dladdr(reinterpret_cast<void*>(&std::fopen), &libc), 0);
  const std::string message = message_of({absent, text.string(), libc.dli_fname});
  EXPECT_NE(message.find(absent + " (absent)"), std::string::npos) << message;
  EXPECT_NE(message.find(text.string() + " ("), std::string::npos) << message;
  EXPECT_NE(message.find(std::string(libc.dli_fname) + " (not stratum's"), std::string::npos) << message;
  EXPECT_NE(message.find("STRATUM_OIIO_PLUGIN"), std::string::npos) << message;
  // The first usable candidate wins.
  const std::string module = stratum::render::image_plugin::module_path();
  EXPECT_EQ(stratum::render::image_plugin::load_first({absent, text.string(), module}), module);
}

TEST(ImagePlugin, ExrRoundTripIsExactInFloat) {
  const Image image = gradient(5, 3);
  const std::string path = scratch("round.exr").string();
  stratum::render::write_image(image, path);
  const Image back = stratum::render::read_image(path);
  EXPECT_EQ(back.width, 5);
  EXPECT_EQ(back.height, 3);
  ASSERT_EQ(back.rgb.size(), image.rgb.size());
  for (std::size_t i = 0; i < image.rgb.size(); ++i) EXPECT_EQ(back.rgb[i], double(float(image.rgb[i]))) << i;
}

TEST(ImagePlugin, PngHoldsTheSrgbEncodingInEightBits) {
  Image image = gradient(4, 2);
  for (auto& v : image.rgb) v = std::fmod(v, 1.0);
  const std::string path = scratch("round.png").string();
  stratum::render::write_image(image, path);
  const Image back = stratum::render::read_image(path);  // the 8-bit codes / 255, not linearized
  ASSERT_EQ(back.rgb.size(), image.rgb.size());
  for (std::size_t i = 0; i < image.rgb.size(); ++i) {
    const double v = image.rgb[i];
    const double srgb = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    EXPECT_NEAR(back.rgb[i], srgb, 0.5 / 255 + 1e-6) << i;
  }
}

TEST(ImagePlugin, RefusesUnknownFormatsAndUnreadableFilesWithoutLeavingFiles) {
  const Image image = gradient(2, 2);
  const fs::path odd = scratch("image.notaformat");
  EXPECT_THROW(stratum::render::write_image(image, odd.string()), stratum::invalid_argument);
  EXPECT_FALSE(fs::exists(odd));
  for (const auto& entry : fs::directory_iterator(odd.parent_path()))
    EXPECT_NE(entry.path().extension(), ".notaformat") << entry.path();
  EXPECT_THROW(stratum::render::read_image(scratch("absent.exr").string()), stratum::invalid_argument);
  const fs::path text = scratch("text.exr");
  std::ofstream(text) << "not an image\n";
  EXPECT_THROW(stratum::render::read_image(text.string()), stratum::invalid_argument);
}

TEST(ImagePlugin, AFailedWriteRemovesItsTemporaryFile) {
  // An empty image passes the path checks, then OpenImageIO refuses it
  // after the temporary file exists: write_image must remove that file.
  Image empty;
  const fs::path target = scratch("empty-dir") / "empty.png";
  fs::create_directories(target.parent_path());
  try {
    stratum::render::write_image(empty, target.string());
    ADD_FAILURE() << "an empty image was written";
  } catch (const stratum::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("output"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(target.parent_path()));
}

TEST(ImagePlugin, CheckImagePathNamesTheArgumentBeforeAnyWork) {
  const auto message = [](const std::string& path) -> std::string {
    try {
      stratum::render::check_image_path("exr", path);
    } catch (const stratum::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message(scratch("fine.exr").string()), "");
  EXPECT_EQ(message(scratch("fine.png").string()), "");
  const std::string unknown = message(scratch("x.notaformat").string());
  EXPECT_NE(unknown.find("exr"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("image format"), std::string::npos) << unknown;
  const std::string no_folder = message(scratch("no/such/folder/x.png").string());
  EXPECT_NE(no_folder.find("must be writable"), std::string::npos) << no_folder;
  EXPECT_FALSE(fs::exists(scratch("fine.exr")));
}
