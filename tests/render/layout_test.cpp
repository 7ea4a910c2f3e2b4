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
  TimePlot both;
  both.show_dphi = true;
  figure.plots = {PhasePlot{}, both};
  const auto layouts = figure_layout(figure);
  ASSERT_EQ(layouts.size(), 2u);
  EXPECT_EQ(layouts[0].plots.size(), 1u);
  EXPECT_EQ(layouts[1].plots.size(), 2u);
  EXPECT_GE(layouts[1].plots[0].x, 600);
}

// However small the figure for its panels (the smallest is 64 px a side), every plot area lies
// inside its cell and so on the image: the plot axes a render reports name points of it. The
// render fuzzer found a 78×69 figure of three panels with a plot area at x = 104.
TEST(FigureLayout, PlotAreasStayInsideTheirCellsInTheSmallestFigures) {
  for (int count = 1; count <= 16; ++count) {
    for (int kind = 0; kind < 3; ++kind) {
      FigureSpec figure;
      TimePlot time;
      time.show_dphi = kind == 1;  // two stacked plot areas
      figure.plots.assign(count, kind == 2 ? PlotSpec{MechanismPlot{}} : PlotSpec{time});
      for (int side : {64, 78, 101, 160}) {
        figure.width = side;
        figure.height = side - 9;
        for (const PanelLayout& layout : figure_layout(figure)) {
          for (const Rect& a : layout.plots) {
            const Rect& c = layout.cell;
            EXPECT_TRUE(a.w >= 1 && a.h >= 1 && a.x >= c.x && a.y >= c.y &&
                        a.right() <= c.right() && a.bottom() <= c.bottom())
                << count << " panels of kind " << kind << " in " << side << " px: plot area " << a.x
                << ", " << a.y << ", " << a.w << " × " << a.h << " in the cell " << c.x << ", "
                << c.y << ", " << c.w << " × " << c.h;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace vibro::render
