// A sweep and its result for the tests of the sweep plots, drawn over the impact oscillator (one
// pellet forced at 0.3 N striking a stop at the bottom).
#pragma once

#include "core/analysis/sweep.h"
#include "render/figure.h"
#include "tests/core/impact_oscillator.h"

namespace vibro::testing {

struct Swept {
  SweepSpec spec;
  SweepResult result;
};

// A figure of one plot of this kind, the rest defaults.
inline FigureSpec figure_of(SweepView view) {
  FigureSpec figure;
  SweepPlot plot;
  plot.view = view;
  figure.plots = {plot};
  return figure;
}

inline RenderResult draw(SweepView view, const Swept& s, ImageFormat format) {
  return render_figure(figure_of(view), impact_oscillator(), RunResult{}, format,
                       {nullptr, SweepData{s.spec, s.result}});
}

}  // namespace vibro::testing
