#include "image_codecs.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfTestFile.h>
#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <exception>
#include <memory>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace stratum::render::image_codecs {

namespace {

/// Images wider or taller than this, or with more pixels, are left to
/// OpenImageIO (a damaged header must not make us allocate gigabytes).
constexpr std::size_t max_pixels = std::size_t(1) << 28;

void require_pixels(int width, int height) {
  if (width < 1 || height < 1) throw std::runtime_error("an image needs at least one pixel");
}

/// libpng reports errors by calling this, which must not return.
[[noreturn]] void png_fail(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void png_quiet(png_structp, png_const_charp) {}

/// What read_png fills. It lives on the heap, made before setjmp: a longjmp
/// from libpng leaves no automatic object changed after setjmp (whose value
/// would be indeterminate) and skips no destructor.
struct PngRead {
  image_plugin::Pixels pixels;
  std::vector<unsigned char> bytes;
  std::vector<png_bytep> rows;
  bool read = false;
};

/// The pixels of an 8-bit RGB PNG without transparency, else nullopt.
std::optional<image_plugin::Pixels> read_png(std::FILE* file) {
  const auto state = std::make_unique<PngRead>();
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, png_fail, png_quiet);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (info && setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, file);
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info), height = png_get_image_height(png, info);
    if (png_get_bit_depth(png, info) == 8 && png_get_color_type(png, info) == PNG_COLOR_TYPE_RGB &&
        !png_get_valid(png, info, PNG_INFO_tRNS) && std::size_t(width) * height <= max_pixels) {
      png_set_interlace_handling(png);
      png_read_update_info(png, info);
      state->bytes.resize(std::size_t(width) * height * 3);
      state->rows.resize(height);
      for (png_uint_32 y = 0; y < height; ++y) state->rows[y] = state->bytes.data() + std::size_t(y) * width * 3;
      png_read_image(png, state->rows.data());
      png_read_end(png, nullptr);
      state->pixels.width = int(width), state->pixels.height = int(height), state->pixels.channels = 3;
      state->read = true;
    }
  }
  png_destroy_read_struct(&png, &info, nullptr);
  if (!state->read) return std::nullopt;
  image_plugin::Pixels& pixels = state->pixels;
  pixels.values.resize(state->bytes.size());
  for (std::size_t i = 0; i < state->bytes.size(); ++i) pixels.values[i] = float(state->bytes[i]) / 255.0f;
  return std::move(pixels);
}

/// The pixels of a single-part OpenEXR holding R, G, B (and maybe A) over its
/// whole display window from (0, 0), in that channel order (OpenImageIO's).
std::optional<image_plugin::Pixels> read_exr(const std::string& path) try {
  bool tiled = false, deep = false, multipart = false;
  if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multipart) || deep || multipart) return std::nullopt;
  Imf::InputFile file(path.c_str());
  const Imf::Header& header = file.header();
  const Imath::Box2i window = header.dataWindow();
  if (window != header.displayWindow() || window.min.x != 0 || window.min.y != 0 || !file.isComplete())
    return std::nullopt;
  std::set<std::string> names;
  for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel) {
    if (channel.channel().xSampling != 1 || channel.channel().ySampling != 1) return std::nullopt;
    names.insert(channel.name());
  }
  const bool alpha = names.count("A") != 0;
  if (names != std::set<std::string>{"R", "G", "B"} && names != std::set<std::string>{"A", "B", "G", "R"})
    return std::nullopt;
  image_plugin::Pixels pixels;
  pixels.width = window.max.x + 1, pixels.height = window.max.y + 1, pixels.channels = alpha ? 4 : 3;
  const std::size_t width = std::size_t(pixels.width), count = width * std::size_t(pixels.height);
  if (count > max_pixels) return std::nullopt;
  pixels.values.resize(count * std::size_t(pixels.channels));
  Imf::FrameBuffer frame;
  const char* order[] = {"R", "G", "B", "A"};
  for (int c = 0; c < pixels.channels; ++c) {
    const std::size_t step = sizeof(float) * std::size_t(pixels.channels);
    frame.insert(order[c],
                 Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.values.data() + c), step, step * width));
  }
  file.setFrameBuffer(frame);
  file.readPixels(0, window.max.y);
  return pixels;
} catch (const std::exception&) {  // damaged or cut short: OpenImageIO says why
  return std::nullopt;
}

}  // namespace

bool writes(const std::string& extension) { return extension == ".png" || extension == ".exr"; }

void write_png(const std::string& path, int width, int height, const unsigned char* rgb) {
  require_pixels(width, height);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(width);
  image.height = png_uint_32(height);
  image.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&image, path.c_str(), 0, rgb, 0, nullptr))
    throw std::runtime_error(std::string("libpng: ") + image.message);
}

void write_exr(const std::string& path, int width, int height, const float* rgb) {
  require_pixels(width, height);
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    const char* names[] = {"R", "G", "B"};
    for (const char* name : names) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    Imf::OutputFile file(path.c_str(), header);
    Imf::FrameBuffer frame;
    const std::size_t step = 3 * sizeof(float);
    for (int c = 0; c < 3; ++c)
      frame.insert(names[c], Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(rgb + c)), step,
                                        step * std::size_t(width)));
    file.setFrameBuffer(frame);
    file.writePixels(height);
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("OpenEXR: ") + e.what());
  }
}

std::optional<image_plugin::Pixels> read(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::nullopt;
  unsigned char signature[8] = {};
  const bool png =
      std::fread(signature, 1, sizeof signature, file) == sizeof signature && png_sig_cmp(signature, 0, 8) == 0;
  std::optional<image_plugin::Pixels> pixels;
  if (png) {
    std::rewind(file);  // libpng reads the signature again
    pixels = read_png(file);
  }
  std::fclose(file);
  return png ? std::move(pixels) : read_exr(path);
}

}  // namespace stratum::render::image_codecs
