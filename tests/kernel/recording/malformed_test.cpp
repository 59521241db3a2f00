#include <catch2/catch.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sketchlab/recording/recording_reader.hpp"

using namespace sketchlab;

namespace {

const std::string header =
    R"({"format":"sketchlab-recording","version":1,"units":"m","workspace":{"up":[0.0,1.0,0.0],)"
    R"("grid_enabled":false,"grid_spacing":0.25,"grid_origin":[0.0,0.0,0.0],"mirror_enabled":false,)"
    R"("mirror_normal":[1.0,0.0,0.0],"mirror_offset":0.0,"scale":1.0},"source":{"test":"malformed"}})";
const std::string good_stroke =
    R"({"t":1.0,"type":"stroke","id":4,"layer":"shape","workspace_scale":1.0,)"
    R"("samples":[[0.0,0.0,0.0,0.5,1.0],[0.1,0.0,0.0,1.0,1.0]]})";
const std::string undo = R"({"t":2.0,"type":"undo"})";

std::string stroke_with_samples(const std::string& samples) {
  return R"({"t":3.0,"type":"stroke","id":5,"layer":"free","workspace_scale":1.0,"samples":)" +
         samples + "}";
}

// Parses header + good stroke + undo + `line` (line 4) and returns the error.
RecordingError error_for(const std::string& text, const RecordingReadOptions& options = {}) {
  std::istringstream in(text);
  try {
    parse_recording(in, "bad.jsonl", options);
  } catch (const RecordingError& e) {
    return e;
  }
  FAIL("no RecordingError for:\n" << text);
  return RecordingError("", 0, "");
}

RecordingError error_on_line4(const std::string& line) {
  return error_for(header + "\n" + good_stroke + "\n" + undo + "\n" + line + "\n");
}

void check(const RecordingError& e, std::size_t line, const std::vector<std::string>& needles) {
  INFO(e.what());
  CHECK(e.file == "bad.jsonl");
  CHECK(e.line == line);
  const std::string prefix = line ? "bad.jsonl:" + std::to_string(line) + ": " : "bad.jsonl: ";
  CHECK(std::string(e.what()) == prefix + e.reason);
  for (const auto& n : needles) CHECK_THAT(e.reason, Catch::Contains(n));
}

}  // namespace

TEST_CASE("the fixture itself is valid", "[recording][malformed]") {
  std::istringstream in(header + "\n" + good_stroke + "\n" + undo + "\n");
  const Recording r = parse_recording(in, "good.jsonl");
  CHECK(r.events.size() == 2);
  CHECK(r.header.source.at("test") == "malformed");
}

TEST_CASE("bad JSON names the line", "[recording][malformed]") {
  check(error_on_line4(R"({"t":3.0,"type":"undo",})"), 4, {"bad JSON"});
  check(error_on_line4("[1, 2"), 4, {"bad JSON"});
  check(error_for(header + "\n" + "not json\n" + undo + "\n"), 2, {"bad JSON"});
}

TEST_CASE("wrong or missing format and version", "[recording][malformed]") {
  std::string v2 = header;
  v2.replace(v2.find("\"version\":1"), 11, "\"version\":2");
  check(error_for(v2 + "\n"), 1, {"unsupported recording version 2", "supported: 1"});
  std::string other = header;
  other.replace(other.find("sketchlab-recording"), 19, "svg");
  check(error_for(other + "\n"), 1, {"not a sketchlab recording", "\"svg\""});
  check(error_for(undo + "\n"), 1, {"missing field 'format'"});
  std::string no_version = header;
  no_version.replace(no_version.find("\"version\":1,"), 12, "");
  check(error_for(no_version + "\n"), 1, {"missing field 'version'"});
  std::string bad_units = header;
  bad_units.replace(bad_units.find("\"units\":\"m\""), 11, "\"units\":\"cm\"");
  check(error_for(bad_units + "\n"), 1, {"units", "allowed: m, px"});
}

TEST_CASE("NaN-like and absurd numbers are rejected", "[recording][malformed]") {
  // JSON has no NaN literal: it is bad JSON.
  check(error_on_line4(stroke_with_samples("[[NaN,0.0,0.0,3.0,1.0],[0.1,0.0,0.0,3.0,1.0]]")), 4,
        {"bad JSON"});
  check(error_on_line4(stroke_with_samples("[[0.0,null,0.0,3.0,1.0],[0.1,0.0,0.0,3.0,1.0]]")), 4,
        {"samples[0][1]", "must be a number", "null"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,3.0,1.0],[0.1,0.0,\"0\",3.0,1.0]]")), 4,
        {"samples[1][2]", "string"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,1e999,1.0],[0.1,0.0,0.0,3.0,1.0]]")), 4,
        {"bad JSON", "overflow", "1e999"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,3.0,1.0],[1e300,0.0,0.0,3.0,1.0]]")), 4,
        {"samples[1][0]", "absurd"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,3.0,1.5],[0.1,0.0,0.0,3.0,1.0]]")), 4,
        {"samples[0][4]", "pressure", "[0, 1]"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,-3.0,1.0],[0.1,0.0,0.0,3.0,1.0]]")), 4,
        {"samples[0][3]", "negative"});
  check(error_on_line4(R"({"t":null,"type":"undo"})"), 4, {"'t'", "null"});
  check(error_on_line4(R"({"t":3.0,"type":"delete_near","point":[0.0,0.0,0.0],"radius":-1.0})"), 4,
        {"radius", "> 0"});
}

TEST_CASE("empty and degenerate strokes are rejected", "[recording][malformed]") {
  check(error_on_line4(stroke_with_samples("[]")), 4, {"stroke 5 has no samples"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,3.0,1.0]]")), 4, {"at least 2"});
  check(error_on_line4(stroke_with_samples("[[0.5,0.0,0.0,3.0,1.0],[0.5,0.0,0.0,3.0,1.0]]")), 4,
        {"zero length"});
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,3.0],[0.1,0.0,0.0,3.0,1.0]]")), 4,
        {"samples[0]", "5 numbers"});
}

TEST_CASE("refuse_truncated: a last line without its newline says truncated", "[recording][malformed]") {
  const std::string body = header + "\n" + good_stroke + "\n" + undo + "\n";
  RecordingReadOptions refuse;
  refuse.refuse_truncated = true;
  // Interrupted in the middle of a stroke.
  check(error_for(body + R"({"t":3.0,"type":"stroke","id":5,"samp)", refuse), 4,
        {"truncated", "not complete JSON"});
  // Complete JSON but no final newline: still an interrupted write.
  check(error_for(header + "\n" + good_stroke + "\n" + undo, refuse), 3, {"truncated"});
  // A header cut short leaves nothing to read, whatever the options.
  check(error_for(header), 1, {"truncated"});
  check(error_for(header.substr(0, 40)), 1, {"truncated", "not complete JSON"});
}

TEST_CASE("sample times running backwards are refused with the sample named", "[recording][malformed]") {
  check(error_on_line4(stroke_with_samples("[[0.0,0.0,0.0,3.0,1.0],[0.1,0.0,0.0,2.5,1.0]]")), 4,
        {"samples[1][3]", "earlier than the previous sample's 3.0", "must not decrease"});
}

TEST_CASE("unknown event types list the allowed ones", "[recording][malformed]") {
  check(error_on_line4(R"({"t":3.0,"type":"scribble"})"), 4,
        {"unknown event type 'scribble'", "allowed: stroke, undo, redo, delete_near, delete_stroke, "
                                          "mode, workspace, correction, add_patch, delete_patch, "
                                          "reference"});
}

TEST_CASE("missing, mistyped and unknown fields are named", "[recording][malformed]") {
  check(error_on_line4(R"({"t":3.0,"type":"stroke","id":5,"workspace_scale":1.0,"samples":[]})"), 4,
        {"missing field 'layer'", "stroke event"});
  check(error_on_line4(R"({"t":3.0,"type":"delete_stroke"})"), 4, {"missing field 'stroke'"});
  check(error_on_line4(R"({"type":"undo"})"), 4, {"missing field 't'"});
  check(error_on_line4(R"({"t":3.0})"), 4, {"missing field 'type'"});
  check(error_on_line4(R"({"t":3.0,"type":"delete_stroke","stroke":"5"})"), 4,
        {"'stroke'", "non-negative integer", "string"});
  check(error_on_line4(R"({"t":3.0,"type":"delete_stroke","stroke":-5})"), 4,
        {"'stroke'", "negative integer"});
  check(error_on_line4(R"({"t":3.0,"type":"mode","mode":"curvy"})"), 4,
        {"'mode'", "curvy", "scaffold, shape, free, guide, auto"});
  check(error_on_line4(R"({"t":3.0,"type":"undo","extra":1})"), 4, {"unknown field 'extra'"});
  check(error_on_line4(R"({"t":3.0,"type":"reference","stroke":1,"track":"cassie","curve":)"
                       R"({"kind":"bezier","points":[[0.0,0.0,0.0],[1.0,0.0,0.0]],"sharp":[false,false],"closed":false}})"),
        4, {"curve", "control points"});
  check(error_on_line4(R"({"t":3.0,"type":"workspace","workspace":{"up":[0.0,1.0,0.0]}})"), 4,
        {"missing field 'grid_enabled' in workspace"});
}

TEST_CASE("events out of time order, empty lines and empty files are errors", "[recording][malformed]") {
  check(error_on_line4(R"({"t":1.5,"type":"redo"})"), 4, {"earlier than the previous event"});
  check(error_for(header + "\n\n" + undo + "\n"), 2, {"empty line"});
  check(error_for(""), 0, {"empty file"});
}

TEST_CASE("read_recording names a missing file", "[recording][malformed]") {
  try {
    read_recording("/nonexistent/dir/session.jsonl");
    FAIL("no error");
  } catch (const RecordingError& e) {
    CHECK(e.line == 0);
    CHECK(std::string(e.what()) == "/nonexistent/dir/session.jsonl: no such file");
  }
}
