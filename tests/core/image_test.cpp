// sRGB encoding by the formula of IEC 61966-2-1, the heat-map scale, and atomic PNG writing.
#include "raystep/render/image.h"

#include <gtest/gtest.h>
#include <stb/stb_image.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

namespace raystep {
namespace {

TEST(Image, LinearToSrgb) {
    EXPECT_EQ(linearToSrgb8(0.0), 0);
    EXPECT_EQ(linearToSrgb8(1.0), 255);
    EXPECT_EQ(linearToSrgb8(0.5), 188);  // 1.055 * 0.5^(1/2.4) - 0.055 = 0.73536 -> 187.52
    EXPECT_EQ(linearToSrgb8(0.001), 3);  // linear segment: 12.92 * 0.001 * 255 = 3.29
    EXPECT_EQ(linearToSrgb8(0.2), 124);  // 1.055 * 0.2^(1/2.4) - 0.055 = 0.48453 -> 123.56
    EXPECT_EQ(linearToSrgb8(-0.5), 0);
    EXPECT_EQ(linearToSrgb8(7.0), 255);
    EXPECT_EQ(linearToSrgb8(std::nan("")), 0);
}

TEST(Image, HeatmapScaleEndsAndStops) {
    using C = std::array<std::uint8_t, 3>;
    EXPECT_EQ(heatmapColor(0.0), (C{0, 0, 4}));
    EXPECT_EQ(heatmapColor(0.25), (C{87, 16, 110}));
    EXPECT_EQ(heatmapColor(1.0), (C{252, 255, 164}));
    EXPECT_EQ(heatmapColor(2.0), (C{252, 255, 164}));
    const auto rgb = heatmapRgb8({0, 10, 5, 10}, 2, 2);
    ASSERT_EQ(rgb.size(), 12u);
    EXPECT_EQ(rgb[0], 0);    // cost 0: darkest
    EXPECT_EQ(rgb[3], 252);  // the maximum: brightest
    EXPECT_EQ(rgb[6], 188);  // half of the maximum: the middle stop (188, 55, 84)
}

class ImageFiles : public ::testing::Test {
  protected:
    std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("raystep-image-" + std::to_string(::getpid()));
    void SetUp() override { std::filesystem::create_directories(dir); }
    void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(ImageFiles, PngRoundTrips) {
    const std::vector<std::uint8_t> rgb = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
    const std::string path = (dir / "a.png").string();
    writePng(path, rgb, 2, 2);
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(w, 2);
    EXPECT_EQ(h, 2);
    EXPECT_TRUE(std::equal(rgb.begin(), rgb.end(), data));
    stbi_image_free(data);
    // Nothing but the image is left in the folder (the temporary file was renamed).
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST_F(ImageFiles, WriteIntoMissingFolderFailsAndLeavesNothing) {
    const std::string path = (dir / "missing" / "a.png").string();
    EXPECT_THROW(writePng(path, std::vector<std::uint8_t>(3, 0), 1, 1), std::runtime_error);
    EXPECT_FALSE(std::filesystem::exists(path));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 0);
}

TEST_F(ImageFiles, AtomicWriteReplacesWholeFile) {
    const std::string path = (dir / "s.json").string();
    writeFileAtomic(path, "first version, longer than the second");
    writeFileAtomic(path, "second");
    std::ifstream in(path);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(text, "second");
}

// A set of files is written all or none: one that cannot be written leaves the others as they were,
// and no temporary behind; a FIFO is refused, not replaced by a regular file.
TEST_F(ImageFiles, FileSetIsWrittenAllOrNone) {
    const std::string a = (dir / "a.txt").string(), fifo = (dir / "pipe").string();
    writeFileAtomic(a, "old");
    EXPECT_THROW(writeFilesAtomic({{a, "new"}, {(dir / "missing" / "b.txt").string(), "b"}}),
                 std::runtime_error);
    EXPECT_THROW(writeFilesAtomic({{a, "new"}, {"/proc/b.txt", "b"}}), std::runtime_error);
    EXPECT_THROW(writeFilesAtomic({{a, "new"}, {(dir / "." / "a.txt").string(), "b"}}),
                 std::runtime_error);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THROW(writeFileAtomic(fifo, "x"), std::runtime_error);
    EXPECT_TRUE(std::filesystem::is_fifo(fifo));
    std::ifstream in(a);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), {}), "old");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 2);  // a.txt, pipe
}

}  // namespace
}  // namespace raystep
