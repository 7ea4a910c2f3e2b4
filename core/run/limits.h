// Every bound a request is checked against, in one struct: what a scene, its run, its figure,
// its sweep and its periodic-orbit request may ask, and the budgets that stop the work. Each
// spec checks itself against a Limits value (validate_model, validate_options, validate_sweep,
// validate_orbit, validate_figure); the scene reader bounds what it reads by the same value. The
// defaults are the widest anything accepts (the command line's); a server only tightens them
// (server/config.h). A budget whose default is "none" bounds nothing until it is tightened.
#pragma once

#include <cstddef>
#include <limits>

namespace vibro {

struct Limits {
  // --- The scene's text ---
  // JSON nesting, levels, counted on the text before it is parsed: a deeper document costs a
  // recursion per level in the parser.
  int depth = 16;
  // A request's body, bytes: the server refuses a longer one from its Content-Length, before
  // reading it. None for a file or the standard input.
  std::size_t body_bytes = std::numeric_limits<std::size_t>::max();

  // --- The model ---
  // Pellets per model: the work of every step and every instant grows with them, and a sweep's
  // section point stores its pellet in 16 bits.
  int pellets = 8;
  // Limiters per model: every step watches each one for each pellet it stops.
  int limiters = 16;

  // --- The run ---
  // Simulated time, s (a scene's t_end lies in (0, t_end]): a run's events and steps grow with
  // it, and the budgets below stop what it cannot bound.
  double t_end = 1e6;
  // Events a run may list, and integrator steps (accepted and rejected) it may take: a run that
  // reaches one stops (SimOptions::max_events, max_steps take the smaller). None by default.
  long events = std::numeric_limits<long>::max();
  long steps = std::numeric_limits<long>::max();
  // Trajectory samples kept, all recorded pellets together; past it the branches are thinned,
  // so a long run is drawn whole, more coarsely (SimOptions::max_samples). 0: none.
  long samples = 0;
  // Wall clock of one simulation, ms: the run stops at it (SimOptions::deadline_ms). None.
  double deadline_ms = std::numeric_limits<double>::infinity();

  // --- The figure ---
  // Image width and height, px each, from kMinFigureSide (render/figure_size.h): the image is
  // held whole in memory, 4 bytes a pixel, and the 3-D view draws at most 4096 px a side.
  int width = 4096;
  int height = 4096;
  // Image width × height, px: no tighter than the sides allow unless tightened.
  long pixels = 4096L * 4096L;
  // Panels per figure: each draws at least an axis box and its labels in a grid cell.
  int plots = 8;
  // Branches a phase panel may pick by number: each is looked up among the run's branches.
  int plot_branches = 10'000;
  // A figure's print size (a scene's "figure", render/plot_spec.h PrintSize): each side in mm,
  // its text in pt, its resolution in dots per inch. The pixels they make (side / 25.4 · dpi)
  // are held to width, height and pixels above.
  double print_mm_min = 10.0;  // less leaves no room for the axes' labels
  double print_mm_max = 1000.0;
  double font_pt_min = 4.0;  // below what a journal prints legibly
  double font_pt_max = 48.0;
  double dpi_min = 50.0;
  double dpi_max = 2400.0;

  // --- Sweeps (core/analysis/sweep.h) ---
  // Runs of one sweep (values × values2 × directions × initial states): every value's model is
  // checked up front, some 3 µs each, so 10^6 runs take some 3 s to check.
  long sweep_runs = 1'000'000;
  // A run's transient and its record, forcing periods each.
  int sweep_run_periods = 1'000'000;
  // Initial states per value: each is a run of its own at every value.
  int sweep_starts = 1000;
  // Periods one sweep may simulate, runs × (transient + record). None by default.
  double sweep_periods = std::numeric_limits<double>::infinity();
  // Section points one sweep may keep (40 bytes each): a stroboscopic sweep over it is refused up
  // front, an impact-section sweep stops when it reaches it. 0: none.
  long sweep_points = 0;
  // Wall clock of one sweep or continuation job, s, shared by its runs. None by default.
  double sweep_seconds = std::numeric_limits<double>::infinity();
  // Section points a sweep's point plot is drawn with as SVG or PDF, where each point is a mark
  // of its own (some 1.4 KB of memory while drawn); PNG draws any number. None by default.
  long sweep_vector_points = std::numeric_limits<long>::max();

  // --- Periodic orbits (core/analysis/periodic_orbit.h, orbit_continuation.h) ---
  // Forcing periods of the sought motion: the map is the simulator over that many periods, and
  // its multipliers lose accuracy with its length.
  int orbit_periods = 64;
  // Forcing periods of the run to the starting guess.
  int orbit_transient = 100'000;
  // Newton iterations of the search, each at least one map.
  int orbit_iterations = 1000;
  // Points of a continued branch, each a few corrector iterations.
  int branch_points = 10'000;
};

}  // namespace vibro
