#include "render/layout.h"

#include <gtest/gtest.h>

namespace vibro::render {
namespace {

int columns(const std::vector<Rect>& cells) {
  int n = 0;
  for (const Rect& c : cells) n += c.y == cells.front().y;
  return n;
}

TEST(GridCells, OnePanelFillsTheFigure) {
  const auto cells = grid_cells(1, 1200, 800);
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0].w, 1200);
  EXPECT_EQ(cells[0].h, 800);
}

TEST(GridCells, TwoPanelsSideBySideWhenWideStackedWhenTall) {
  EXPECT_EQ(columns(grid_cells(2, 1200, 800)), 2);
  EXPECT_EQ(columns(grid_cells(2, 600, 900)), 1);
}

TEST(GridCells, ThreeAndFourMakeTwoByTwo) {
  EXPECT_EQ(columns(grid_cells(3, 1200, 800)), 2);
  EXPECT_EQ(columns(grid_cells(4, 1200, 800)), 2);
  EXPECT_EQ(grid_cells(4, 1200, 800)[3].y, 400);
}

TEST(GridCells, MoreMakeANearSquareGridInsideTheFigure) {
  const auto cells = grid_cells(7, 1200, 800);
  EXPECT_EQ(columns(cells), 3);
  for (const Rect& c : cells) {
    EXPECT_LE(c.right(), 1200);
    EXPECT_LE(c.bottom(), 800);
  }
  EXPECT_EQ(columns(grid_cells(7, 800, 1200)), 3);  // rows of 3, 3 and 1
  EXPECT_EQ(grid_cells(5, 800, 1200).size(), 5u);
}

TEST(PanelLayout, PlotAreasSitInsideTheCellWithRoomForLabels) {
  const Rect cell{600, 0, 600, 800};
  const PanelLayout one = panel_layout(cell, Style{1.0}, 1);
  ASSERT_EQ(one.plots.size(), 1u);
  const Rect& a = one.plots[0];
  EXPECT_GT(a.x, cell.x + 60);
  EXPECT_LT(a.right(), cell.right());
  EXPECT_GT(a.y, cell.y + 25);
  EXPECT_LT(a.bottom(), cell.bottom() - 40);

  const PanelLayout two = panel_layout(cell, Style{1.0}, 2);
  ASSERT_EQ(two.plots.size(), 2u);
  EXPECT_LT(two.plots[0].bottom(), two.plots[1].y);
  EXPECT_EQ(two.plots[0].w, a.w);
}

TEST(FigureLayout, StacksTheTimePanelWhenItShowsDphi) {
  FigureSpec figure;
  figure.plots = {PlotSpec{}, PlotSpec{}};
  figure.plots[1].kind = PlotKind::time;
  figure.plots[1].show_dphi = true;
  const auto layouts = figure_layout(figure);
  ASSERT_EQ(layouts.size(), 2u);
  EXPECT_EQ(layouts[0].plots.size(), 1u);
  EXPECT_EQ(layouts[1].plots.size(), 2u);
  EXPECT_GE(layouts[1].plots[0].x, 600);
}

}  // namespace
}  // namespace vibro::render
