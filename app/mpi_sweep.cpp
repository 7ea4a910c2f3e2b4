#include "app/mpi_sweep.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "core/analysis/attractors.h"
#include "io/sweep_wire.h"

namespace vibro {
namespace {

constexpr int kRequestTag = 1;
constexpr int kReplyTag = 100;  // + the worker's slot on its rank
constexpr int kMaxChunk = 256;  // chains: small enough that a checkpoint stays current

// What a crash reports: per worker slot, the run it is in, written before the run starts (a
// signal handler may not format).
constexpr int kMaxSlots = 1024;
char g_running[kMaxSlots][320];
std::size_t g_running_length[kMaxSlots];
thread_local int t_slot = -1;

extern "C" void on_crash(int signal) {
  if (t_slot >= 0 && g_running_length[t_slot] > 0) {
    [[maybe_unused]] const auto n =
        write(STDERR_FILENO, g_running[t_slot], g_running_length[t_slot]);
  } else {
    static const char what[] = "vibro sweep: a process of the MPI job crashed between runs\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, what, sizeof what - 1);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void on_crashes() {
  for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, on_crash);
}

// A request from a worker: its slot, whether it failed (and why), the chains it finished.
std::string request(int slot, const std::string& failure, const std::string& records) {
  std::string bytes(2 * sizeof(std::int32_t), '\0');
  const std::int32_t head[2] = {slot, static_cast<std::int32_t>(failure.size())};
  std::memcpy(bytes.data(), head, sizeof head);
  return bytes + failure + records;
}

struct Worker {
  const Model& model;
  const SimOptions& options;
  const SweepSpec& spec;
  int rank;
  std::string host;
  int fail_rank;  // the test hook VIBRO_SWEEP_FAIL_RANK: this rank crashes at its first run

  void operator()(int slot) const {
    t_slot = slot;
    auto before_run = [&](double v, double v2) {
      std::string what = "vibro sweep: rank " + std::to_string(rank) + " on " + host +
                         " failed while running " + spec.axis.parameter + " = " + number(v);
      if (spec.axis2) what += ", " + spec.axis2->parameter + " = " + number(v2);
      what += "\n";
      const std::size_t n = std::min(what.size(), sizeof g_running[0]);
      std::memcpy(g_running[slot], what.data(), n);
      g_running_length[slot] = n;
      if (rank == fail_rank) std::abort();
    };
    std::string records;
    for (;;) {
      const std::string ask = request(slot, "", records);
      records.clear();
      MPI_Send(ask.data(), static_cast<int>(ask.size()), MPI_BYTE, 0, kRequestTag, MPI_COMM_WORLD);
      MPI_Message message;
      MPI_Status status;
      MPI_Mprobe(0, kReplyTag + slot, MPI_COMM_WORLD, &message, &status);
      int n = 0;
      MPI_Get_count(&status, MPI_INT, &n);
      std::vector<int> chunk(n);
      MPI_Mrecv(chunk.data(), n, MPI_INT, &message, MPI_STATUS_IGNORE);
      if (chunk.empty()) return;
      for (int c : chunk) {
        try {
          append_chain(records,
                       {c, run_sweep_chain(model, options, spec, c, nullptr, {}, before_run)});
        } catch (const std::exception& e) {
          std::string why(g_running[slot], g_running_length[slot]);
          if (!why.empty()) why.pop_back();
          const std::string failed = request(slot, why + ": " + e.what(), records);
          MPI_Send(failed.data(), static_cast<int>(failed.size()), MPI_BYTE, 0, kRequestTag,
                   MPI_COMM_WORLD);
          return;  // rank 0 ends the job
        }
      }
    }
  }

  static std::string number(double v) {  // the shortest text that reads back as v
    char b[32];
    return {b, std::to_chars(b, b + sizeof b, v).ptr};
  }
};

// Rank 0's dispatcher: answers every worker's request with the next chunk of chains, the
// largest first (a share of what is left) and smaller as the work runs out, so that the last
// chunks are short whatever each run costs; keeps the runs that come back.
struct Coordinator {
  const SweepSpec& spec;
  const SweepControl& control;
  int workers;
  std::vector<SweepRun> runs;
  int cursor = 0;
  long done = 0;

  std::vector<int> next_chunk() {
    const int chains = sweep_chain_count(spec);
    const int want = std::clamp((chains - cursor) / (2 * workers), 1, kMaxChunk);
    std::vector<int> chunk;
    for (; cursor < chains && static_cast<int>(chunk.size()) < want; ++cursor)
      if (!control.skip || !control.skip(cursor)) chunk.push_back(cursor);
    return chunk;
  }

  void operator()() {
    const long total = sweep_runs(spec);
    for (int active = workers; active > 0;) {
      int arrived = 0;
      MPI_Message message;
      MPI_Status status;
      MPI_Improbe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &arrived, &message, &status);
      if (!arrived) {  // polled: a blocking probe would spin a core the workers need
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        continue;
      }
      int n = 0;
      MPI_Get_count(&status, MPI_BYTE, &n);
      std::string bytes(static_cast<std::size_t>(n), '\0');
      MPI_Mrecv(bytes.data(), n, MPI_BYTE, &message, MPI_STATUS_IGNORE);
      std::int32_t head[2];
      std::memcpy(head, bytes.data(), sizeof head);
      const std::string failure = bytes.substr(sizeof head, head[1]);
      for (ChainRuns& chain :
           read_chains(std::string_view(bytes).substr(sizeof head + head[1])).chains) {
        if (control.chain_done) control.chain_done(chain.chain, chain.runs);
        done += static_cast<long>(chain.runs.size());
        if (control.progress) control.progress(done, total);
        if (control.keep_runs)
          for (SweepRun& r : chain.runs) runs.push_back(std::move(r));
      }
      if (!failure.empty()) {
        std::fprintf(stderr, "%s\n", failure.c_str());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
      const std::vector<int> chunk = next_chunk();
      MPI_Send(chunk.data(), static_cast<int>(chunk.size()), MPI_INT, status.MPI_SOURCE,
               kReplyTag + head[0], MPI_COMM_WORLD);
      if (chunk.empty()) --active;
    }
  }
};

}  // namespace

bool mpi_start(int& rank) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (provided < MPI_THREAD_MULTIPLE) {
    std::fprintf(stderr,
                 "vibro sweep: this MPI library cannot let every thread communicate "
                 "(MPI_THREAD_MULTIPLE), which vibro's sweeps need; Open MPI 4 can\n");
    MPI_Finalize();
    return false;
  }
  return true;
}

void mpi_finish() { MPI_Finalize(); }

bool mpi_all_agree(bool ok) {
  int mine = ok ? 1 : 0, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

std::optional<SweepResult> run_sweep_mpi(const Model& model, const SimOptions& options,
                                         const SweepSpec& spec, const SweepControl& control) {
  const auto t0 = std::chrono::steady_clock::now();
  int rank = 0, threads = std::clamp(control.threads, 1, kMaxSlots), workers = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Allreduce(&threads, &workers, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  char host[128] = "?";
  gethostname(host, sizeof host - 1);
  const char* fail = std::getenv("VIBRO_SWEEP_FAIL_RANK");
  const Worker worker{model, options, spec, rank, host, fail ? std::atoi(fail) : -1};
  on_crashes();

  Coordinator coordinator{spec, control, workers, {}};
  std::thread dispatcher;
  if (rank == 0) dispatcher = std::thread(std::ref(coordinator));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker, k);
  worker(0);
  for (std::thread& t : pool) t.join();
  if (rank != 0) return std::nullopt;
  dispatcher.join();

  SweepResult result;
  result.runs = std::move(coordinator.runs);
  order_sweep_runs(result.runs);
  if (spec.classify_attractor) classify_attractors(model, result);
  result.threads = workers;
  result.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace vibro
