// vibro.periodic_orbit(scene, progress=None) -> vibro.PeriodicOrbit: the scene's periodic motion
// (and the branch continued from it) as `vibro orbit` finds it (app/orbit_command.cpp).
#include <pybind11/complex.h>
#include <pybind11/numpy.h>

#include <algorithm>
#include <atomic>
#include <complex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "io/orbit_json.h"
#include "io/scene_json.h"
#include "python/bindings.h"
#include "python/image.h"
#include "python/interruptible.h"
#include "python/json_values.h"
#include "python/scene_input.h"
#include "render/orbit_figure.h"

namespace vibro::python {
namespace {

py::array_t<std::complex<double>> complex_array(const std::vector<std::complex<double>>& xs) {
  py::array_t<std::complex<double>> a(static_cast<py::ssize_t>(xs.size()));
  std::copy(xs.begin(), xs.end(), a.mutable_data());
  return a;
}

// An orbit's result as its JSON's Python values (API.md, "Periodic motions and their
// stability"), with every "multipliers" a complex numpy array instead of a list of {re, im}.
class PeriodicOrbitResult {
 public:
  PeriodicOrbitResult(Scene scene, OrbitResult result, nlohmann::json json)
      : scene_(std::move(scene)), result_(std::move(result)), json_(std::move(json)) {
    data_ = python_from_json(json_).cast<py::dict>();
    data_["orbit"]["multipliers"] = complex_array(result_.orbit.multipliers);
    py::list branch = data_["branch"];
    for (std::size_t k = 0; k < result_.branch.points.size(); ++k)
      branch[k]["multipliers"] = complex_array(result_.branch.points[k].multipliers);
  }

  py::object get(const std::string& key) const {
    if (!data_.contains(key)) throw py::attribute_error("PeriodicOrbit has no \"" + key + "\"");
    return py::object(data_[py::str(key)]);
  }
  const py::dict& data() const { return data_; }
  // With its scene, as `vibro orbit` writes it (so that `vibro plot` can redraw it).
  std::string to_json() const {
    nlohmann::json saved = json_;
    saved["scene"] = scene_to_json(scene_);
    return saved.dump(2) + "\n";
  }

  // The continued branch (or its curves) as `vibro orbit -o OUT.png` draws it, over the scene's
  // sweep when the figure draws one (run here once, on every core, interruptible); None when
  // there is no branch to draw.
  py::object branch_image(const std::string& format_name) {
    const ImageFormat format = image_format(format_name);
    const OrbitRequest& request = *scene_.periodic_orbit;
    OrbitFigure figure{.branch = &result_.branch,
                       .continuation = request.continuation ? &*request.continuation : nullptr,
                       .sweep_spec = scene_.sweep ? &*scene_.sweep : nullptr,
                       .curves = &result_.curves,
                       .follow = request.follow ? &*request.follow : nullptr};
    if (!draws_branch(figure)) return py::none();
    if (draws_sweep_beneath(figure)) figure.sweep = &sweep_beneath();
    RenderResult image;
    {
      py::gil_scoped_release release;
      image = render_branch_figure(scene_.figure, scene_.model, figure, format);
    }
    return image_of(image, format);
  }

 private:
  // The scene's sweep as `vibro orbit` runs it beneath the figure, run on the first call.
  const SweepResult& sweep_beneath() {
    if (sweep_) return *sweep_;
    SweepControl control;
    control.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<bool> cancel{false};
    control.cancel = &cancel;
    SimOptions options = scene_.sim;
    options.check = false;
    SweepResult result;
    run_interruptible([&] { result = run_sweep(scene_.model, options, *scene_.sweep, control); },
                      cancel, {});
    return sweep_.emplace(std::move(result));
  }

  Scene scene_;
  OrbitResult result_;
  std::optional<SweepResult> sweep_;
  nlohmann::json json_;
  py::dict data_;
};

PeriodicOrbitResult find_orbit(py::handle scene_value, py::object progress) {
  Scene scene = scene_from_python(scene_value);
  if (!scene.periodic_orbit) scene.periodic_orbit = OrbitRequest{};
  const OrbitRequest& request = *scene.periodic_orbit;
  check(validate_orbit_request(scene.model, request));
  std::atomic<bool> cancel{false};
  std::atomic<double> done{0.0};
  double reported = -1.0;
  std::function<void()> report;
  if (!progress.is_none())
    report = [&] {
      const double d = done.load();
      if (d == reported) return;
      reported = d;
      progress(d);
    };
  OrbitResult result;
  nlohmann::json json;
  run_interruptible(
      [&] {
        result = run_orbit_request(
            scene.model, scene.sim, request, [&done](double d) { done = d; }, &cancel);
        json = orbit_result_json(result);
      },
      cancel, report);
  return PeriodicOrbitResult(std::move(scene), std::move(result), std::move(json));
}

}  // namespace

void add_periodic_orbit(py::module_& m) {
  py::class_<PeriodicOrbitResult>(
      m, "PeriodicOrbit",
      "A periodic motion found by vibro.periodic_orbit: its parts as in the JSON (orbit, branch, "
      "bifurcations, reached, message, ...), as attributes or items, multipliers as complex "
      "numpy arrays.")
      .def("__getattr__", &PeriodicOrbitResult::get)
      .def("__getitem__", &PeriodicOrbitResult::get)
      .def("keys", [](const PeriodicOrbitResult& o) { return o.data().attr("keys")(); })
      .def("__dir__", [](const PeriodicOrbitResult& o) { return py::list(o.data()); })
      .def("to_json", &PeriodicOrbitResult::to_json,
           "The result as `vibro orbit` prints it for the same scene (API.md's JSON).")
      .def("render", &PeriodicOrbitResult::branch_image, py::arg("format") = "png",
           "The continued branch, or the curves followed from it, drawn as `vibro orbit -o "
           "OUT.png` draws them: over the scene's sweep when it is of the same parameter(s), "
           "run on the first call on every core (Ctrl-C stops it). None without a branch.")
      .def("_repr_png_", [](PeriodicOrbitResult& o) { return o.branch_image("png"); })
      .def("__repr__", [](const PeriodicOrbitResult& o) {
        const py::dict orbit = o.data()["orbit"];
        return "<vibro.PeriodicOrbit: converged=" +
               py::repr(orbit["converged"]).cast<std::string>() +
               ", stable=" + py::repr(orbit["stable"]).cast<std::string>() + ", " +
               std::to_string(py::len(o.data()["branch"])) + " branch points>";
      });

  m.def("periodic_orbit", &find_orbit, py::arg("scene"), py::arg("progress") = py::none(),
        "Finds the scene's periodic_orbit (the defaults without one) and follows it when it asks "
        "for a continuation, as `vibro orbit` does, with the GIL released.\n\nprogress: a "
        "callable given the share of the continuation done (0 to 1), called on the calling "
        "thread. Ctrl-C (KeyboardInterrupt) stops the continuation and raises it. Raises "
        "vibro.SceneError naming the field of a bad request.");
}

}  // namespace vibro::python
