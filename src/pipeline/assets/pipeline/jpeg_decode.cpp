// pipeline/jpeg_decode.cpp — JPEG through libjpeg-turbo (Debian's libjpeg62-turbo-dev). stb_image's
// JPEG decoder (libstb-dev 0.0~git20220908) was dropped for it: fuzz/parse_inputs found a write one
// past its Huffman size table (stb_image.h:1990, stbi__build_huffman) on a malformed DHT segment.
#include <csetjmp>
#include <cstdio>  // jpeglib.h needs FILE and size_t declared first
#include <stdexcept>

#include <jpeglib.h>

#include "pipeline/image_io.hpp"

namespace gsdot3::pipeline {

namespace {

struct jpeg_failure {
  jpeg_error_mgr mgr;  // first: libjpeg passes &mgr as the whole
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr c) {
  auto* f = reinterpret_cast<jpeg_failure*>(c->err);
  (*c->err->format_message)(c, f->message);
  std::longjmp(f->jump, 1);
}
void on_message(j_common_ptr, int) {}  // warnings (corrupt data it recovers from) stay quiet

}  // namespace

image decode_jpeg(const std::uint8_t* data, std::size_t size, const std::string& name) {
  jpeg_decompress_struct info{};
  jpeg_failure failure{};
  info.err = jpeg_std_error(&failure.mgr);
  failure.mgr.error_exit = on_error;
  failure.mgr.emit_message = on_message;
  // Everything longjmp may skip over is constructed before setjmp, so its destructor still runs.
  image img;
  volatile bool too_large = false;
  if (setjmp(failure.jump)) {
    jpeg_destroy_decompress(&info);
    throw std::runtime_error(name + ": malformed JPEG data (" + failure.message + ")");
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, data, static_cast<unsigned long>(size));
  jpeg_read_header(&info, TRUE);
  too_large = info.image_width > static_cast<JDIMENSION>(max_image_side) ||
              info.image_height > static_cast<JDIMENSION>(max_image_side) ||
              static_cast<long long>(info.image_width) * info.image_height > max_image_pixels;
  if (!too_large) {
    info.out_color_space = info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&info);
    img = {static_cast<int>(info.output_width), static_cast<int>(info.output_height), info.output_components,
           std::vector<std::uint8_t>(static_cast<std::size_t>(info.output_width) * info.output_height *
                                     static_cast<std::size_t>(info.output_components))};
    const std::size_t stride =
        static_cast<std::size_t>(info.output_width) * static_cast<std::size_t>(info.output_components);
    while (info.output_scanline < info.output_height) {
      JSAMPROW row = img.data.data() + stride * info.output_scanline;
      jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
  }
  const long long w = info.image_width, h = info.image_height;
  jpeg_destroy_decompress(&info);
  if (too_large) check_image_size(w, h, name);
  return img;
}

}  // namespace gsdot3::pipeline
