// differential_scan: runs N random scenes through every check of the instrument (checks.h) and
// prints how many disagree, by class. Each failing scene is written to --out as scene JSON
// whose "description" says what failed, and findings.jsonl there lists every finding with its
// conditioning numbers. Scene i of seed S is the same whatever --jobs is, so a failure found in
// a large scan is re-run alone with --first i --count 1.
//
//   differential_scan --count 100000 --seed 1 --out /tmp/scan --jobs 2
#include <rapidcheck.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/run/validate.h"
#include "tests/differential/checks.h"
#include "tests/differential/minimize.h"

namespace {

using namespace vibro;
using namespace vibro::differential;

struct Args {
  long count = 1000;
  long first = 0;
  std::uint64_t seed = 1;
  std::string out;
  int jobs = 1;
  bool shrink = false;  // shrink the first scene of each signature (needs --out)
  bool trust = false;   // compare only what the runs vouch for (before stats.trusted_until)
  bool dump = false;    // write every scene to --out, failing or not (to look at one by index)
};

[[noreturn]] void usage() {
  std::cerr << "usage: differential_scan --count N [--seed S] [--first I] [--out DIR [--shrink]] "
               "[--jobs J] [--trust] [--dump]\n";
  std::exit(2);
}

Args parse(int argc, char** argv) {
  Args a;
  for (int k = 1; k < argc; ++k) {
    const std::string key = argv[k];
    if (key == "--shrink" || key == "--trust" || key == "--dump") {
      (key == "--shrink" ? a.shrink : key == "--trust" ? a.trust : a.dump) = true;
      continue;
    }
    if (k + 1 >= argc) usage();
    const char* v = argv[++k];
    if (key == "--count")
      a.count = std::atol(v);
    else if (key == "--first")
      a.first = std::atol(v);
    else if (key == "--seed")
      a.seed = std::strtoull(v, nullptr, 10);
    else if (key == "--out")
      a.out = v;
    else if (key == "--jobs")
      a.jobs = std::max(1, std::atoi(v));
    else
      usage();
  }
  return a;
}

struct Outcome {
  bool invalid = false;  // refused by validate_model (never, by construction)
  bool incomplete = false;
  std::vector<Finding> findings;
  // Worst |Δt|/(rtol·(T0 + t)) of every agreeing comparison: the spread of event times that
  // TimeTolerance::kFactor must cover. `across_methods`: against dop853; else against rtol/10.
  struct Spread {
    bool across_methods;
    Method method;
    double rtol;
    double ratio;
  };
  std::vector<Spread> spreads;
  int runs = 0, trusted_to_end = 0;  // with --trust: runs that vouch for all their events
};

Outcome check_scene(const RandomScene& scene, bool trust) {
  Outcome o;
  if (validate_model(scene.model)) {
    o.invalid = true;
    return o;
  }
  SceneRuns runs(scene, trust);
  for (double rtol : {1e-9, 1e-10, 1e-11, 1e-12}) {
    if (incomplete(runs, rtol)) {
      o.incomplete = true;
      return o;
    }
  }
  for (Method m : kMethods)
    for (double rtol : {1e-9, 1e-10, 1e-11, 1e-12}) {
      if (auto f = physics_fails(runs, m, rtol)) o.findings.push_back(*f);
      const Stats& st = runs.run(m, rtol).stats;
      ++o.runs;
      o.trusted_to_end += st.trusted_until >= st.t_reached;
    }
  for (double rtol : {1e-11, 1e-12}) {
    if (auto f = methods_disagree(runs, rtol)) o.findings.push_back(*f);
    const TimeTolerance tol{rtol, time_scale(scene.model)};
    for (Method m : kMethods) {  // the spread of agreeing times, against dop853
      const Comparison c =
          compare_runs(runs.run(Method::dop853, rtol), runs.run(m, rtol), tol, scene.t_end);
      if (m != Method::dop853 && c.verdict == Verdict::agree)
        o.spreads.push_back({true, m, rtol, c.worst_ratio});
    }
  }
  for (Method m : kMethods)
    for (double rtol : {1e-9, 1e-10}) {
      if (auto f = rtol_disagrees(runs, m, rtol)) o.findings.push_back(*f);
      const Comparison c = compare_runs(runs.run(m, rtol), runs.run(m, rtol / 10),
                                        {rtol, time_scale(scene.model)}, scene.t_end);
      if (c.verdict == Verdict::agree) o.spreads.push_back({false, m, rtol, c.worst_ratio});
    }
  return o;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * v.size()))];
}

// A file name from a signature: "methods: sequence, dop853 odd: release vs collision" ->
// "methods-sequence-dop853-odd-release-vs-collision".
std::string slug(const std::string& signature) {
  std::string out;
  for (char c : signature) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      out += c;
    else if (!out.empty() && out.back() != '-')
      out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

void write_scene(const std::string& path, const RandomScene& scene,
                 const std::vector<Finding>& findings) {
  std::string description;
  for (const Finding& f : findings) description += (description.empty() ? "" : " | ") + describe(f);
  if (description.size() > 2000) description.resize(2000);  // the scene reader's limit
  std::ofstream(path) << scene_json_text(scene, Method::automatic, 1e-11, description) << "\n";
}

// The scene shrunk to a small one with the finding's signature, and the finding it then gives.
std::pair<RandomScene, Finding> shrink(const RandomScene& scene, const Finding& finding) {
  const RandomScene small = minimize(scene, finding);
  return {small, check_again(small, finding).value_or(finding)};
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  if (!args.out.empty()) std::filesystem::create_directories(args.out);
  std::ofstream jsonl;
  if (!args.out.empty()) jsonl.open(args.out + "/findings.jsonl");

  std::vector<Outcome> outcomes(args.count);
  std::atomic<long> next{0}, done{0};
  std::mutex io;
  const auto started = std::chrono::steady_clock::now();
  auto work = [&] {
    for (long k = next++; k < args.count; k = next++) {
      const long i = args.first + k;
      const RandomScene scene = scene_at(args.seed, i);
      outcomes[k] = check_scene(scene, args.trust);
      const long d = ++done;
      std::lock_guard lock(io);
      if ((!outcomes[k].findings.empty() || args.dump) && !args.out.empty()) {
        for (const Finding& f : outcomes[k].findings)
          jsonl << nlohmann::json{{"scene", i},
                                  {"signature", f.signature},
                                  {"margin", f.margin},
                                  {"isolation", f.isolation},
                                  {"earlier_margin", f.earlier_margin},
                                  {"detail", f.detail}}
                       .dump()
                << "\n";
        write_scene(
            args.out + "/scene-" + std::to_string(args.seed) + "-" + std::to_string(i) + ".json",
            scene, outcomes[k].findings);
      }
      if (d % 1000 == 0) std::cerr << d << " scenes\n";
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < args.jobs; ++j) threads.emplace_back(work);
  for (std::thread& t : threads) t.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  // Scenes per class and per signature (a scene counts once in each), with the first example.
  long invalid = 0, incomplete_count = 0, failing = 0, runs = 0, trusted_to_end = 0;
  std::map<std::string_view, long> by_class;
  std::map<std::string, std::pair<long, long>> by_signature;  // count, first scene index
  std::vector<double> method_ratios, rtol_ratios;
  std::ofstream csv;
  if (!args.out.empty()) {
    csv.open(args.out + "/spreads.csv");
    csv << "scene,check,method,rtol,ratio\n";
  }
  for (long k = 0; k < args.count; ++k) {
    const Outcome& o = outcomes[k];
    invalid += o.invalid;
    incomplete_count += o.incomplete;
    runs += o.runs;
    trusted_to_end += o.trusted_to_end;
    failing += !o.findings.empty();
    std::set<std::string_view> classes;
    std::set<std::string> signatures;
    for (const Finding& f : o.findings) {
      classes.insert(class_name(f.cls));
      signatures.insert(f.signature);
    }
    for (std::string_view c : classes) ++by_class[c];
    for (const std::string& sig : signatures) {
      auto [it, fresh] = by_signature.try_emplace(sig, 0, args.first + k);
      ++it->second.first;
    }
    for (const Outcome::Spread& s : o.spreads) {
      (s.across_methods ? method_ratios : rtol_ratios).push_back(s.ratio);
      if (csv.is_open())
        csv << args.first + k << "," << (s.across_methods ? "methods" : "rtol") << ","
            << method_name(s.method) << "," << s.rtol << "," << s.ratio << "\n";
    }
  }
  std::cout << "scenes " << args.count << " (seed " << args.seed << ", first " << args.first
            << ") in " << seconds << " s, " << args.count / seconds << " scenes/s\n"
            << "invalid (refused by validate_model) " << invalid
            << "\nincomplete (stopped at their bounds on work, not checked) " << incomplete_count
            << "\nfailing " << failing << "\n";
  if (args.trust)
    std::cout << "runs trusted to their end " << trusted_to_end << " of " << runs << "\n";
  for (const auto& [c, n] : by_class) std::cout << "  " << c << ": " << n << "\n";
  std::cout << "by signature (scenes, first scene):\n";
  for (const auto& [sig, n] : by_signature)
    std::cout << "  " << n.first << "  " << sig << "  (scene " << n.second << ")\n";
  std::cout << "agreeing event times, |dt|/(rtol (T0 + t)), worst per comparison:\n";
  for (const auto& [what, r] :
       {std::pair{"  methods", &method_ratios}, {"  rtol/10", &rtol_ratios}})
    std::cout << what << ": median " << percentile(*r, 0.5) << ", 99% " << percentile(*r, 0.99)
              << ", 99.9% " << percentile(*r, 0.999) << ", max " << percentile(*r, 1.0) << "\n";

  if (args.shrink && !args.out.empty()) {
    for (const auto& [sig, n] : by_signature) {
      const long i = n.second;
      for (const Finding& f : outcomes[i - args.first].findings) {
        if (f.signature != sig) continue;
        const auto [small, finding] = shrink(scene_at(args.seed, i), f);
        const std::string path = args.out + "/min-" + slug(sig) + ".json";
        write_scene(path, small, {finding});
        std::cout << "shrunk scene " << i << " to " << path << "\n";
        break;
      }
    }
  }
  return 0;
}
