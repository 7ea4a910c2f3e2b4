// `vibro sweep SCENE | --preset NAME [-o OUT.json|.csv|.png|.svg|.pdf] [--threads N] [--plot KIND]
// [--pellet I] [--coordinate dphi|phi] [--resume]`: runs the scene's sweep on every core (or N
// threads), and under mpirun or srun on every rank's (app/mpi_sweep.h); writes its points (JSON
// to stdout without -o) or draws it (a bifurcation diagram, a section, an impact map, a regime
// map, or its largest Lyapunov exponents as a line or a map), and shows a progress bar with the
// time left on stderr when that is a terminal. With -o, finished chains are kept in OUT.partial
// as they finish, so a sweep that stops (a failed rank, a killed job, Ctrl-C) resumes with
// --resume; OUT.partial goes once OUT is written.
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "app/commands.h"
#include "app/mpi_sweep.h"
#include "app/progress_bar.h"
#include "core/sweep.h"
#include "io/sweep_checkpoint.h"
#include "io/sweep_json.h"
#include "render/figure.h"

namespace vibro {
namespace {

void usage_error(const std::string& field, const std::string& message) {
  std::cerr << nlohmann::json{{"error", message}, {"field", field}}.dump() << "\n";
}

// A sweep as the command line asks for it, checked.
struct SweepJob {
  Scene scene;
  std::string out;
  int threads = 1;
  PlotSpec plot;
  std::optional<ImageFormat> image;
  std::optional<Checkpoint> resumed;  // rank 0 only
};

// Reads and checks the arguments; on rank 0 (`root`) also the checkpoint. On failure prints
// why and returns nothing with the exit code in `code`.
std::optional<SweepJob> prepare(const Args& args, bool root, int& code) {
  code = 2;
  std::size_t next = 0;
  auto scene = load_scene(args, next);
  if (!scene) return std::nullopt;
  SweepJob job;
  job.scene = std::move(*scene);
  job.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::string plot_name;
  bool resume = false;
  for (; next < args.size(); ++next) {
    const std::string& a = args[next];
    if ((a == "-o" || a == "--output") && next + 1 < args.size()) {
      job.out = args[++next];
    } else if (a == "--threads" && next + 1 < args.size()) {
      try {
        job.threads = std::stoi(args[++next]);
      } catch (const std::exception&) {
        job.threads = 0;
      }
      if (job.threads < 1 || job.threads > 1024) {
        usage_error("--threads", "must be an integer in [1, 1024]");
        return std::nullopt;
      }
    } else if (a == "--pellet" && next + 1 < args.size()) {
      const std::string& v = args[++next];
      job.plot.pellet = v.size() == 1 && v[0] >= '0' && v[0] <= '9' ? v[0] - '0' : -1;
      if (job.plot.pellet < 0 || job.plot.pellet >= job.scene.model.size()) {
        usage_error("--pellet",
                    "must be a pellet index in 0.." + std::to_string(job.scene.model.size() - 1));
        return std::nullopt;
      }
    } else if (a == "--plot" && next + 1 < args.size()) {
      plot_name = args[++next];
    } else if (a == "--coordinate" && next + 1 < args.size()) {
      const std::string& v = args[++next];
      if (v != "dphi" && v != "phi") {
        usage_error("--coordinate", "must be \"dphi\" or \"phi\"");
        return std::nullopt;
      }
      job.plot.coordinate = v == "phi" ? SectionCoordinate::phi : SectionCoordinate::dphi;
    } else if (a == "--resume") {
      resume = true;
    } else {
      usage_error(a, "is not an option of `vibro sweep`");
      return std::nullopt;
    }
  }
  if (!job.scene.sweep) {
    usage_error("sweep", "the scene has no sweep: add one (API.md, \"Sweeps\")");
    return std::nullopt;
  }
  const auto kind = sweep_plot_kind(plot_name, *job.scene.sweep);
  if (!kind) {
    usage_error("--plot", std::string("must be ") + kSweepPlotNames);
    return std::nullopt;
  }
  job.plot.kind = *kind;
  job.image = image_format_of_file(job.out);
  if (!job.out.empty() && !job.out.ends_with(".json") && !job.out.ends_with(".csv") && !job.image) {
    usage_error("-o", "name the output OUT.json, OUT.csv, OUT.png, OUT.svg or OUT.pdf");
    return std::nullopt;
  }
  // Before the sweep runs, not after it: a plot of what the sweep does not compute.
  if (const auto e =
          job.image ? validate_sweep_plot(job.plot.kind, *job.scene.sweep) : std::nullopt) {
    usage_error(e->field, e->message);
    return std::nullopt;
  }
  if (resume && job.out.empty()) {
    usage_error("--resume", "resumes the sweep of an output file: name it with -o");
    return std::nullopt;
  }
  if (!root || job.out.empty()) return job;
  const std::string partial = checkpoint_path(job.out);
  if (resume) {
    auto read = read_checkpoint(partial, scene_fingerprint(job.scene));
    if (auto* why = std::get_if<std::string>(&read)) {
      usage_error("--resume", *why);
      return std::nullopt;
    }
    job.resumed = std::move(std::get<Checkpoint>(read));
  } else if (std::ifstream(partial)) {
    usage_error("-o", partial + " holds the finished part of an earlier run of this sweep: "
                "--resume continues it; remove it to start afresh");
    return std::nullopt;
  }
  return job;
}

// Draws or writes the result to job.out (stdout without it).
int write_result(const SweepJob& job, const SweepResult& result) {
  std::string text;
  if (job.image) {
    FigureSpec figure;
    figure.width = job.scene.figure.width;
    figure.height = job.scene.figure.height;
    figure.plots = {job.plot};
    const RenderResult drawn = render_figure(figure, job.scene.model, RunResult{}, *job.image,
                                             {nullptr, &*job.scene.sweep, &result});
    if (!drawn.ok()) {
      usage_error(drawn.error->field, drawn.error->message);
      return 1;
    }
    text.assign(drawn.bytes.begin(), drawn.bytes.end());
  } else {
    text = job.out.ends_with(".csv") ? sweep_result_csv(result)
                                     : sweep_result_json(*job.scene.sweep, result).dump() + "\n";
  }
  if (job.out.empty()) {
    std::cout << text;
    return 0;
  }
  std::ofstream file(job.out, std::ios::binary);
  file << text;
  if (!file) {
    usage_error(job.out, "cannot write the file");
    return 1;
  }
  return 0;
}

// The sweep on this process's threads, or on every rank's under MPI; rank 0 writes the result.
int run_job(const Args& args, bool mpi, int rank) {
  int code = 0;
  const std::optional<SweepJob> job = prepare(args, rank == 0, code);
#ifdef VIBRO_HAVE_MPI
  if (mpi && !mpi_all_agree(job.has_value())) return job ? 1 : code;
#endif
  if (!job) return code;
  const SweepSpec& spec = *job->scene.sweep;
  std::optional<CheckpointWriter> checkpoint;
  std::vector<char> done_before;
  if (rank == 0 && !job->out.empty()) {
    checkpoint.emplace(checkpoint_path(job->out), scene_fingerprint(job->scene),
                       job->resumed ? &*job->resumed : nullptr);
    if (!checkpoint->ok()) {
      usage_error("-o", "cannot write " + checkpoint_path(job->out));
      return 1;
    }
    done_before.assign(sweep_chain_count(spec), 0);
    if (job->resumed)
      for (const ChainRuns& c : job->resumed->chains)
        if (c.chain >= 0 && c.chain < static_cast<int>(done_before.size())) done_before[c.chain] = 1;
  }
  ProgressBar bar;
  SweepControl control;
  control.threads = job->threads;
  if (rank == 0 && isatty(STDERR_FILENO))
    control.progress = [&bar](long done, long total) {
      bar(static_cast<double>(done) / std::max(total, 1L),
          std::to_string(done) + "/" + std::to_string(total) + " runs");
    };
  if (checkpoint) {
    control.skip = [&done_before](int c) { return done_before[c] != 0; };
    control.chain_done = [&checkpoint](int c, const std::vector<SweepRun>& runs) {
      checkpoint->add({c, runs});
    };
  }
  std::optional<SweepResult> result;
#ifdef VIBRO_HAVE_MPI
  if (mpi) result = run_sweep_mpi(job->scene.model, job->scene.sim, spec, control);
#endif
  if (!mpi) result = run_sweep(job->scene.model, job->scene.sim, spec, control);
  if (rank != 0) return 0;
  if (job->resumed) {
    for (const ChainRuns& c : job->resumed->chains)
      result->runs.insert(result->runs.end(), c.runs.begin(), c.runs.end());
    order_sweep_runs(result->runs);
  }
  const int written = write_result(*job, *result);
  if (written == 0 && checkpoint) checkpoint->remove();
  return written;
}

}  // namespace

int sweep_command(const Args& args) {
  if (!launched_by_mpi()) return run_job(args, false, 0);
#ifdef VIBRO_HAVE_MPI
  int rank = 0;
  if (!mpi_start(rank)) return 1;
  const int code = run_job(args, true, rank);
  mpi_finish();
  return code;
#else
  usage_error("mpirun", "this vibro was built without MPI, so under mpirun every process would run "
              "the whole sweep: install Open MPI (apt-get install openmpi-bin libopenmpi-dev, or "
              "scripts/setup.sh) and build again");
  return 2;
#endif
}

}  // namespace vibro
