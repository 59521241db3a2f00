#include "mpi_run.hpp"

#include <mpi.h>
#include <sched.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "progress_line.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/lab/case_result_json.hpp"
#include "sketchlab/recording/event_json.hpp"

namespace sketchlab::cli {
namespace {

using Clock = std::chrono::steady_clock;

// Messages between rank 0 and the others (MPI tags).
enum Tag : int {
  hello = 1,      // rank -> 0: "<pid> <host>"
  cannot_run,     // rank -> 0: why this rank cannot run cases
  request,        // rank -> 0: one of my threads is free
  assign,         // 0 -> rank: a case index (long long), -1: no case left
  result,         // rank -> 0: a finished case (result_message)
  heartbeat,      // rank -> 0: still alive (every second)
  bye,            // rank -> 0: no case left and none running
  finish,         // 0 -> rank: the run is over (int: 1 = a rank died, skip MPI_Finalize)
};

constexpr double heartbeat_s = 1.0;
// A rank says hello once it has planned the run (loaded the experiment,
// hashed the recordings), which may take a while on a busy file system; till
// then it gets at least this long.
constexpr double startup_s = 120.0;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::string receive_text(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}

void send_int(long long value, int to, int tag) { MPI_Send(&value, 1, MPI_LONG_LONG, to, tag, MPI_COMM_WORLD); }

long long receive_int(const MPI_Status& status) {
  long long value = 0;
  MPI_Recv(&value, 1, MPI_LONG_LONG, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return value;
}

std::string processor_name() {
  char name[MPI_MAX_PROCESSOR_NAME];
  int length = 0;
  MPI_Get_processor_name(name, &length);
  return std::string(name, static_cast<std::size_t>(length));
}

void broadcast_text(std::string& text) {
  long long size = static_cast<long long>(text.size());
  MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(size));
  MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
}

// Threads per rank when -j is not given: the CPUs this rank may run on. A
// launcher that binds each rank to its own cores gives disjoint affinity
// masks; one that does not (--bind-to none) gives every rank the whole host,
// then shared among the ranks on it that run cases (rank 0 runs none).
int default_jobs(int rank) {
  cpu_set_t set;
  CPU_ZERO(&set);
  const int affinity = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 0;
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  MPI_Comm local;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &local);
  int local_size = 1, has_rank0 = rank == 0 ? 1 : 0, local_rank0 = 0;
  MPI_Comm_size(local, &local_size);
  MPI_Allreduce(&has_rank0, &local_rank0, 1, MPI_INT, MPI_MAX, local);
  MPI_Comm_free(&local);
  if (affinity > 0 && affinity < cores) return affinity;
  return std::max(1, cores / std::max(1, local_size - local_rank0));
}

// What rank 0 needs of a case run elsewhere: its record and, for the
// pictures, its final sketch (network as sketch.json, strokes as
// recording lines).
std::string result_message(std::size_t index, const CaseResult& c, const std::optional<Sketch>& sketch) {
  nlohmann::json m{{"index", index}, {"result", case_result_to_json(c)}};
  if (sketch) {
    m["sketch"] = sketch_to_json(*sketch);
    std::string strokes;
    for (const auto& [id, stroke] : sketch->strokes) try {
        strokes += to_json_line(Event{0.0, StrokeEvent{stroke}}) + "\n";
      } catch (const std::invalid_argument&) {
        // Not writable as a recording line: the picture goes without it.
      }
    m["strokes"] = strokes;
  }
  return m.dump();
}

std::size_t read_result_message(const std::string& text, CaseResult& c, std::optional<Sketch>& sketch) {
  const auto m = nlohmann::json::parse(text);
  const auto index = m.at("index").get<std::size_t>();
  case_result_from_json(m.at("result").get<std::string>(), "case record from a rank", c);
  if (m.contains("sketch")) {
    sketch = parse_sketch_json(m.at("sketch").get<std::string>(), "case sketch from a rank");
    const std::string strokes = m.at("strokes").get<std::string>();
    for (std::size_t a = 0, b; a < strokes.size(); a = b + 1) {
      b = strokes.find('\n', a);
      const Event e = event_from_json_line(std::string_view(strokes).substr(a, b - a));
      const Stroke& s = std::get<StrokeEvent>(e.payload).stroke;
      sketch->strokes.emplace(s.id, s);
    }
  }
  return index;
}

// Runs cases on `jobs` threads; the calling thread hands them in and takes
// the finished ones out (it alone talks MPI).
class CasePool {
 public:
  CasePool(const RunPlan& plan, const PluginHost& host, const RunOptions& options, int jobs) {
    for (int j = 0; j < jobs; ++j)
      threads_.emplace_back([this, &plan, &host, &options] {
        for (;;) {
          std::size_t index = 0;
          {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || !todo_.empty(); });
            if (todo_.empty()) return;
            index = todo_.front();
            todo_.pop_front();
          }
          std::optional<Sketch> sketch;
          const CaseResult c = run_case(plan, index, host, options, &sketch);
          std::string message = result_message(index, c, sketch);
          std::lock_guard lock(mutex_);
          done_.push_back(std::move(message));
        }
      });
  }
  ~CasePool() {
    {
      std::lock_guard lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : threads_) t.join();
  }
  void add(std::size_t index) {
    {
      std::lock_guard lock(mutex_);
      todo_.push_back(index);
    }
    wake_.notify_one();
  }
  std::vector<std::string> take_done() {
    std::lock_guard lock(mutex_);
    return std::exchange(done_, {});
  }

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::size_t> todo_;
  std::vector<std::string> done_;
  bool stop_ = false;
  std::vector<std::thread> threads_;
};

// Ranks 1..N-1: ask for cases while a thread is free, run them, send them
// back; a heartbeat every second. Returns whether a rank died (rank 0's
// final word).
bool run_cases(const RunPlan* plan, const std::string& cannot, const PluginHost& host, const RunOptions& options,
               int jobs) {
  send_text(std::to_string(getpid()) + " " + processor_name(), 0, hello);
  if (!plan) {
    send_text(cannot, 0, cannot_run);
  } else {
    CasePool pool(*plan, host, options, jobs);
    int requested = 0, running = 0;
    bool no_more = false;
    auto last_sent = Clock::now();
    for (;;) {
      for (; !no_more && running + requested < jobs; ++requested) send_int(0, 0, request);
      int flag = 0;
      MPI_Status status;
      for (MPI_Iprobe(0, assign, MPI_COMM_WORLD, &flag, &status); flag;
           MPI_Iprobe(0, assign, MPI_COMM_WORLD, &flag, &status)) {
        const long long index = receive_int(status);
        --requested;
        if (index < 0) {
          no_more = true;
        } else {
          pool.add(static_cast<std::size_t>(index));
          ++running;
        }
      }
      for (const auto& message : pool.take_done()) {
        send_text(message, 0, result);
        --running;
        last_sent = Clock::now();
      }
      if (no_more && running == 0 && requested == 0) break;
      if (seconds_since(last_sent) > heartbeat_s) {
        send_int(0, 0, heartbeat);
        last_sent = Clock::now();
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    send_int(0, 0, bye);
  }
  MPI_Status status;
  MPI_Probe(0, finish, MPI_COMM_WORLD, &status);
  return receive_int(status) != 0;
}

// The message rank 0 leaves when the launcher ends the job (SIGTERM), e.g.
// because a rank died and the job was not started with --enable-recovery.
std::string* terminated_message = nullptr;

extern "C" void on_terminate(int) {
  if (terminated_message) {
    [[maybe_unused]] const auto n = write(STDERR_FILENO, terminated_message->data(), terminated_message->size());
  }
  _exit(143);
}

struct RankState {
  std::string host = "?";
  pid_t pid = 0;
  bool checkable = false;  // on rank 0's host, in its PID namespace: kill(pid, 0) tells
  Clock::time_point heard;
  std::set<std::size_t> running;
  enum { starting, working, finished, gone } state = starting;
};

// Rank 0: hands out the cases, gathers them, watches the ranks.
RunSummary coordinate(RunPlan plan, int size, const PluginHost& host, const RunOptions& options,
                      const MpiRunOptions& mpi, ProgressLine& progress, std::vector<std::string>& lost,
                      Clock::time_point start) {
  const std::string my_host = processor_name();
  const std::size_t total = plan.summary.cases.size(), resumed = total - plan.pending.size();
  std::size_t done = resumed, failed = plan.summary.failed() - plan.pending.size(), next = 0;
  std::vector<std::optional<Sketch>> sketches(total);
  std::vector<RankState> ranks(static_cast<std::size_t>(size));
  for (auto& r : ranks) r.heard = Clock::now();
  const auto label = [&](std::size_t i) {
    return plan.summary.cases[i].recording.stem().string() + " x " + plan.summary.cases[i].variant.stack.name;
  };
  const auto report = [&](std::size_t i) {
    if (options.progress) options.progress({done, total, failed, resumed, label(i), seconds_since(start)});
  };
  const auto name = [&](int r) {
    return "rank " + std::to_string(r) + " on " + ranks[static_cast<std::size_t>(r)].host;
  };
  const auto lose = [&](int r, const std::string& why) {
    RankState& s = ranks[static_cast<std::size_t>(r)];
    s.state = RankState::gone;
    progress.finish();
    std::cerr << ("sketchlab: " + name(r) + ": " + why + "\n");  // one write (see cmd_run.cpp)
    lost.push_back(name(r) + ": " + why);
    for (std::size_t i : s.running) {
      CaseResult c;
      c.error = "lost: " + name(r) + " " + why + " while running it (this case or one beside it on that rank; "
                "`sketchlab run --resume " + plan.summary.run_dir.string() + "` runs it again)";
      set_case_result(plan, i, std::move(c));
      ++done;
      ++failed;
      report(i);
    }
    s.running.clear();
  };
  auto last_check = Clock::now();
  const auto active = [&] {
    for (int r = 1; r < size; ++r)
      if (ranks[static_cast<std::size_t>(r)].state < RankState::finished) return true;
    return false;
  };
  while (active()) {
    int flag = 0;
    MPI_Status status;
    for (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status); flag;
         MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status)) {
      const int from = status.MPI_SOURCE;
      RankState& s = ranks[static_cast<std::size_t>(from)];
      s.heard = Clock::now();
      switch (status.MPI_TAG) {
        case hello: {
          const std::string text = receive_text(status);
          const auto space = text.find(' ');
          s.pid = static_cast<pid_t>(std::stol(text.substr(0, space)));
          s.host = text.substr(space + 1);
          s.checkable = s.host == my_host && ::kill(s.pid, 0) == 0;
          if (s.state == RankState::starting) s.state = RankState::working;
          break;
        }
        case cannot_run: {
          const std::string why = receive_text(status);
          progress.finish();
          std::cerr << ("sketchlab: " + name(from) + ": cannot run cases: " + why + "\n");
          lost.push_back(name(from) + ": cannot run cases: " + why);
          s.state = RankState::finished;  // it waits for the end of the run
          break;
        }
        case request: {
          receive_int(status);
          if (s.state == RankState::gone) break;  // declared dead; ignore a late word
          if (next < plan.pending.size()) {
            const std::size_t i = plan.pending[next++];
            s.running.insert(i);
            send_int(static_cast<long long>(i), from, assign);
            report(i);
          } else {
            send_int(-1, from, assign);
          }
          break;
        }
        case result: {
          CaseResult c;
          std::optional<Sketch> sketch;
          const std::size_t i = read_result_message(receive_text(status), c, sketch);
          if (!s.running.erase(i)) break;  // from a rank already declared dead
          ++done;
          failed += !c.ok;
          set_case_result(plan, i, std::move(c));
          sketches[i] = std::move(sketch);
          report(i);
          break;
        }
        case heartbeat:
          receive_int(status);
          break;
        case bye:
          receive_int(status);
          if (s.state != RankState::gone) s.state = RankState::finished;
          break;
        default:
          receive_text(status);
      }
    }
    if (seconds_since(last_check) > 0.2) {
      last_check = Clock::now();
      for (int r = 1; r < size; ++r) {
        RankState& s = ranks[static_cast<std::size_t>(r)];
        if (s.state >= RankState::finished) continue;
        if (s.checkable && ::kill(s.pid, 0) != 0 && errno == ESRCH)
          lose(r, "died (its process " + std::to_string(s.pid) + " is gone)");
        else if (const double limit = s.state == RankState::starting ? std::max(mpi.rank_timeout_s, startup_s)
                                                                       : mpi.rank_timeout_s;
                 seconds_since(s.heard) > limit)
          lose(r, "died (silent for " + std::to_string(static_cast<int>(limit)) + " s)");
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  // A rank lost before it asked for its cases leaves them unassigned: the
  // others have finished, so they stay for --resume.
  for (; next < plan.pending.size(); ++next) {
    CaseResult c;
    c.error = "not run: no rank was left to run it (`sketchlab run --resume " + plan.summary.run_dir.string() +
              "` runs it)";
    set_case_result(plan, plan.pending[next], std::move(c));
  }
  const long long any_lost = lost.empty() ? 0 : 1;
  for (int r = 1; r < size; ++r)
    if (ranks[static_cast<std::size_t>(r)].state != RankState::gone) send_int(any_lost, r, finish);
  progress.finish();
  return finish_run(std::move(plan), std::move(sketches), host, options, seconds_since(start));
}

}  // namespace

void end_mpi_job(const std::vector<std::string>& lost, int exit_code) {
  if (lost.empty()) return;
  std::cout.flush();
  std::cerr.flush();
  MPI_Abort(MPI_COMM_WORLD, exit_code);
}

std::optional<RunSummary> run_over_mpi(const ExperimentConfig& config, const PluginHost& host, RunOptions options,
                                       const MpiRunOptions& mpi, ProgressLine& progress,
                                       std::vector<std::string>& lost) {
  const auto start = Clock::now();
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  // A dead peer must not abort rank 0: sends to it return an error, ignored.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int jobs = options.jobs > 0 ? options.jobs : default_jobs(rank);
  options.jobs = jobs;
  bool skip_finalize = false;
  std::optional<RunSummary> summary;
  if (size == 1) {
    try {
      summary = run_experiment(config, host, options);
    } catch (...) {
      MPI_Finalize();
      throw;
    }
  } else if (rank == 0) {
    std::optional<RunPlan> plan;
    std::string error, dir;
    try {
      plan = plan_run(config, host, options);
      dir = plan->summary.run_dir.string();
    } catch (const std::exception& e) {
      error = e.what();
    }
    // The folder and the number of cases, which every rank must see alike;
    // empty: the run cannot start.
    if (plan) dir += "\n" + std::to_string(plan->summary.cases.size());
    broadcast_text(dir);
    if (!plan) {
      MPI_Finalize();
      throw std::runtime_error(error);
    }
    const std::string run_dir = plan->summary.run_dir.string();
    std::string message = "sketchlab: the job was ended before every case had run; the finished ones are in " +
                          run_dir + ": `sketchlab run --resume " + run_dir +
                          "` runs the others (a rank that dies ends an MPI job unless it was started with "
                          "`mpirun --enable-recovery` or `srun -K0 --no-kill`)\n";
    terminated_message = &message;
    std::signal(SIGTERM, on_terminate);
    summary = coordinate(std::move(*plan), size, host, options, mpi, progress, lost, start);
    std::signal(SIGTERM, SIG_DFL);
    terminated_message = nullptr;
    skip_finalize = !lost.empty();
  } else {
    std::string dir;
    broadcast_text(dir);
    if (!dir.empty()) {
      std::optional<RunPlan> plan;
      std::string cannot;
      const auto newline = dir.find('\n');
      try {
        plan = plan_run(config, host, options, false, dir.substr(0, newline));
        const std::string cases = std::to_string(plan->summary.cases.size()), expected = dir.substr(newline + 1);
        if (cases != expected)
          throw std::runtime_error("the experiment has " + cases + " cases here and " + expected +
                                   " on rank 0 (are the experiment and recordings the same files on every host?)");
      } catch (const std::exception& e) {
        plan.reset();
        cannot = e.what();
      }
      skip_finalize = run_cases(plan ? &*plan : nullptr, cannot, host, options, jobs);
    }
  }
  // MPI_Finalize waits for every rank, a dead one too: skip it then (the
  // launcher reports the ranks that ended without it).
  if (!skip_finalize) MPI_Finalize();
  return summary;
}

}  // namespace sketchlab::cli
