/// Images: PNG and OpenEXR directly (image_codecs.hpp), every other format
/// through OpenImageIO (loaded on first use: image_plugin.hpp); linear EXR
/// (and HDR), 8-bit sRGB for other formats.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "image_codecs.hpp"
#include "image_plugin.hpp"
#include "stratum/io/output_file.hpp"
#include "stratum/render/compare.hpp"
#include "stratum/render/render.hpp"
#include "stratum/util/error.hpp"

namespace stratum::render {

namespace {

/// The sRGB transfer curve (IEC 61966-2-1).
double srgb(double linear) {
  const double v = std::clamp(linear, 0.0, 1.0);
  return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

/// The file name's extension in lower case (".EXR" -> ".exr").
std::string lowercase_extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

}  // namespace

void write_image(const Image& image, io::OutputFile& file) {
  const std::string extension = lowercase_extension(file.path());
  check_image_path(file.argument(), file.path());
  file.prepare();
  if (!file.active()) return;  // a distributed job writes once, from rank 0
  const bool linear = extension == ".exr" || extension == ".hdr";
  std::vector<float> floats;
  std::vector<unsigned char> bytes;
  if (linear) {
    floats.assign(image.rgb.begin(), image.rgb.end());
  } else {
    bytes.resize(image.rgb.size());
    for (std::size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = static_cast<unsigned char>(std::lround(255 * srgb(image.rgb[i])));
  }
  // The staging file has the target's extension: OpenImageIO picks the format by it.
  try {
    if (extension == ".exr") image_codecs::write_exr(file.staging(), image.width, image.height, floats.data());
    else if (extension == ".png") image_codecs::write_png(file.staging(), image.width, image.height, bytes.data());
    else if (linear) image_plugin::write(file.staging(), image.width, image.height, floats.data());
    else image_plugin::write(file.staging(), image.width, image.height, bytes.data());
  } catch (const std::runtime_error& e) {
    const std::string staging = file.staging();
    file.discard();
    std::string why = e.what();  // the library's words, about the target rather than the staging file
    for (auto at = why.find(staging); !staging.empty() && at != std::string::npos;
         at = why.find(staging, at + file.path().size()))
      why.replace(at, staging.size(), file.path());
    throw invalid_argument(file.argument(), file.path(), "could not be written: " + why);
  }
  file.check_staged();
  // Read back: a file cut short (a full disk that a library did not report)
  // is caught here, and stratum never leaves an image its reader refuses.
  try {
    const Image back = read_image(file.staging());
    if (back.width != image.width || back.height != image.height)
      throw std::runtime_error("it reads back at another size");
  } catch (const std::exception& e) {
    std::string why = e.what();  // the reader's reason, without the staging file's name
    const auto reason = why.find(": ", why.find(file.staging()));
    if (why.find(file.staging()) != std::string::npos && reason != std::string::npos) why = why.substr(reason + 2);
    file.discard();
    throw invalid_argument(file.argument(), file.path(),
                           "could not be written completely (no room on the disk?): it reads back as: " + why);
  }
}

void write_image(const Image& image, const std::string& path) {
  io::OutputFile file("output", path);
  write_image(image, file);
  file.commit();
}

void check_image_path(const std::string& argument, const std::string& path) {
  bool known = image_codecs::writes(lowercase_extension(path));
  try {
    known = known || image_plugin::writable(path);
  } catch (const std::runtime_error& e) {  // the module did not load
    throw invalid_argument(argument, path, std::string("cannot be written: ") + e.what());
  }
  if (!known)
    throw invalid_argument(argument, path, "must end in an image format OpenImageIO writes (.exr, .png, ...)");
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw invalid_argument(argument, path, std::string("must be writable (") + std::strerror(errno) + ")");
}

void check_variance_path(const std::string& argument, const std::string& path) {
  const std::string extension = lowercase_extension(path);
  require(extension == ".exr", argument, path,
          "must be an OpenEXR file (.exr): variances are linear, unbounded values");
}

void write_variance_image(const Image& image, io::OutputFile& file) {
  check_variance_path(file.argument(), file.path());
  require(image.variance.size() == image.rgb.size(), file.argument(), file.path(),
          "needs the image's per-pixel variances (this image has none, e.g. a reference cached without them)");
  Image variance;
  variance.width = image.width;
  variance.height = image.height;
  variance.rgb = image.variance;
  write_image(variance, file);
}

void write_variance_image(const Image& image, const std::string& path) {
  io::OutputFile file("variance", path);
  write_variance_image(image, file);
  file.commit();
}

}  // namespace stratum::render
