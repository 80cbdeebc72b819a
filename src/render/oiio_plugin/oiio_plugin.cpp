/// OpenImageIO behind a small C interface, built as a module that stratum
/// loads (dlopen) on its first image read or write (src/render/image_plugin.cpp):
/// Debian's OpenImageIO pulls in about 260 shared libraries, whose loading
/// and relocation cost every process that links them about 0.2 s of CPU at
/// start — every `stratum` command and every `import stratum`, images or not.
#include <OpenImageIO/imageio.h>

#include <cstddef>
#include <cstring>
#include <exception>
#include <string>

namespace {

void copy_error(const std::string& message, char* error, std::size_t error_size) {
  if (error_size == 0) return;
  std::strncpy(error, message.c_str(), error_size - 1);
  error[error_size - 1] = '\0';
}

}  // namespace

extern "C" {

/// The interface's version: the loader refuses a module of another.
int stratum_oiio_abi_version() { return 1; }

/// 1 when OpenImageIO has a writer for the file's extension, else 0.
int stratum_oiio_writable(const char* path) {
  try {
    return OIIO::ImageOutput::create(path) != nullptr;
  } catch (...) {
    return 0;
  }
}

/// Writes width × height RGB pixels, float (as_float) or 8-bit, to `path`
/// (format by its extension). 0: written; else the message in `error`.
int stratum_oiio_write(const char* path, int width, int height, int as_float, const void* pixels, char* error,
                       std::size_t error_size) try {
  auto output = OIIO::ImageOutput::create(path);
  if (!output) {
    copy_error("no OpenImageIO writer for this file name", error, error_size);
    return 1;
  }
  const OIIO::TypeDesc type = as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  const OIIO::ImageSpec spec(width, height, 3, type);
  if (output->open(path, spec) && output->write_image(type, pixels) && output->close()) return 0;
  copy_error(output->geterror(), error, error_size);
  return 2;
} catch (const std::exception& e) {  // no exception crosses the C interface
  copy_error(e.what(), error, error_size);
  return 2;
} catch (...) {
  copy_error("unknown exception", error, error_size);
  return 2;
}

/// Reads the image at `path` as float: `allocate(context, width, height,
/// channels)` returns room for width·height·channels floats (or null to
/// refuse the image). 0: read; 1: not readable; 2: refused (a volume, or by
/// allocate); 3: read failed; messages in `error`.
int stratum_oiio_read(const char* path, void* context, float* (*allocate)(void*, int, int, int), char* error,
                      std::size_t error_size) try {
  auto input = OIIO::ImageInput::open(path);
  if (!input) {
    copy_error(OIIO::geterror(), error, error_size);
    return 1;
  }
  const OIIO::ImageSpec& spec = input->spec();
  const std::string shape = std::to_string(spec.width) + "x" + std::to_string(spec.height) + "x" +
                            std::to_string(spec.depth) + " pixels, " + std::to_string(spec.nchannels) + " channels";
  if (spec.depth != 1) {  // a volume: width·height·depth values would not fit what allocate gives
    copy_error("it has " + shape, error, error_size);
    return 2;
  }
  float* pixels = allocate(context, spec.width, spec.height, spec.nchannels);
  if (!pixels) {
    copy_error("it has " + shape, error, error_size);
    return 2;
  }
  if (input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels)) return 0;
  copy_error(input->geterror(), error, error_size);
  return 3;
} catch (const std::exception& e) {
  copy_error(e.what(), error, error_size);
  return 3;
} catch (...) {
  copy_error("unknown exception", error, error_size);
  return 3;
}

}  // extern "C"
