#include "tests/robustness/edge_requests.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stop_token>
#include <thread>

#include "core/model/parameter.h"
#include "io/orbit_json.h"
#include "io/scene_json.h"
#include "io/sweep_json.h"
#include "server/run_scene.h"
#include "tests/robustness/edge_values.h"
#include "tests/sanitizers.h"

namespace vibro::robustness {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Sets `flag` once `ms` have passed, unless destroyed first: DELETE /api/jobs/ID at a moment.
class CancelAt {
 public:
  CancelAt(std::atomic<bool>& flag, double ms)
      : thread_([&flag, ms](std::stop_token stop) {
          std::mutex m;
          std::condition_variable_any wake;
          std::unique_lock lock(m);
          wake.wait_for(lock, stop, std::chrono::duration<double, std::milli>(ms),
                        [] { return false; });
          if (!stop.stop_requested()) flag = true;
        }) {}

 private:
  std::jthread thread_;
};

// The value at a field path of the request, or null.
const json* at_path(const json& j, const std::string& path) {
  return field_at(const_cast<json&>(j), path);
}

// The model fields a request varies: a refusal may name one of them (core/analysis/sweep.h,
// validate_sweep: "a model field that a swept value makes invalid").
bool varied(const json& request, const std::string& field) {
  for (const char* path :
       {"sweep.parameter", "sweep.parameter2.parameter", "periodic_orbit.continuation.parameter"}) {
    const json* p = at_path(request, path);
    if (p && p->is_string() && p->get<std::string>() == field) return true;
  }
  return false;
}

// A refusal names a non-empty field that the request holds (or that it varies, or that it lacks
// and must hold: "is required").
void check_refusal(const std::string& body, EdgeOutcome& out) {
  if (out.field.empty()) {
    out.findings.push_back("refused without naming a field: " + out.message);
    return;
  }
  const json request = json::parse(body, nullptr, false);
  if (request.is_discarded()) return;  // text no JSON reader takes: "scene" is the field
  if (!at_path(request, out.field) && !varied(request, out.field) &&
      !out.message.starts_with("is required"))
    out.findings.push_back("refused naming \"" + out.field +
                           "\", which the request does not hold: " + out.message);
}

// Every number in the answer is finite (the writers send null for the rest).
void check_finite(const json& j, const std::string& where, EdgeOutcome& out) {
  if (j.is_number_float() && !std::isfinite(j.get<double>()))
    out.findings.push_back("the answer holds " + json(j.get<double>()).dump() + " at " + where);
  if (j.is_object())
    for (const auto& [key, value] : j.items()) check_finite(value, where + "/" + key, out);
  if (j.is_array())
    for (std::size_t i = 0; i < j.size(); ++i)
      check_finite(j[i], where + "/" + std::to_string(i), out);
}

// Every cell of the CSV is a finite number or empty, but the Lyapunov exponent's "-inf"
// (docs/SWEEPS.md: every perturbation dies).
void check_csv(const std::string& csv, EdgeOutcome& out) {
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // the header
  while (std::getline(lines, line)) {
    std::istringstream cells(line);
    std::string cell;
    for (int column = 0; std::getline(cells, cell, ','); ++column) {
      if (cell.empty() || (column == 13 && cell == "-inf")) continue;
      char* end = nullptr;
      const double x = std::strtod(cell.c_str(), &end);
      if (*end != '\0' || !std::isfinite(x)) {
        out.findings.push_back("the CSV holds \"" + cell + "\" in column " +
                               std::to_string(column) + ": " + line);
        return;
      }
    }
  }
}

// The model at a value of `parameter` passes the checks a scene of its own passes.
void check_value(const Model& model, const std::string& parameter, double value,
                 const std::string& what, EdgeOutcome& out) {
  Model m = model;
  set_parameter(m, parameter, value);
  if (auto e = validate_model(m))
    out.findings.push_back(what + " " + parameter + " = " + json(value).dump() +
                           ", where the model is invalid: " + e->field + " " + e->message);
}

void check_branch(const Scene& scene, const OrbitResult& result, EdgeOutcome& out) {
  const auto& c = scene.periodic_orbit->continuation;
  if (!c) return;
  for (const BranchPoint& p : result.branch.points)
    check_value(scene.model, c->parameter, p.value, "a branch point at", out);
  for (const Bifurcation& b : result.branch.bifurcations) {
    check_value(scene.model, c->parameter, b.value, "a bifurcation at", out);
    if (b.doubled_value)
      check_value(scene.model, c->parameter, *b.doubled_value, "a doubled motion at", out);
  }
}

void check_runs(const Scene& scene, const SweepResult& result, EdgeOutcome& out) {
  const SweepSpec& spec = *scene.sweep;
  for (const SweepRun& run : result.runs) {
    if (!(run.value >= spec.axis.from && run.value <= spec.axis.to))
      out.findings.push_back("a run at " + json(run.value).dump() +
                             ", outside sweep.from .. sweep.to");
    check_value(scene.model, spec.axis.parameter, run.value, "a run at", out);
    if (!spec.axis2) continue;
    if (!(run.value2 >= spec.axis2->from && run.value2 <= spec.axis2->to))
      out.findings.push_back("a run at value2 " + json(run.value2).dump() +
                             ", outside sweep.parameter2.from .. to");
    check_value(scene.model, spec.axis2->parameter, run.value2, "a run at", out);
  }
}

// The sanitizers slow the work between two looks at a deadline some tenfold, while deadlines stay
// wall clock: there the bound is four times as generous.
constexpr double kSlack = vibro::testing::kUnderAsan ? 4.0 : 1.0;

void check_time(const server::Limits& limits, EdgeOutcome& out) {
  if (out.ms > kSlack * (5.0 * limits.deadline_ms + 1000.0))
    out.findings.push_back("answered after " + std::to_string(std::lround(out.ms)) + " ms, over " +
                           (kSlack > 1.0 ? "4 × (" : "(") + "5 × its deadline of " +
                           std::to_string(std::lround(limits.deadline_ms)) + " ms + 1 s)");
}

// The scene as the server reads it, or the refusal in `out`.
std::optional<Scene> read(const std::string& body, const server::Limits& limits, EdgeOutcome& out) {
  SceneOrError parsed = scene_from_text(body, limits);
  if (const FieldError* e = std::get_if<FieldError>(&parsed)) {
    out.field = e->field;
    out.message = e->message;
    return std::nullopt;
  }
  return std::get<Scene>(std::move(parsed));
}

std::optional<Scene> refused(const FieldError& e, EdgeOutcome& out) {
  out.field = e.field;
  out.message = e.message;
  return std::nullopt;
}

// Api::orbit_post up to the run.
std::optional<Scene> accepted_orbit(const std::string& body, const server::Limits& limits,
                                    EdgeOutcome& out) {
  std::optional<Scene> scene = read(body, limits, out);
  if (!scene) return std::nullopt;
  if (!scene->periodic_orbit) {
    scene->periodic_orbit.emplace();
    if (auto e = validate_orbit_request(scene->model, *scene->periodic_orbit, limits))
      return refused(*e, out);
  }
  scene->sim = server::bounded_options(scene->sim, limits);
  return scene;
}

// Api::sweep_post up to the job.
std::optional<Scene> accepted_sweep(const std::string& body, const server::Limits& limits,
                                    EdgeOutcome& out) {
  std::optional<Scene> scene = read(body, limits, out);
  if (!scene) return std::nullopt;
  if (!scene->sweep) return refused(FieldError{"sweep", "is required"}, out);
  scene->sim = server::bounded_options(scene->sim, limits);
  return scene;
}

// Runs `work` with the request's checks around it: the refusal's field, the time, exceptions.
template <class Work>
EdgeOutcome carried_out(const std::string& body, const server::Limits& limits, Work work) {
  EdgeOutcome out;
  const Clock::time_point t0 = Clock::now();
  try {
    out.accepted = work(out);
  } catch (const std::exception& e) {
    out.findings.push_back(std::string("threw (a 500): ") + e.what());
  }
  out.ms = ms_since(t0);
  if (out.accepted)
    check_time(limits, out);
  else if (out.findings.empty())
    check_refusal(body, out);
  return out;
}

}  // namespace

EdgeOutcome orbit_request(const std::string& body, const server::Limits& limits) {
  return carried_out(body, limits, [&](EdgeOutcome& out) {
    const std::optional<Scene> scene = accepted_orbit(body, limits, out);
    if (!scene) return false;
    std::atomic<bool> cancel{false};
    OrbitResult result;
    if (scene->periodic_orbit->continuation) {
      const CancelAt stop(cancel, limits.deadline_ms);
      result = run_orbit_request(scene->model, scene->sim, *scene->periodic_orbit, {}, &cancel);
    } else {
      result = run_orbit_request(scene->model, scene->sim, *scene->periodic_orbit);
    }
    check_finite(orbit_result_json(result), "", out);
    check_branch(*scene, result, out);
    return true;
  });
}

EdgeOutcome sweep_request(const std::string& body, const server::Limits& limits, long runs) {
  return carried_out(body, limits, [&](EdgeOutcome& out) {
    const std::optional<Scene> scene = accepted_sweep(body, limits, out);
    if (!scene) return false;
    std::atomic<bool> cancel{false};
    SweepControl control;
    control.cancel = &cancel;
    control.progress = [&](long done, long) {
      if (done >= runs) cancel = true;
    };
    SweepResult result;
    {
      const CancelAt stop(cancel, limits.deadline_ms);
      result = run_sweep(scene->model, scene->sim, *scene->sweep, control);
    }
    check_finite(sweep_result_json(*scene->sweep, result), "", out);
    check_csv(sweep_result_csv(*scene->sweep, result), out);
    check_runs(*scene, result, out);
    return true;
  });
}

}  // namespace vibro::robustness
