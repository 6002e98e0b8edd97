// The PNG plugin (CMake MODULE sphtroch_png, the one binary of the tool that links librsvg and
// cairo): an SVG in, its PNG out, at the SVG's own size in pixels on white. librsvg parses and
// draws through cairo, cairo's PNG writer encodes, as their documentation shows:
// rsvg_handle_new_from_data, the intrinsic size in pixels, rsvg_handle_render_document onto an
// ARGB32 image surface, cairo_surface_write_to_png_stream. The C ABI and its error contract:
// output_plugin.hpp.
#include "output_plugin.hpp"

#include <cairo.h>
#include <librsvg/rsvg.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace {

/// Owns what one rendering allocates.
struct Rendering {
  RsvgHandle* handle = nullptr;
  cairo_surface_t* surface = nullptr;
  cairo_t* cairo = nullptr;
  GError* error = nullptr;
  ~Rendering() {
    if (cairo) cairo_destroy(cairo);
    if (surface) cairo_surface_destroy(surface);
    if (handle) g_object_unref(handle);
    if (error) g_error_free(error);
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("PNG: librsvg could not " + what + (error ? std::string(": ") + error->message : std::string()));
  }
};

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

/// The PNG of `svg`. Throws std::runtime_error if librsvg cannot read or draw it.
std::string png_from_svg(const std::string& svg) {
  Rendering r;
  r.handle = rsvg_handle_new_from_data(reinterpret_cast<const guint8*>(svg.data()), svg.size(), &r.error);
  if (!r.handle) r.fail("read the SVG");
  gdouble width = 0, height = 0;
  if (!rsvg_handle_get_intrinsic_size_in_pixels(r.handle, &width, &height) || !(width >= 1 && height >= 1))
    r.fail("find the SVG's size in pixels");
  const int w = static_cast<int>(std::ceil(width)), h = static_cast<int>(std::ceil(height));
  r.surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
  r.cairo = cairo_create(r.surface);
  cairo_set_source_rgb(r.cairo, 1, 1, 1);  // white under the picture: no transparent holes
  cairo_paint(r.cairo);
  const RsvgRectangle viewport{0, 0, width, height};
  if (!rsvg_handle_render_document(r.handle, r.cairo, &viewport, &r.error)) r.fail("draw the SVG");
  std::string png;
  if (cairo_surface_write_to_png_stream(r.surface, append_bytes, &png) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("PNG: cairo could not encode the picture");
  return png;
}

}  // namespace

SPHTROCH_OUTPUT_PLUGIN(png_from_svg)
