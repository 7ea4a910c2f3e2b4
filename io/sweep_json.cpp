#include "io/sweep_json.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "io/json_fields.h"
#include "io/result_json.h"

namespace vibro {
namespace {

using nlohmann::json;

int bounded_int(Fields& f, const std::string& key, int fallback) {
  const auto v = f.integer(key);
  if (!v) return fallback;
  if (*v < -2147483647L || *v > 2147483647L) throw FieldException(f.path(key), "is out of range");
  return static_cast<int>(*v);
}

SweepAxis read_axis(Fields& f) {
  SweepAxis a;
  const auto parameter = f.string("parameter", 200);
  if (!parameter)
    throw FieldException(f.path("parameter"),
                         "is required: a field path such as \"model.pellets[0].F0\"");
  a.parameter = *parameter;
  a.from = f.required_number("from");
  a.to = f.required_number("to");
  a.count = bounded_int(f, "count", 1);
  return a;
}

const char* section_name(SectionKind k) {
  return k == SectionKind::stroboscopic ? "stroboscopic" : "impact";
}

const char* continuation_name(Continuation c) {
  switch (c) {
    case Continuation::none:
      return "none";
    case Continuation::forward:
      return "forward";
    case Continuation::backward:
      return "backward";
    case Continuation::both:
      return "both";
  }
  return "none";
}

// Text formatted into a buffer that goes to the sink whenever it passes a piece's size.
class Pieces {
 public:
  explicit Pieces(const TextSink& sink) : sink_(sink) { buffer_.reserve(kPiece + 512); }
  void text(std::string_view s) {
    buffer_ += s;
    if (buffer_.size() >= kPiece) flush();
  }
  // A JSON string, escaped.
  void string(const std::string& s) { text(json(s).dump()); }
  // A JSON number: null when not finite (as every number of vibro's JSON), and ".0" on a whole
  // one, so that it reads back as a double (as nlohmann::json writes it).
  void number(double x) {
    if (!std::isfinite(x)) return text("null");
    char b[40];
    const std::string_view v(b, std::to_chars(b, b + sizeof b, x).ptr - b);
    text(v);
    if (v.find_first_of(".e") == std::string_view::npos) text(".0");
  }
  // A CSV number: 17 significant digits ("inf", "-inf" and "nan" as they are).
  void digits17(double x) {
    char b[40];
    text({b, static_cast<std::size_t>(
                 std::to_chars(b, b + sizeof b, x, std::chars_format::general, 17).ptr - b)});
  }
  void integer(long x) {
    char b[24];
    text({b, static_cast<std::size_t>(std::to_chars(b, b + sizeof b, x).ptr - b)});
  }
  void boolean(bool x) { text(x ? "true" : "false"); }
  // Whether the sink took everything so far; once it refuses, nothing more is sent.
  bool ok() const { return ok_; }
  bool finish() {
    flush();
    return ok_;
  }

 private:
  static constexpr std::size_t kPiece = 64 * 1024;
  void flush() {
    if (ok_ && !buffer_.empty()) ok_ = sink_(buffer_);
    buffer_.clear();
  }
  const TextSink& sink_;
  std::string buffer_;
  bool ok_ = true;
};

// A column of the result's JSON: its name and how one entry is written (a point's, with its run
// and the run's index; or a run's).
using Run = const SweepRun&;
using Point = const SectionPoint&;
struct PointColumn {
  const char* name;
  void (*write)(Pieces&, Run, std::size_t run, Point);
};
struct RunColumn {
  const char* name;
  void (*write)(Pieces&, Run);
};

// In sorted order, as a JSON object's keys are written.
constexpr PointColumn kPointColumns[] = {
    {"attractor", [](Pieces& o, Run r, std::size_t, Point) { o.integer(r.attractor); }},
    {"direction", [](Pieces& o, Run r, std::size_t, Point) { o.integer(r.direction); }},
    {"dphi", [](Pieces& o, Run, std::size_t, Point p) { o.number(p.dphi); }},
    {"limiter", [](Pieces& o, Run, std::size_t, Point p) { o.integer(p.limiter); }},
    {"pellet", [](Pieces& o, Run, std::size_t, Point p) { o.integer(p.pellet); }},
    {"phase", [](Pieces& o, Run, std::size_t, Point p) { o.number(p.phase); }},
    {"phi", [](Pieces& o, Run, std::size_t, Point p) { o.number(p.phi); }},
    {"run", [](Pieces& o, Run, std::size_t k, Point) { o.integer(static_cast<long>(k)); }},
    {"start", [](Pieces& o, Run r, std::size_t, Point) { o.integer(r.start); }},
    {"t", [](Pieces& o, Run, std::size_t, Point p) { o.number(p.t); }},
    {"trusted", [](Pieces& o, Run, std::size_t, Point p) { o.boolean(p.trusted); }},
    {"value", [](Pieces& o, Run r, std::size_t, Point) { o.number(r.value); }},
    {"value2", [](Pieces& o, Run r, std::size_t, Point) { o.number(r.value2); }},
};

constexpr RunColumn kRunColumns[] = {
    {"at_rest", [](Pieces& o, Run r) { o.boolean(r.at_rest); }},
    {"attractor", [](Pieces& o, Run r) { o.integer(r.attractor); }},
    {"direction", [](Pieces& o, Run r) { o.integer(r.direction); }},
    {"error_estimate", [](Pieces& o, Run r) { o.number(r.error_estimate); }},
    {"impacts_per_period", [](Pieces& o, Run r) { o.number(r.impacts_per_period); }},
    // JSON has no −infinity: null, as for a run without an exponent (docs/SWEEPS.md).
    {"lyapunov", [](Pieces& o, Run r) { r.lyapunov ? o.number(*r.lyapunov) : o.text("null"); }},
    {"message", [](Pieces& o, Run r) { o.string(r.message); }},
    {"period", [](Pieces& o, Run r) { o.integer(r.period); }},
    {"start", [](Pieces& o, Run r) { o.integer(r.start); }},
    {"sticks", [](Pieces& o, Run r) { o.boolean(r.sticks); }},
    {"termination",
     [](Pieces& o, Run r) { o.string(std::string(termination_name(r.termination))); }},
    {"trusted", [](Pieces& o, Run r) { o.boolean(r.trusted); }},
    {"trusted_until", [](Pieces& o, Run r) { o.number(r.trusted_until); }},
    {"value", [](Pieces& o, Run r) { o.number(r.value); }},
    {"value2", [](Pieces& o, Run r) { o.number(r.value2); }},
};

// The attractor columns are written only for a sweep that classifies attractors: other sweeps'
// results stay as they were.
bool column_written(const char* name, const SweepResult& result) {
  return result.classified || std::string_view(name) != "attractor";
}

// "attractors": [{"cells", "id", "at_rest", "impacts_per_period", "period", "section": [{"dphi",
// "phi"}]}]
void write_attractors(Pieces& out, const SweepResult& result) {
  out.text("\"attractors\":[");
  for (const Attractor& a : result.attractors) {
    if (&a != result.attractors.data()) out.text(",");
    out.text("{\"cells\":");
    out.integer(a.cells);
    out.text(",\"id\":");
    out.integer(a.id);
    out.text(",\"at_rest\":");
    out.boolean(a.at_rest);
    out.text(",\"impacts_per_period\":");
    out.number(a.impacts_per_period);
    out.text(",\"period\":");
    out.integer(a.period);
    out.text(",\"section\":[");
    for (std::size_t k = 0; k < a.section.size(); ++k) {
      out.text(k > 0 ? ",{\"dphi\":" : "{\"dphi\":");
      out.number(a.section[k].second);
      out.text(",\"phi\":");
      out.number(a.section[k].first);
      out.text("}");
    }
    out.text("]}");
  }
  out.text("],");
}

// What `write` writes to a sink, as one string.
template <class Write>
std::string whole_text(const Write& write) {
  std::string text;
  write([&text](std::string_view piece) {
    text += piece;
    return true;
  });
  return text;
}

// One column of every point, as a JSON array.
bool write_point_column(Pieces& out, const PointColumn& column, const SweepResult& result) {
  out.text("[");
  bool first = true;
  for (std::size_t r = 0; r < result.runs.size() && out.ok(); ++r)
    for (const SectionPoint& p : result.runs[r].points) {
      if (!first) out.text(",");
      first = false;
      column.write(out, result.runs[r], r, p);
    }
  out.text("]");
  return out.ok();
}

bool write_run_column(Pieces& out, const RunColumn& column, const SweepResult& result) {
  out.text("[");
  for (std::size_t r = 0; r < result.runs.size() && out.ok(); ++r) {
    if (r > 0) out.text(",");
    column.write(out, result.runs[r]);
  }
  out.text("]");
  return out.ok();
}

}  // namespace

SweepSpec read_sweep(const json& j) {
  Fields f(j, "sweep");
  SweepSpec s;
  s.axis = read_axis(f);
  if (const json* p2 = f.value("parameter2")) {
    Fields f2(*p2, "sweep.parameter2");
    s.axis2 = read_axis(f2);
    f2.done();
  }
  s.transient = bounded_int(f, "transient", s.transient);
  s.record = bounded_int(f, "record", s.record);
  if (auto section = f.string("section", 32)) {
    if (*section == "stroboscopic")
      s.section = SectionKind::stroboscopic;
    else if (*section == "impact")
      s.section = SectionKind::impact;
    else
      throw FieldException("sweep.section",
                           "must be \"stroboscopic\" or \"impact\", got \"" + *section + "\"");
  }
  if (auto c = f.string("continuation", 32)) {
    if (*c == "none")
      s.continuation = Continuation::none;
    else if (*c == "forward")
      s.continuation = Continuation::forward;
    else if (*c == "backward")
      s.continuation = Continuation::backward;
    else if (*c == "both")
      s.continuation = Continuation::both;
    else
      throw FieldException(
          "sweep.continuation",
          "must be \"none\", \"forward\", \"backward\" or \"both\", got \"" + *c + "\"");
  }
  s.initial_states = bounded_int(f, "initial_states", s.initial_states);
  if (auto seed = f.integer("seed")) {
    if (*seed < 0) throw FieldException("sweep.seed", "must not be negative");
    s.seed = static_cast<std::uint64_t>(*seed);
  }
  s.lyapunov = f.boolean("lyapunov", s.lyapunov);
  if (auto classify = f.string("classify", 32)) {
    if (*classify != "attractor")
      throw FieldException("sweep.classify", "must be \"attractor\", got \"" + *classify + "\"");
    s.classify_attractor = true;
  }
  f.done();
  return s;
}

json sweep_to_json(const SweepSpec& s) {
  auto axis = [](const SweepAxis& a) {
    return json{{"parameter", a.parameter}, {"from", a.from}, {"to", a.to}, {"count", a.count}};
  };
  json j = axis(s.axis);
  if (s.axis2) j["parameter2"] = axis(*s.axis2);
  j["transient"] = s.transient;
  j["record"] = s.record;
  j["section"] = section_name(s.section);
  j["continuation"] = continuation_name(s.continuation);
  j["initial_states"] = s.initial_states;
  j["seed"] = s.seed;
  j["lyapunov"] = s.lyapunov;
  if (s.classify_attractor) j["classify"] = "attractor";
  return j;
}

namespace {

// The result's keys before its columns: the attractors (when classified) and the parameters.
void write_head(Pieces& out, const SweepSpec& spec, const SweepResult& result) {
  out.text("{");
  if (result.classified) write_attractors(out, result);
  out.text("\"parameter\":");
  out.string(spec.axis.parameter);
  if (spec.axis2) {
    out.text(",\"parameter2\":");
    out.string(spec.axis2->parameter);
  }
}

// The point and run columns, each key preceded by a comma.
bool write_columns(Pieces& out, const SweepResult& result) {
  out.text(",\"points\":{");
  bool first = true;
  for (const PointColumn& c : kPointColumns) {
    if (!column_written(c.name, result)) continue;
    if (!first) out.text(",");
    first = false;
    out.string(c.name);
    out.text(":");
    if (!write_point_column(out, c, result)) return false;
  }
  out.text("},\"runs\":{");
  for (const RunColumn& c : kRunColumns) {
    if (!column_written(c.name, result)) continue;
    if (&c != kRunColumns) out.text(",");
    out.string(c.name);
    out.text(":");
    if (!write_run_column(out, c, result)) return false;
  }
  out.text("}");
  return true;
}

// The keys after the columns: the scene (when given), the section and the stats; then the end.
bool write_tail(Pieces& out, const SweepSpec& spec, const SweepResult& result, const json& scene) {
  long points = 0;
  for (const SweepRun& run : result.runs) points += static_cast<long>(run.points.size());
  if (!scene.is_null()) {
    out.text(",\"scene\":");
    out.text(scene.dump());
  }
  out.text(",\"section\":");
  out.string(section_name(spec.section));
  out.text(",\"stats\":{\"cancelled\":");
  out.boolean(result.cancelled);
  out.text(",\"points\":");
  out.integer(points);
  out.text(",\"runs\":");
  out.integer(static_cast<long>(result.runs.size()));
  out.text(",\"threads\":");
  out.integer(result.threads);
  out.text(",\"wall_ms\":");
  out.number(result.wall_ms);
  out.text("}}");
  return out.finish();
}

}  // namespace

bool write_sweep_result_json(const SweepSpec& spec, const SweepResult& result, const TextSink& sink,
                             const json& scene) {
  Pieces out(sink);
  write_head(out, spec, result);
  if (!write_columns(out, result)) return false;
  return write_tail(out, spec, result, scene);
}

bool write_sweep_summary_json(const SweepSpec& spec, const SweepResult& result,
                              const TextSink& sink) {
  Pieces out(sink);
  write_head(out, spec, result);
  return write_tail(out, spec, result, nullptr);
}

std::string sweep_result_text(const SweepSpec& spec, const SweepResult& result, const json& scene) {
  return whole_text(
      [&](const TextSink& sink) { return write_sweep_result_json(spec, result, sink, scene); });
}

json sweep_result_json(const SweepSpec& spec, const SweepResult& result, const json& scene) {
  return json::parse(sweep_result_text(spec, result, scene));
}

std::optional<SweepView> sweep_plot_kind(const std::string& name, const SweepSpec& spec) {
  if (name.empty() && spec.classify_attractor) return SweepView::basins;
  if (name.empty()) return spec.axis2 ? SweepView::regime_map : SweepView::bifurcation;
  if (name == "bifurcation") return SweepView::bifurcation;
  if (name == "section") return SweepView::section;
  if (name == "impact_map") return SweepView::impact_map;
  if (name == "regime_map") return SweepView::regime_map;
  if (name == "lyapunov") return SweepView::lyapunov;
  if (name == "lyapunov_map") return SweepView::lyapunov_map;
  if (name == "basins") return SweepView::basins;
  return std::nullopt;
}

namespace {

// One line per section point of the run, as in write_sweep_result_csv; `attractor` the value of
// the last column when it is written (a sweep that classifies attractors).
void write_run_rows(Pieces& out, const SweepRun& run, std::optional<int> attractor) {
  for (const SectionPoint& p : run.points) {
    out.digits17(run.value);
    out.text(",");
    out.digits17(run.value2);
    out.text(",");
    out.integer(run.start);
    out.text(",");
    out.integer(run.direction);
    out.text(",");
    out.integer(p.pellet);
    for (double x : {p.t, p.phi, p.dphi, p.phase}) {
      out.text(",");
      out.digits17(x);
    }
    out.text(",");
    out.integer(p.limiter);
    out.text(p.trusted ? ",1," : ",0,");
    out.integer(run.period);
    out.text(",");
    out.digits17(run.impacts_per_period);
    // Empty without an exponent, "-inf" where every perturbation dies (strtod reads it).
    out.text(",");
    if (run.lyapunov) out.digits17(*run.lyapunov);
    if (attractor) {
      out.text(",");
      out.integer(*attractor);
    }
    out.text("\n");
  }
}

// A header cell as CSV quotes it: within double quotes, its quotes doubled, when it holds a
// comma, a quote or a line break (a field path does not, but the header must stay one row).
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

std::array<std::string, 2> sweep_value_names(const SweepSpec& spec) {
  return {spec.axis.parameter, spec.axis2 ? spec.axis2->parameter : std::string("value2")};
}

std::string sweep_csv_header(const SweepSpec& spec) {
  const std::array<std::string, 2> names = sweep_value_names(spec);
  return csv_cell(names[0]) + "," + csv_cell(names[1]) +
         ",start,direction,pellet,t,phi,dphi,phase,limiter,trusted,period,impacts_per_period,"
         "lyapunov" +
         (spec.classify_attractor ? ",attractor\n" : "\n");
}

std::string sweep_run_csv(const SweepRun& run, std::optional<int> attractor) {
  return whole_text([&](const TextSink& sink) {
    Pieces out(sink);
    write_run_rows(out, run, attractor);
    return out.finish();
  });
}

bool write_sweep_result_csv(const SweepSpec& spec, const SweepResult& result,
                            const TextSink& sink) {
  Pieces out(sink);
  out.text(sweep_csv_header(spec));
  for (const SweepRun& run : result.runs) {
    if (!out.ok()) return false;
    write_run_rows(out, run,
                   spec.classify_attractor ? std::optional<int>(run.attractor) : std::nullopt);
  }
  return out.finish();
}

std::string sweep_result_csv(const SweepSpec& spec, const SweepResult& result) {
  return whole_text(
      [&](const TextSink& sink) { return write_sweep_result_csv(spec, result, sink); });
}

}  // namespace vibro
