// `vibro sweep SCENE | --preset NAME [-o OUT.json|.csv|.png|.svg|.pdf]... [--threads N] [--plot
// KIND]
// [--pellet I] [--coordinate dphi|phi] [--resume]`: runs the scene's sweep on every core (or N
// threads), and under mpirun or srun on every rank's (app/mpi_sweep.h); writes its points (JSON
// to stdout without -o) or draws it (a bifurcation diagram, a section, an impact map, a regime
// map, or its largest Lyapunov exponents as a line or a map), to every -o given from the one run
// (`vibro plot` redraws a saved OUT.json later), and shows a progress bar with the
// time left on stderr when that is a terminal. With -o, finished chains are kept in OUT.partial
// as they finish, so a sweep that stops (a failed rank, a killed job, Ctrl-C) resumes with
// --resume; OUT.partial goes once OUT is written. A checkpoint that cannot be written (a full
// disk) stops the sweep; OUT is replaced only by a whole new file (io/whole_file.h).
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "app/commands.h"
#include "app/mpi_sweep.h"
#include "app/progress_bar.h"
#include "app/scene_options.h"
#include "app/sweep_plot_options.h"
#include "app/usage.h"
#include "core/analysis/attractors.h"
#include "core/analysis/sweep.h"
#include "io/scene_json.h"
#include "io/sweep_checkpoint.h"
#include "io/sweep_csv_stream.h"
#include "io/sweep_json.h"
#include "io/whole_file.h"
#include "render/figure.h"

namespace vibro {
namespace {

// The command line of a sweep, as parsed.
struct SweepOptions {
  SceneOutput job;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  SweepPlotOptions plot;
  bool resume = false;
};

// A sweep as the command line asks for it, checked.
struct SweepJob {
  Scene scene;
  std::vector<std::string> outs;  // every one written from the one sweep
  int threads = 1;
  SweepPlot plot;
  std::optional<Checkpoint> resumed;  // rank 0 only
  // The file the finished chains are kept beside (its .partial): the first output.
  std::string checkpointed() const { return outs.empty() ? std::string() : outs.front(); }
};

// Reads the scene and checks the options against it; on rank 0 (`root`) also reads the
// checkpoint. On failure prints why and returns nothing with the exit code in `code`.
std::optional<SweepJob> prepare(const SweepOptions& o, bool root, int& code) {
  code = 2;
  auto scene = load_scene(o.job.scene);
  if (!scene) return std::nullopt;
  SweepJob job;
  job.scene = std::move(*scene);
  job.outs = o.job.outs;
  job.threads = o.threads;
  if (!job.scene.sweep) {
    print_error("sweep", "the scene has no sweep: add one (API.md, \"Sweeps\")");
    return std::nullopt;
  }
  if (!outputs_named(job.outs, {".json", ".csv", ".png", ".svg", ".pdf"},
                     "OUT.json, OUT.csv, OUT.png, OUT.svg or OUT.pdf"))
    return std::nullopt;
  // Before the sweep runs, not after it: a plot of what the sweep does not compute.
  const bool draws = std::any_of(job.outs.begin(), job.outs.end(), [](const std::string& out) {
    return image_format_of_file(out).has_value();
  });
  const auto plot = sweep_plot_of(o.plot, job.scene, draws);
  if (!plot) return std::nullopt;
  job.plot = *plot;
  if (o.resume && job.outs.empty()) {
    print_error("--resume", "resumes the sweep of an output file: name it with -o");
    return std::nullopt;
  }
  if (!root || job.outs.empty()) return job;
  const std::string partial = checkpoint_path(job.checkpointed());
  if (o.resume) {
    auto read = read_checkpoint(partial, job.scene);
    if (auto* why = std::get_if<std::string>(&read)) {
      print_error("--resume", *why);
      return std::nullopt;
    }
    job.resumed = std::move(std::get<Checkpoint>(read));
  } else if (std::error_code ec; std::filesystem::exists(partial, ec)) {
    print_error("-o", partial +
                          " holds the finished part of an earlier run of this sweep: "
                          "--resume continues it; remove it to start afresh");
    return std::nullopt;
  }
  return job;
}

// The result as the output `out` names it: drawn, CSV or JSON ("" : JSON). Empty after printing
// why when it cannot be drawn.
std::optional<std::string> result_text(const SweepJob& job, const SweepResult& result,
                                       const std::string& out) {
  const SweepSpec& spec = *job.scene.sweep;
  if (const auto image = image_format_of_file(out))
    return sweep_image(job.scene, job.plot, result, *image);
  if (out.ends_with(".csv")) return sweep_result_csv(spec, result);
  // With its scene, so that `vibro plot` redraws it from this file alone.
  return sweep_result_text(spec, result, scene_to_json(job.scene)) + "\n";
}

// Draws or writes the result to every output (stdout without one).
int write_result(const SweepJob& job, const SweepResult& result) {
  if (job.outs.empty()) {
    const auto text = result_text(job, result, "");
    std::cout << *text;  // checked once the command ends (app/main.cpp)
    return 0;
  }
  for (const std::string& out : job.outs) {
    const auto text = result_text(job, result, out);
    if (!text) return 1;
    if (const auto problem = write_whole_file(out, *text)) {
      print_error("-o", problem->message + "; it is left as it was, and " +
                            checkpoint_path(job.checkpointed()) +
                            " keeps the finished chains for --resume");
      return 1;
    }
  }
  return 0;
}

// A checkpoint that could not be written stops the sweep: what it holds is all a stop would
// keep. The message says so.
int checkpoint_failed(const CheckpointWriter& checkpoint) {
  print_error("-o", checkpoint.problem()->message + "; the sweep stopped, and the " +
                        std::to_string(checkpoint.chains()) +
                        " chains it holds whole are kept: --resume continues from them");
  return 1;
}

// Puts the streamed CSV in place; the checkpoint goes once it is.
int finish_csv(SweepCsvStream& csv, CheckpointWriter& checkpoint) {
  if (const auto problem = csv.finish()) {
    print_error("-o", problem->message + "; " + checkpoint_path(csv.path()) +
                          " keeps the finished chains for --resume");
    return 1;
  }
  checkpoint.remove();
  return 0;
}

// The sweep on this process's threads, or on every rank's under MPI; rank 0 writes the result.
int run_job(const SweepOptions& o, bool mpi, int rank) {
  int code = 0;
  const std::optional<SweepJob> job = prepare(o, rank == 0, code);
#ifdef VIBRO_HAVE_MPI
  if (mpi && !mpi_all_agree(job.has_value())) return job ? 1 : code;
#endif
  if (!job) return code;
  const SweepSpec& spec = *job->scene.sweep;
  std::optional<CheckpointWriter> checkpoint;
  std::vector<char> done_before;
  if (rank == 0 && !job->outs.empty()) {
    checkpoint.emplace(checkpoint_path(job->checkpointed()), scene_fingerprint(job->scene),
                       job->resumed ? &*job->resumed : nullptr);
    if (const auto problem = checkpoint->problem()) {
      print_error("-o", problem->message);
      return 1;
    }
    done_before.assign(sweep_chain_count(spec), 0);
    if (job->resumed)  // chains in range, each once: read_checkpoint checked them
      for (const ChainRuns& c : job->resumed->chains) done_before[c.chain] = 1;
  }
  ProgressBar bar;
  SweepControl control;
  std::atomic<bool> stop{false};
  control.threads = job->threads;
  control.cancel = &stop;
  if (rank == 0 && isatty(STDERR_FILENO))
    control.progress = [&bar](long done, long total) {
      bar(static_cast<double>(done) / std::max(total, 1L),
          std::to_string(done) + "/" + std::to_string(total) + " runs");
    };
  // A CSV alone is written as the chains finish, the resumed ones first: the runs are not kept.
  std::optional<SweepCsvStream> csv;
  if (checkpoint && job->outs.size() == 1 && job->outs.front().ends_with(".csv")) {
    csv.emplace(job->outs.front(), job->scene.model, spec);
    if (job->resumed)
      for (const ChainRuns& c : job->resumed->chains) csv->add(c.chain, c.runs);
    control.keep_runs = false;
  }
  if (checkpoint) {
    control.skip = [&done_before](int c) { return done_before[c] != 0; };
    control.chain_done = [&checkpoint, &csv, &stop](int c, const std::vector<SweepRun>& runs) {
      if (!checkpoint->add({c, runs})) stop = true;
      if (csv) csv->add(c, runs);
    };
  }
  std::optional<SweepResult> result;
#ifdef VIBRO_HAVE_MPI
  if (mpi) result = run_sweep_mpi(job->scene.model, job->scene.sim, spec, control);
#endif
  if (!mpi) result = run_sweep(job->scene.model, job->scene.sim, spec, control);
  if (rank != 0) return 0;
  if (result->cancelled) return checkpoint_failed(*checkpoint);  // nothing else cancels
  if (csv) return finish_csv(*csv, *checkpoint);
  if (job->resumed) {
    for (const ChainRuns& c : job->resumed->chains)
      result->runs.insert(result->runs.end(), c.runs.begin(), c.runs.end());
    order_sweep_runs(result->runs);
    // The resumed runs and the new ones together: ids over the whole sweep.
    if (spec.classify_attractor) classify_attractors(job->scene.model, *result);
  }
  const int written = write_result(*job, *result);
  if (written == 0 && checkpoint) checkpoint->remove();
  return written;
}

int sweep(const SweepOptions& o) {
  if (!launched_by_mpi()) return run_job(o, false, 0);
#ifdef VIBRO_HAVE_MPI
  int rank = 0;
  if (!mpi_start(rank)) return 1;
  const int code = run_job(o, true, rank);
  mpi_finish();
  return code;
#else
  print_error("mpirun",
              "this vibro was built without MPI, so under mpirun every process would run "
              "the whole sweep: install Open MPI (apt-get install openmpi-bin libopenmpi-dev, or "
              "scripts/setup.sh) and build again");
  return 2;
#endif
}

}  // namespace

Command add_sweep_command(CLI::App& vibro) {
  auto o = std::make_shared<SweepOptions>();
  CLI::App* command = add_scene_command(
      vibro, "sweep",
      "Run the scene's sweep (a bifurcation diagram, regime map, ...) on every core, or over an "
      "MPI job under mpirun or srun",
      "write OUT.json or OUT.csv instead of JSON on stdout, or draw OUT.png, OUT.svg or OUT.pdf; "
      "finished chains are kept in OUT.partial (of the first OUT) until all are written",
      o->job);
  command->add_option("--threads", o->threads, "worker threads (default: one per core)")
      ->transform(integer_in(1, 1024))
      ->type_name("N");
  add_sweep_plot_options(*command, o->plot);
  command->add_flag("--resume", o->resume,
                    "continue the sweep of -o OUT from OUT.partial, left by a run that stopped");
  return {command, [o] { return sweep(*o); }};
}

}  // namespace vibro
