#include "penshape/render/progress_bar.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace penshape::render {
namespace {

TEST(ProgressBar, LineShowsBarCountTimeAndEstimate) {
  using std::chrono::duration;
  EXPECT_EQ(progress_line("files", 45, 100, duration<double>(12.3), 20),
            "files [#########...........]  45/100  12 s, about 15 s left");
  EXPECT_EQ(progress_line("radii", 0, 4, duration<double>(0.25), 4), "radii [....]  0/4  0.2 s");
  EXPECT_EQ(progress_line("radii", 4, 4, duration<double>(2.0), 4), "radii [####]  4/4  2.0 s");
  EXPECT_EQ(progress_line("scan", 7, 0, duration<double>(1.5)), "scan  7 done  1.5 s");
  // More done than announced never overflows the bar.
  EXPECT_EQ(progress_line("x", 9, 4, duration<double>(1.0), 4), "x [####]  4/4  1.0 s");
}

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int c = 0; (c = std::fgetc(f)) != EOF;) out += static_cast<char>(c);
  return out;
}

TEST(ProgressBar, SilentWhenNotATerminal) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressBar bar("work", 3, f);
    EXPECT_FALSE(bar.drawing());
    bar.advance();
    bar.advance(2);
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(ProgressBar, AlwaysModeRedrawsInPlaceAndEndsTheLine) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    ProgressBar bar("work", 2, f, ProgressBar::Mode::kAlways);
    bar.update(1); // first draw happens at once
    bar.update(2); // within 100 ms: not redrawn, but finish() draws the final state
  }
  const std::string out = contents(f);
  EXPECT_EQ(out.rfind("\rwork [", 0), 0U) << out;
  EXPECT_NE(out.find("1/2"), std::string::npos) << out;
  EXPECT_NE(out.find("2/2"), std::string::npos) << out;
  EXPECT_EQ(out.back(), '\n');
  std::fclose(f);
}

} // namespace
} // namespace penshape::render
