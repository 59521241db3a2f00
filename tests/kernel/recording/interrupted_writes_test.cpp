// Recordings survive interruption (issue 17, D2): a writer killed at any byte,
// or stopped by a full disk, leaves every earlier event readable.
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "kernel/recording/random_recording.hpp"
#include "sketchlab/io/warning.hpp"
#include "sketchlab/recording/event_json.hpp"
#include "sketchlab/recording/recording_reader.hpp"
#include "sketchlab/recording/recording_writer.hpp"

using namespace sketchlab;
namespace fs = std::filesystem;

namespace {

// Collects warnings for the lifetime of the object.
struct WarningCapture {
  std::vector<std::string> messages;
  WarningSink previous;
  WarningCapture() {
    previous = set_warning_sink([this](const std::string& m) { messages.push_back(m); });
  }
  ~WarningCapture() { set_warning_sink(std::move(previous)); }
};

// Long strokes, as in the reproducer W1: a 200-sample stroke is a ~15 KB line.
Recording long_strokes(int strokes) {
  Recording rec;
  rec.header.units = "m";
  double t = 0.0;
  for (int k = 0; k < strokes; ++k) {
    Stroke s;
    s.id = static_cast<StrokeId>(k + 1);
    s.layer = Layer::shape;
    for (int i = 0; i < 200; ++i) {
      Sample smp;
      smp.position = Vec3(0.001 * i + 0.1 * k, 0.123456789 * std::sin(0.1 * i), 0.3 + 1e-5 * i * k);
      smp.time = t += 0.011;
      smp.pressure = 0.5 + 0.002 * i;
      s.samples.push_back(smp);
    }
    rec.events.push_back(Event{t, StrokeEvent{s}});
    rec.events.push_back(Event{t, UndoEvent{}});
  }
  return rec;
}

std::string text_of(const Recording& rec) {
  std::ostringstream out;
  write_recording(out, rec);
  return out.str();
}

std::string file_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The events whose lines end (newline included) within the first n bytes.
std::size_t complete_events(const std::string& text, std::size_t n) {
  std::size_t lines = 0;
  for (std::size_t i = 0; i < n; ++i) lines += text[i] == '\n';
  return lines == 0 ? 0 : lines - 1;
}

// Writes `rec` with a RecordingWriter in a child process whose file size is
// limited to `limit` bytes. With SIGXFSZ at its default the kernel writes up
// to the limit and then kills the child inside write(2): a kill at byte
// `limit`. With SIGXFSZ ignored, write(2) fails with EFBIG: a full disk.
// Returns the child's wait status.
int write_limited(const fs::path& file, const Recording& rec, std::size_t limit, bool kill) {
  fs::remove(file);
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    if (!kill) signal(SIGXFSZ, SIG_IGN);
    rlimit r{limit, limit};
    setrlimit(RLIMIT_FSIZE, &r);
    try {
      RecordingWriter writer(file, rec.header);
      for (const Event& e : rec.events) {
        try {
          writer.append(e);
        } catch (const std::runtime_error&) {
          // A full disk: the writer cut the partial line off; the session
          // goes on and tries the next (smaller) event.
        }
      }
      writer.close();
    } catch (...) {
      _exit(3);
    }
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

}  // namespace

TEST_CASE("a partial last line is skipped with a warning naming file and line", "[recording][reliability]") {
  const Recording rec = long_strokes(3);
  const std::string text = text_of(rec);
  const std::size_t last_line = text.rfind('\n', text.size() - 2) + 1;
  WarningCapture warnings;

  // Cut inside the last line: everything before it is read.
  std::istringstream cut(text.substr(0, last_line + 7));
  const Recording read = parse_recording(cut, "cut.jsonl");
  CHECK(read.events.size() == rec.events.size() - 1);
  REQUIRE(warnings.messages.size() == 1);
  CHECK_THAT(warnings.messages[0],
             Catch::StartsWith("cut.jsonl:" + std::to_string(rec.events.size() + 1) + ": ") &&
                 Catch::Contains("skipped the last line") && Catch::Contains("interrupted write"));

  // Complete but for its newline: the event is kept, with a warning.
  std::istringstream whole(text.substr(0, text.size() - 1));
  CHECK(parse_recording(whole, "whole.jsonl").events.size() == rec.events.size());
  REQUIRE(warnings.messages.size() == 2);
  CHECK_THAT(warnings.messages[1], Catch::Contains("kept"));

  // A terminated file warns about nothing.
  std::istringstream full(text);
  CHECK(parse_recording(full, "full.jsonl") == rec);
  CHECK(warnings.messages.size() == 2);
}

TEST_CASE("a recording cut at any byte reads back every complete event", "[recording][reliability]") {
  const Recording rec = long_strokes(4);
  const std::string text = text_of(rec);
  const std::size_t header_end = text.find('\n') + 1;
  WarningCapture warnings;
  std::vector<std::size_t> cuts;
  // Every byte around each line end, and every 61st byte elsewhere.
  for (std::size_t i = header_end; i <= text.size(); i += 61) cuts.push_back(i);
  for (std::size_t i = header_end; i < text.size(); ++i)
    if (text[i] == '\n')
      for (std::size_t d = 0; d < 4; ++d) cuts.insert(cuts.end(), {i - d, i + d});
  for (std::size_t n : cuts) {
    if (n < header_end || n > text.size()) continue;
    std::istringstream in(text.substr(0, n));
    const Recording read = parse_recording(in, "cut.jsonl");
    // Complete lines, plus the last event when only its newline is missing.
    const bool only_newline_missing = n < text.size() && text[n] == '\n';
    const std::size_t expect = complete_events(text, n) + (only_newline_missing ? 1 : 0);
    INFO("cut at byte " << n << " of " << text.size());
    REQUIRE(read.events.size() == expect);
    for (std::size_t k = 0; k < expect; ++k) REQUIRE(read.events[k] == rec.events[k]);
  }
  CHECK(cuts.size() > 200);
}

TEST_CASE("a writer killed inside write(2) at many offsets loses only the line it was writing",
          "[recording][reliability]") {
  const fs::path file = fs::temp_directory_path() / "sketchlab_test_killed_writer.jsonl";
  const Recording rec = long_strokes(3);
  const std::string text = text_of(rec);
  const std::size_t header_end = text.find('\n') + 1;
  WarningCapture warnings;
  int killed = 0;
  for (int k = 0; k <= 24; ++k) {
    const std::size_t limit = header_end + (text.size() - header_end) * k / 25 + (k % 3);
    const int status = write_limited(file, rec, limit, /*kill=*/true);
    INFO("limit " << limit << " of " << text.size());
    REQUIRE(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGXFSZ);
    ++killed;
    REQUIRE(fs::file_size(file) == limit);
    const Recording read = read_recording(file);
    const bool only_newline_missing = text[limit] == '\n';
    const std::size_t expect = complete_events(text, limit) + (only_newline_missing ? 1 : 0);
    REQUIRE(read.events.size() == expect);
    for (std::size_t e = 0; e < expect; ++e) REQUIRE(read.events[e] == rec.events[e]);
  }
  CHECK(killed == 25);
  fs::remove(file);
}

TEST_CASE("a full disk leaves whole lines only: the failed line is cut off, later ones go on",
          "[recording][reliability]") {
  const fs::path file = fs::temp_directory_path() / "sketchlab_test_full_disk.jsonl";
  const Recording rec = long_strokes(3);  // stroke, undo, stroke, undo, ...
  const std::string text = text_of(rec);
  const std::size_t first_stroke_end = text.find('\n', text.find('\n') + 1) + 1;
  WarningCapture warnings;
  // Room for the first stroke and a few undo lines, not for the second stroke.
  const std::size_t limit = first_stroke_end + 200;
  const int status = write_limited(file, rec, limit, /*kill=*/false);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  const std::string written = file_text(file);
  REQUIRE(!written.empty());
  CHECK(written.back() == '\n');
  const Recording read = read_recording(file);
  CHECK(warnings.messages.empty());
  // The first stroke and every undo fitted; the strokes after it did not.
  REQUIRE(read.events.size() == 4);
  CHECK(read.events[0] == rec.events[0]);
  for (int i = 1; i < 4; ++i) CHECK(std::holds_alternative<UndoEvent>(read.events[i].payload));
  fs::remove(file);
}
