// The window's layout as a pure function: the view never meets a panel, at any size and scale.
#include "app/layout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace s4d {
namespace {

void expect_view_clear_of_panels(const Layout& l, const std::string& what) {
  for (const auto& [name, r] : l.panels()) EXPECT_FALSE(l.view.intersects(r)) << what << ": the view meets the " << name;
}

TEST(Layout, ALaptopWindowHasBothColumnsAndAViewBetweenThem) {
  LayoutInput in;
  in.width = 1280, in.height = 800;
  const Layout l = compute_layout(in);
  EXPECT_EQ(l.left.x, 0);
  EXPECT_EQ(l.left.w, kLeftColumnWidth);
  EXPECT_EQ(l.right.right(), 1280);
  EXPECT_EQ(l.right.w, kRightColumnWidth);
  EXPECT_EQ(l.view.x, l.left.right());
  EXPECT_EQ(l.view.right(), l.right.x);
  EXPECT_EQ(l.view.y, l.menu.bottom());
  EXPECT_EQ(l.view.bottom(), l.status.y);
  EXPECT_EQ(l.status.bottom(), 800);
  EXPECT_GT(l.view.w, 600);
  expect_view_clear_of_panels(l, "1280x800");
}

TEST(Layout, TheInstructionBandSitsAboveTheViewAndClosedColumnsGiveItTheirWidth) {
  LayoutInput in;
  in.band_lines = 2;
  const Layout open = compute_layout(in);
  EXPECT_EQ(open.band.bottom(), open.view.y);
  EXPECT_EQ(open.band.x, open.view.x);
  EXPECT_NEAR(open.band.h, 2 * in.line_height + 10, 0.5);
  in.left_open = in.right_open = false;
  const Layout closed = compute_layout(in);
  EXPECT_EQ(closed.left.w, kStripWidth);
  EXPECT_EQ(closed.right.w, kStripWidth);
  EXPECT_EQ(closed.view.w, 1280 - 2 * kStripWidth);
  expect_view_clear_of_panels(closed, "closed columns");
}

TEST(Layout, AtScaleTwoTheColumnsGiveWaySoTheViewKeepsItsShare) {
  LayoutInput in;
  in.width = 1920, in.height = 1080, in.scale = 2, in.menu_height = 38, in.line_height = 34, in.band_lines = 3;
  const Layout l = compute_layout(in);
  EXPECT_GE(l.view.w, kMinViewShare * 1920 - 1);
  EXPECT_EQ(l.left.w, 2 * kLeftColumnWidth);  // the right one gives way first
  EXPECT_LT(l.right.w, 2 * kRightColumnWidth);
  EXPECT_GE(l.right.w, 2 * kStripWidth);
  expect_view_clear_of_panels(l, "1920x1080 at 2");
}

TEST(Layout, EverySizeAndScaleTilesTheWindowWithoutOverlap) {
  for (float w : {320.f, 800.f, 1280.f, 1920.f, 3840.f})
    for (float h : {240.f, 800.f, 1080.f, 2160.f})
      for (float s : {0.5f, 1.f, 1.5f, 2.f, 3.f})
        for (bool page : {false, true}) {
          LayoutInput in;
          in.width = w, in.height = h, in.scale = s, in.menu_height = 19 * s, in.line_height = 17 * s;
          in.band_lines = 2, in.start_page = page;
          const Layout l = compute_layout(in);
          const std::string what = std::to_string(w) + "x" + std::to_string(h) + " at " + std::to_string(s);
          expect_view_clear_of_panels(l, what);
          const auto parts = l.panels();
          for (std::size_t i = 0; i < parts.size(); ++i) {
            EXPECT_GE(parts[i].second.x, 0) << what;
            EXPECT_LE(parts[i].second.right(), w + 0.5f) << what << " " << parts[i].first;
            EXPECT_LE(parts[i].second.bottom(), h + 0.5f) << what << " " << parts[i].first;
            for (std::size_t j = i + 1; j < parts.size(); ++j)
              EXPECT_FALSE(parts[i].second.intersects(parts[j].second)) << what << ": " << parts[i].first << " and " << parts[j].first;
          }
          EXPECT_EQ(page, l.view.empty() && !l.page.empty()) << what;
        }
}

TEST(Layout, AbsurdInputGivesAUsableLayout) {
  LayoutInput in;
  in.width = std::numeric_limits<float>::quiet_NaN(), in.height = -5, in.scale = std::numeric_limits<float>::infinity();
  const Layout l = compute_layout(in);
  for (const auto& [name, r] : l.panels()) EXPECT_TRUE(std::isfinite(r.x + r.y + r.w + r.h)) << name;
}

}  // namespace
}  // namespace s4d
