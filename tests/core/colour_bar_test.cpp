// A heat map's legend PNG: it reads back as an image with the viridis low end
// below its high end and a title above the bar; a folder that does not exist
// fails with Error(IO) and success leaves no temporary file beside the PNG.
#include <gtest/gtest.h>

#include <cairo/cairo.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/colour_bar.h"
#include "core/error.h"
#include "support/temp_files.h"

namespace {

namespace fs = std::filesystem;
using fabvdb::test::TempDir;

struct Pixel {
    int r, g, b;
};

bool near(const Pixel& p, int r, int g, int b, int tolerance) {
    return std::abs(p.r - r) <= tolerance && std::abs(p.g - g) <= tolerance && std::abs(p.b - b) <= tolerance;
}

TEST(ColourBar, LowEndBelowHighEndWithTitleAbove) {
    TempDir folder;
    const std::string path = (fs::path(folder.path()) / "legend.png").string();
    fabvdb::write_colour_bar_png(path, "Wall thickness", 0.5, 4.0, "mm");
    ASSERT_TRUE(fs::exists(path));
    // Only the PNG is left in the folder: no temporary file.
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(fs::path(folder.path()))) ++entries;
    EXPECT_EQ(entries, 1);

    cairo_surface_t* image = cairo_image_surface_create_from_png(path.c_str());
    ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
    const int width = cairo_image_surface_get_width(image), height = cairo_image_surface_get_height(image);
    const int stride = cairo_image_surface_get_stride(image);
    const unsigned char* data = cairo_image_surface_get_data(image);
    ASSERT_GT(width, 0);
    ASSERT_GT(height, 0);
    auto pixel = [&](int x, int y) {
        const uint32_t word = *reinterpret_cast<const uint32_t*>(data + size_t(y) * size_t(stride) + size_t(x) * 4);
        return Pixel{int((word >> 16) & 0xff), int((word >> 8) & 0xff), int(word & 0xff)};
    };
    // Rows holding viridis' dark purple end (#440154) and its yellow end
    // (#fde725), and the topmost row with a near-black pixel (text).
    int low_row = -1, high_row = -1, top_dark_row = -1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Pixel p = pixel(x, y);
            if (near(p, 0x44, 0x01, 0x54, 4)) low_row = y;                         // the last one found
            if (near(p, 0xfd, 0xe7, 0x25, 4) && high_row < 0) high_row = y;        // the first one found
            if (p.r < 60 && p.g < 60 && p.b < 60 && top_dark_row < 0) top_dark_row = y;
        }
    cairo_surface_destroy(image);
    ASSERT_GE(low_row, 0) << "no low-end colour in the bar";
    ASSERT_GE(high_row, 0) << "no high-end colour in the bar";
    EXPECT_LT(high_row, low_row) << "high values belong at the top";
    ASSERT_GE(top_dark_row, 0) << "no text";
    EXPECT_LT(top_dark_row, high_row) << "the title is above the bar";
}

TEST(ColourBar, MissingFolderIsAnIoError) {
    TempDir folder;
    const fs::path path = fs::path(folder.path()) / "missing" / "legend.png";
    try {
        fabvdb::write_colour_bar_png(path.string(), "Draft", 0.0, 90.0, "deg");
        FAIL() << "no error";
    } catch (const fabvdb::Error& error) {
        EXPECT_EQ(error.status(), FABVDB_ERR_IO);
    }
    EXPECT_FALSE(fs::exists(path));
    EXPECT_TRUE(fs::is_empty(fs::path(folder.path())));
}

}  // namespace
