//! A heat map's legend as a PNG (see colour_bar.h).
#include "core/colour_bar.h"

#include <cstdio>

#include <cairo.h>

#include "core/atomic_output.h"
#include "core/colour_map.h"
#include "core/error.h"

namespace fabvdb {

void write_colour_bar_png(const std::string& path, const std::string& title, double low, double high,
                          const std::string& unit) {
    constexpr int kWidth = 220, kHeight = 300, kBarX = 20, kBarTop = 40, kBarWidth = 32, kBarHeight = 240;
    cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, kWidth, kHeight);
    cairo_t* cr = cairo_create(surface);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    for (int y = 0; y < kBarHeight; ++y) {
        const auto rgb = viridis(1.0 - (y + 0.5) / kBarHeight);
        cairo_set_source_rgb(cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
        cairo_rectangle(cr, kBarX, kBarTop + y, kBarWidth, 1);
        cairo_fill(cr);
    }
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, kBarX + 0.5, kBarTop + 0.5, kBarWidth, kBarHeight);
    cairo_stroke(cr);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 13);
    cairo_move_to(cr, 8, 22);
    cairo_show_text(cr, title.c_str());
    for (int tick = 0; tick <= 4; ++tick) {
        const double y = kBarTop + kBarHeight * (1.0 - tick / 4.0) + 0.5;
        cairo_move_to(cr, kBarX + kBarWidth, y);
        cairo_line_to(cr, kBarX + kBarWidth + 6, y);
        cairo_stroke(cr);
        char label[64];
        std::snprintf(label, sizeof label, "%.3g %s", low + (high - low) * tick / 4.0, unit.c_str());
        cairo_move_to(cr, kBarX + kBarWidth + 10, y + 4);
        cairo_show_text(cr, label);
    }
    cairo_destroy(cr);
    AtomicOutput output(path);
    const cairo_status_t status = cairo_surface_write_to_png(surface, output.temp_path().c_str());
    cairo_surface_destroy(surface);
    if (status != CAIRO_STATUS_SUCCESS) throw Error(FABVDB_ERR_IO, path + ": cannot write the colour bar");
    output.commit();
}

}  // namespace fabvdb
