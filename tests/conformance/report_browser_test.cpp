// report_browser_test.cpp — report.html in a real browser: the real vgc
// binary certifies a node with two seeded faults (a subdivision that
// ignores creases, a ?classify that misses the boundary), headless Chromium
// renders the run's report.html from disk to PNG, and the picture is
// decoded (libpng) and checked: each mesh picture is there and not blank
// (many colours, much drawn on its background) and shows the highlight
// colour; and the browser logged no console message (the page has no
// script, and its Content-Security-Policy makes any attempt to load
// something from outside a console error).
//
// Skipped, saying so, only when no chromium is installed (./vgc test
// installs it with the other Debian packages).
#include <gtest/gtest.h>
#include <png.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "exec_implementation.h"  // shell_quote

namespace vgc {
namespace {

namespace fs = std::filesystem;

struct Rgb {
  int r, g, b;
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};
constexpr Rgb kCanvas{0xfb, 0xfb, 0xf4};     // svg_mesh.h kCanvasColour
constexpr Rgb kHighlight{0xe6, 0x00, 0x7e};  // svg_mesh.h kHighlightColour

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  Rgb at(int x, int y) const {
    const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

bool decode_png(const fs::path& file, Image* out, std::string* error) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, file.c_str())) {
    *error = image.message;
    return false;
  }
  image.format = PNG_FORMAT_RGB;
  out->width = static_cast<int>(image.width);
  out->height = static_cast<int>(image.height);
  out->rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out->rgb.data(), 0, nullptr)) {
    *error = image.message;
    png_image_free(&image);
    return false;
  }
  return true;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

// The pictures: bands of rows holding the canvas colour, top to bottom,
// each with the columns the canvas spans.
struct Band {
  int top = 0, bottom = 0, left = 0, right = 0;
};
std::vector<Band> canvas_bands(const Image& img) {
  std::vector<Band> bands;
  int gap = 1000;
  for (int y = 0; y < img.height; ++y) {
    int n = 0, left = img.width, right = -1;
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y) == kCanvas) ++n, left = std::min(left, x), right = std::max(right, x);
    if (n < 40) {
      ++gap;
      continue;
    }
    if (gap > 20 || bands.empty()) bands.push_back({y, y, left, right});
    Band& b = bands.back();
    b.bottom = y, b.left = std::min(b.left, left), b.right = std::max(b.right, right);
    gap = 0;
  }
  std::vector<Band> pictures;  // bands as tall as a picture, not a stray row of that colour
  for (const Band& b : bands)
    if (b.bottom - b.top > 100 && b.right - b.left > 100) pictures.push_back(b);
  return pictures;
}

TEST(ReportBrowser, AFailingRunsReportRendersItsMeshesWithTheFindingsHighlighted) {
  if (run("command -v chromium >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "SKIPPED: chromium is not installed, so report.html was not rendered; "
                    "`./vgc test` installs it (apt-get install chromium)";
  const fs::path dir = fs::temp_directory_path() / ("vgc_report_browser_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);

  // A failing run: two capability faults, their two clauses only.
  const std::string certify =
      "cd " + shell_quote(dir.string()) +
      " && VGC_FAULT=subdivision-ignores-creases,classify-misses-boundary " + shell_quote(VGC_BINARY) +
      " certify --impl " + shell_quote(std::string("plugin:") + VGC_FAULT_PLUGIN_REQUESTS) +
      " --clauses SUBD-CATMARK-1,MESH-CLASSIFY-1 --cases 40 --max-size 20 --seed 1 --quiet --reports rep"
      " >certify.out 2>&1";
  ASSERT_EQ(run(certify), 1) << read(dir / "certify.out");
  const fs::path page = fs::canonical(dir / "rep" / "latest") / "report.html";
  ASSERT_TRUE(fs::is_regular_file(page)) << page;

  // Headless Chromium as root in a container: no sandbox, no GPU, a
  // profile of its own, no D-Bus; console messages logged to stderr.
  const fs::path png = dir / "page.png", log = dir / "chromium.log";
  const std::string chromium =
      "cd " + shell_quote(dir.string()) + " && DBUS_SESSION_BUS_ADDRESS=disabled: timeout 120 chromium --headless "
      "--no-sandbox --disable-gpu --no-first-run --disable-extensions --disable-dev-shm-usage --hide-scrollbars "
      "--user-data-dir=" + shell_quote((dir / "profile").string()) +
      " --enable-logging=stderr --v=0 --window-size=1100,3200 --screenshot=" + shell_quote(png.string()) + " " +
      shell_quote("file://" + page.string()) + " >" + shell_quote(log.string()) + " 2>&1";
  const int rc = run(chromium);
  ASSERT_EQ(rc, 0) << "chromium failed:\n" << read(log);
  ASSERT_TRUE(fs::is_regular_file(png)) << read(log);

  // The page loaded without a console message (an error, a blocked load).
  std::istringstream lines(read(log));
  std::string line, console;
  while (std::getline(lines, line))
    if (line.find(":CONSOLE") != std::string::npos) console += line + "\n";
  EXPECT_TRUE(console.empty()) << "the browser console reported:\n" << console;

  Image img;
  std::string error;
  ASSERT_TRUE(decode_png(png, &img, &error)) << error;
  const std::vector<Band> pictures = canvas_bands(img);
  ASSERT_EQ(pictures.size(), 2u) << "expected the two mesh pictures in " << png;
  for (const Band& b : pictures) {
    SCOPED_TRACE("picture at rows " + std::to_string(b.top) + ".." + std::to_string(b.bottom));
    std::set<int> colours;
    long drawn = 0, highlight = 0, all = 0;
    for (int y = b.top; y <= b.bottom; ++y)
      for (int x = b.left; x <= b.right; ++x) {
        const Rgb c = img.at(x, y);
        ++all;
        colours.insert(c.r << 16 | c.g << 8 | c.b);
        drawn += !(c == kCanvas);
        highlight += c == kHighlight;
      }
    EXPECT_GE(colours.size(), 50u) << "too few colours: a blank picture?";
    EXPECT_GE(drawn, all / 20) << "less than 5% of the picture is drawn on";
    EXPECT_GE(highlight, 40) << "the highlight colour is (nearly) absent: nothing is highlighted";
  }
  if (!HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace vgc
