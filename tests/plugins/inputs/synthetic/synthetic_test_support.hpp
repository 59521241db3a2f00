#pragma once
// Helpers shared by the synthetic input tests.
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "session_synthesis.hpp"
#include "sketchlab/recording/recording_writer.hpp"

namespace sketchlab::synthetic::support {

inline SynthesisParams perfect(const std::string& model, Modality modality = Modality::vr) {
  SynthesisParams p;
  p.model = model;
  p.modality = modality;
  p.noise = 0.0;
  return p;
}

// Only the given VR error sources, at noise scale 1.
inline SynthesisParams vr_only(const std::string& model, NoiseModel noise, std::uint64_t seed = 1) {
  SynthesisParams p;
  p.model = model;
  p.seed = seed;
  p.vr_noise = noise;
  return p;
}

inline std::string to_text(const Recording& rec) {
  std::ostringstream out;
  write_recording(out, rec);
  return out.str();
}

struct Drawn {
  Stroke stroke;
  Curve truth;
};

// Strokes with their ground-truth curves, in order; relations separately.
inline std::vector<Drawn> drawn(const Recording& rec) {
  std::vector<Drawn> out;
  for (const Event& e : rec.events) {
    if (const auto* s = std::get_if<StrokeEvent>(&e.payload)) out.push_back({s->stroke, {}});
    if (const auto* r = std::get_if<ReferenceEvent>(&e.payload)) {
      if (!out.empty() && out.back().stroke.id == r->stroke && r->track == "ground_truth")
        out.back().truth = r->curve;
    }
  }
  return out;
}

inline std::vector<RelationEvent> relations(const Recording& rec) {
  std::vector<RelationEvent> out;
  for (const Event& e : rec.events)
    if (const auto* r = std::get_if<RelationEvent>(&e.payload)) out.push_back(*r);
  return out;
}

inline std::map<ConstraintKind, int> count_by_kind(const std::vector<RelationEvent>& rels) {
  std::map<ConstraintKind, int> n;
  for (const auto& r : rels) ++n[r.kind];
  return n;
}

}  // namespace sketchlab::synthetic::support
