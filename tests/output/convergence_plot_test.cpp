/// @file
/// plot_convergence writes an SVG through PLplot without a display and without console output.

#include "output/convergence_plot.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace iga {
namespace {

namespace fs = std::filesystem;

/// PLplot's SVG driver writes every character as a numeric reference (&#x4c;): turn them back
/// into UTF-8 so the test can search for text.
std::string decode_character_references(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const std::size_t end = s.find(';', i);
    if (s.compare(i, 3, "&#x") == 0 && end != std::string::npos) {
      const unsigned long c = std::stoul(s.substr(i + 3, end - i - 3), nullptr, 16);
      if (c < 0x80) {
        out += char(c);
      } else if (c < 0x800) {
        out += char(0xC0 | (c >> 6)), out += char(0x80 | (c & 0x3F));
      } else {
        out += char(0xE0 | (c >> 12)), out += char(0x80 | ((c >> 6) & 0x3F)), out += char(0x80 | (c & 0x3F));
      }
      i = end + 1;
    } else {
      out += s[i++];
    }
  }
  return out;
}

std::string read_file(const std::string& file) {
  std::ifstream in(file);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Four levels of a degree-2 study: e_L2 = h^3, |e|_H1 = 2 h^2, |e|_H2 = 5 h.
std::vector<LevelResult> synthetic_rows(bool with_h1_h2) {
  std::vector<LevelResult> rows;
  for (int level = 0; level < 4; ++level) {
    LevelResult r;
    r.level = level;
    r.h = std::pow(0.5, level + 2);
    r.dofs = static_cast<int>(std::pow(1 / r.h + 2, 2));
    r.free_dofs = r.dofs / 2;
    r.l2 = std::pow(r.h, 3);
    if (with_h1_h2) {
      r.h1 = 2 * r.h * r.h;
      r.h2 = 5 * r.h;
    }
    rows.push_back(r);
  }
  return rows;
}

class ConvergencePlotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("iga_plot_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!std::getenv("IGA_KEEP_TEST_OUTPUT")) fs::remove_all(dir_);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ConvergencePlotTest, WritesSvgWithLegendAndTitleSilently) {
  const std::string file = path("convergence.svg");
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  plot_convergence(synthetic_rows(true), OptimalRates{3, 2, 1}, "Poisson Q2 & friends", file);
  const std::string out = testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");

  ASSERT_TRUE(fs::exists(file));
  EXPECT_GT(fs::file_size(file), 1000u);
  const std::string svg = read_file(file);
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u) << svg.substr(0, 80);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);  // the stream was closed
  const std::string text = decode_character_references(svg);
  // Labels: ||e||_L2 and the seminorms |e|_H1, |e|_H2 (PLplot writes the subscript as its own span).
  for (const char* label : {"||e||", "|e|", ">L2<", ">H1<", ">H2<", "Poisson Q2 & friends",
                            "degrees of freedom", "time to solution"})
    EXPECT_NE(text.find(label), std::string::npos) << label;
  EXPECT_EQ(text.find("H1 error"), std::string::npos);  // no seminorm labelled as if it were the norm
  // Both panels carry the L2 series in their legends.
  std::size_t count = 0;
  for (std::size_t at = text.find("||e||"); at != std::string::npos; at = text.find("||e||", at + 1)) ++count;
  EXPECT_EQ(count, 2u);
}

TEST_F(ConvergencePlotTest, OnlyTheSeriesThatHaveErrorsAreDrawn) {
  const std::string file = path("l2_only.svg");
  plot_convergence(synthetic_rows(false), OptimalRates{2, 1, 0}, "L2 only", file);
  const std::string text = decode_character_references(read_file(file));
  EXPECT_NE(text.find(">L2<"), std::string::npos);
  EXPECT_EQ(text.find(">H1<"), std::string::npos);
  EXPECT_EQ(text.find(">H2<"), std::string::npos);
}

TEST_F(ConvergencePlotTest, SingleLevelStillPlots) {
  // One point gives a zero-width data range; the plot window must still be valid.
  auto rows = synthetic_rows(true);
  rows.resize(1);
  const std::string file = path("one.svg");
  testing::internal::CaptureStderr();
  plot_convergence(rows, OptimalRates{3, 2, 1}, "one level", file);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_GT(fs::file_size(file), 1000u);
}

TEST_F(ConvergencePlotTest, NoErrorsMeansNoFile) {
  auto rows = synthetic_rows(false);
  for (auto& r : rows) r.l2.reset();
  const std::string file = path("none.svg");
  EXPECT_NO_THROW(plot_convergence(rows, OptimalRates{3, 2, 1}, "none", file));
  EXPECT_FALSE(fs::exists(file));
  EXPECT_NO_THROW(plot_convergence({}, OptimalRates{3, 2, 1}, "empty", file));
  EXPECT_FALSE(fs::exists(file));
}

TEST_F(ConvergencePlotTest, UnwritablePathThrowsInsteadOfExiting) {
  // PLplot itself would end the process here; the writer must check first.
  EXPECT_THROW(plot_convergence(synthetic_rows(true), OptimalRates{3, 2, 1}, "x", path("missing/dir/plot.svg")), std::runtime_error);
}

}  // namespace
}  // namespace iga
