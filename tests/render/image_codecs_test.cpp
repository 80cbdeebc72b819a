// PNG and OpenEXR read and written directly (src/render/image_codecs.cpp),
// checked against OpenImageIO (the module every other format goes through):
// each reads what the other writes to the same values, and every layout the
// direct readers leave alone still reaches OpenImageIO.
#include "render/image_codecs.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "render/image_plugin.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"

namespace {

namespace fs = std::filesystem;
namespace codecs = stratum::render::image_codecs;
namespace plugin = stratum::render::image_plugin;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("stratum_image_codecs_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

/// Values that are not representable in half precision, negative and large
/// too: an EXR must keep them as 32-bit floats.
std::vector<float> float_pixels(int width, int height) {
  std::vector<float> values(std::size_t(width) * height * 3);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.1234567f * float(i) - 1.5f + 1e-7f * float(i * i);
  return values;
}

std::vector<unsigned char> byte_pixels(int width, int height) {
  std::vector<unsigned char> values(std::size_t(width) * height * 3);
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<unsigned char>((i * 37 + i / 7) % 256);
  return values;
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A PNG in another layout than the one stratum writes (libpng's simple API).
void write_png_as(const fs::path& path, png_uint_32 format, int width, int height) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = format;
  std::vector<std::uint16_t> buffer(PNG_IMAGE_SIZE(image) / 2 + 1, 0x4321);
  ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, buffer.data(), 0, nullptr), 0) << image.message;
}

/// An EXR with the given channels over a data window that starts at (x0, y0).
void write_exr_as(const fs::path& path, const std::vector<std::string>& channels, int x0, int y0) {
  const int width = 4, height = 3;
  Imf::Header header(Imath::Box2i({x0, y0}, {x0 + width - 1, y0 + height - 1}),
                     Imath::Box2i({x0, y0}, {x0 + width - 1, y0 + height - 1}));
  for (const std::string& name : channels) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  std::vector<float> values(std::size_t(width) * height, 0.5f);
  Imf::FrameBuffer frame;
  for (const std::string& name : channels)
    frame.insert(name, Imf::Slice(Imf::FLOAT,
                                  reinterpret_cast<char*>(values.data()) -
                                      (std::ptrdiff_t(x0) + std::ptrdiff_t(y0) * width) * sizeof(float),
                                  sizeof(float), sizeof(float) * width));
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(height);
}

}  // namespace

TEST(ImageCodecs, ExrWrittenHereReadsTheSameThroughOpenImageIOAndBack) {
  const int width = 7, height = 5;
  const std::vector<float> values = float_pixels(width, height);
  const std::string ours = scratch("ours.exr").string();
  codecs::write_exr(ours, width, height, values.data());
  const plugin::Pixels oiio = plugin::read(ours, "image");
  EXPECT_EQ(oiio.width, width);
  EXPECT_EQ(oiio.height, height);
  EXPECT_EQ(oiio.channels, 3);
  EXPECT_EQ(oiio.values, values);
  const std::string theirs = scratch("theirs.exr").string();
  plugin::write(theirs, width, height, values.data());
  const auto back = codecs::read(theirs);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->width, width);
  EXPECT_EQ(back->height, height);
  EXPECT_EQ(back->values, values);
}

TEST(ImageCodecs, PngWrittenHereReadsTheSameThroughOpenImageIOAndBack) {
  const int width = 9, height = 4;
  const std::vector<unsigned char> bytes = byte_pixels(width, height);
  std::vector<float> expected(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) expected[i] = float(bytes[i]) / 255.0f;
  const std::string ours = scratch("ours.png").string();
  codecs::write_png(ours, width, height, bytes.data());
  const plugin::Pixels oiio = plugin::read(ours, "image");
  EXPECT_EQ(oiio.width, width);
  EXPECT_EQ(oiio.channels, 3);
  ASSERT_EQ(oiio.values.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(oiio.values[i], expected[i]) << i;
  const std::string theirs = scratch("theirs.png").string();
  plugin::write(theirs, width, height, bytes.data());
  const auto back = codecs::read(theirs);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->height, height);
  EXPECT_EQ(back->values, expected);
}

TEST(ImageCodecs, TheSameImageGivesTheSameBytes) {
  // No time stamp in the header: a render written by rank 0 of an MPI job
  // and by one process are the same file.
  const std::vector<float> values = float_pixels(6, 6);
  codecs::write_exr(scratch("a.exr").string(), 6, 6, values.data());
  codecs::write_exr(scratch("b.exr").string(), 6, 6, values.data());
  EXPECT_EQ(bytes_of(scratch("a.exr")), bytes_of(scratch("b.exr")));
}

TEST(ImageCodecs, LeavesOtherLayoutsToOpenImageIO) {
  write_png_as(scratch("rgba.png"), PNG_FORMAT_RGBA, 3, 2);
  write_png_as(scratch("gray.png"), PNG_FORMAT_GRAY, 3, 2);
  write_png_as(scratch("sixteen.png"), PNG_FORMAT_LINEAR_RGB, 3, 2);
  write_exr_as(scratch("luminance.exr"), {"Y"}, 0, 0);
  write_exr_as(scratch("offset.exr"), {"R", "G", "B"}, 2, 1);
  write_exr_as(scratch("extra.exr"), {"R", "G", "B", "Z"}, 0, 0);
  for (const char* name : {"rgba.png", "gray.png", "sixteen.png", "luminance.exr", "offset.exr", "extra.exr"})
    EXPECT_FALSE(codecs::read(scratch(name).string()).has_value()) << name;
  // ...and OpenImageIO still reads them, or refuses them as it did.
  const stratum::render::Image rgba = stratum::render::read_image(scratch("rgba.png").string());
  EXPECT_EQ(rgba.width, 3);
  const stratum::render::Image sixteen = stratum::render::read_image(scratch("sixteen.png").string());
  EXPECT_NEAR(sixteen.rgb[0], 0x4321 / 65535.0, 1e-6);  // 16 bits kept, the stored code / 65535
  EXPECT_EQ(stratum::render::read_image(scratch("offset.exr").string()).width, 4);
  EXPECT_THROW(stratum::render::read_image(scratch("gray.png").string()), stratum::invalid_argument);
  EXPECT_THROW(stratum::render::read_image(scratch("luminance.exr").string()), stratum::invalid_argument);
  // A layout it takes: R, G, B, A, in that order whatever the file's.
  write_exr_as(scratch("alpha.exr"), {"A", "B", "G", "R"}, 0, 0);
  const auto alpha = codecs::read(scratch("alpha.exr").string());
  ASSERT_TRUE(alpha.has_value());
  EXPECT_EQ(alpha->channels, 4);
  EXPECT_EQ(alpha->values, plugin::read(scratch("alpha.exr").string(), "image").values);
}

TEST(ImageCodecs, DamagedOrAbsentFilesGoToOpenImageIOForItsMessage) {
  const std::vector<float> values = float_pixels(16, 16);
  codecs::write_exr(scratch("whole.exr").string(), 16, 16, values.data());
  const std::string whole = bytes_of(scratch("whole.exr"));
  std::ofstream(scratch("cut.exr"), std::ios::binary) << whole.substr(0, whole.size() / 2);
  std::ofstream(scratch("text.png"), std::ios::binary) << "not an image\n";
  for (const char* name : {"cut.exr", "text.png", "absent.exr"})
    EXPECT_FALSE(codecs::read(scratch(name).string()).has_value()) << name;
  EXPECT_THROW(stratum::render::read_image(scratch("cut.exr").string()), stratum::invalid_argument);
  EXPECT_THROW(codecs::write_png(scratch("empty.png").string(), 0, 4, nullptr), std::runtime_error);
  EXPECT_THROW(codecs::write_exr(scratch("no-folder/x.exr").string(), 2, 2, values.data()), std::runtime_error);
}
