#include "server/sweep_limits.h"

#include <algorithm>
#include <string>

#include "core/analysis/sweep.h"

namespace vibro::server {
namespace {

// The runs made one after another: a chain's runs in order, and the chains `threads` at a time.
long serial_runs(const SweepSpec& spec, int threads) {
  const long chains = sweep_chain_count(spec);
  const long per_chain = sweep_runs(spec) / std::max(1L, chains);
  const long rounds = (chains + std::max(1, threads) - 1) / std::max(1, threads);
  return rounds * per_chain;
}

}  // namespace

std::optional<ApiError> check_sweep_cost(const Scene& scene, const Limits& limits, int threads) {
  const SweepSpec& spec = *scene.sweep;
  const long runs = sweep_runs(spec);
  if (spec.section == SectionKind::stroboscopic) {
    const long per_run = stroboscopic_points_per_run(scene.model, spec);
    // Runs at most 10^7, points per run at most (10^6 + 1) × 64: the product fits in 64 bits.
    const long points = runs * per_run;
    if (points > limits.sweep_points)
      return ApiError{400, "sweep.record",
                      "the sweep would keep " + std::to_string(points) +
                          " section points (runs × (record + 1) × pellets = " +
                          std::to_string(runs) + " × " + std::to_string(per_run) +
                          "), over the server's limit of " + std::to_string(limits.sweep_points) +
                          ": record fewer periods, or sweep fewer values"};
  }
  const long serial = serial_runs(spec, threads);
  const double share_ms = 1000.0 * limits.sweep_seconds / static_cast<double>(serial);
  if (share_ms < kMinSweepRunMs)
    return ApiError{400, "sweep.count",
                    "the sweep's " + std::to_string(runs) + " runs (" + std::to_string(serial) +
                        " one after another on the server's " + std::to_string(threads) +
                        " sweep thread" + (threads == 1 ? "" : "s") + ") would leave each " +
                        shortest_text(share_ms) + " ms of the server's wall-clock budget of " +
                        shortest_text(limits.sweep_seconds) +
                        " s for a sweep; a run needs at least " + shortest_text(kMinSweepRunMs) +
                        " ms: sweep fewer values"};
  return std::nullopt;
}

double sweep_run_deadline_ms(const SweepSpec& spec, const Limits& limits, int threads) {
  const double share_ms =
      0.9 * 1000.0 * limits.sweep_seconds / static_cast<double>(serial_runs(spec, threads));
  return std::min(limits.deadline_ms, share_ms);
}

}  // namespace vibro::server
