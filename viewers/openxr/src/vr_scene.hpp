#pragma once
// The VR scene: the desktop viewer's sketch actors (viewers/scene: raw
// strokes faint, curves, nodes, patches) for the shown stack, placed in the
// stage by the workspace placement, with what only VR has: the workspace
// (workspace_actors.hpp), the hands and the hand menu (hand_actors.hpp),
// the feedback on each correction (correction_feedback.hpp) and, in compare
// mode, the next stack's curves overlaid in `compare_colour`.
//
// The sketch is drawn incrementally: the worker builds each stack's geometry
// in chunks (viewers/scene/sketch_geometry.hpp, through geometry_preparer)
// and the render thread only converts and re-uploads the chunks a
// correction added, changed or removed (sketch_chunk_actors.hpp), so the
// frame that shows a correction costs that correction, not the sketch.
//
// In VR, curves are lit tubes (VTK's RenderLinesAsTubes: a shaded screen-
// space tube, so curves read in depth at no geometry cost) and patches are
// shaded (diffuse and specular), where the desktop draws them flat.
#include <string>
#include <vector>

#include <vtkRenderer.h>

#include "correction_feedback.hpp"
#include "correction_worker.hpp"
#include "hand_actors.hpp"
#include "scene_actors.hpp"
#include "sketch_chunk_actors.hpp"
#include "workspace_actors.hpp"

namespace sketchlab::vr {

inline constexpr viewer::Rgb compare_colour{0.95, 0.50, 0.05};

// The SceneStyle of the VR viewer: exact pixels (no multisampling, the
// tests read them), curves a little wider than on the desktop.
viewer::SceneStyle vr_style();

// The worker's half of the scene: fills SketchSnapshot::geometry with every
// stack's geometry, updated incrementally from the previous snapshot's (one
// SketchGeometryBuilder per stack, kept by the returned function). Give it
// to the CorrectionWorker whose snapshots VrScene::show draws.
CorrectionWorker::Prepare geometry_preparer(const viewer::SceneStyle& style);

class VrScene {
 public:
  // `stack_names`: the session's stacks, in order (at least one).
  VrScene(vtkRenderer* renderer, const viewer::SceneStyle& style, std::vector<std::string> stack_names);

  // A stroke the input finished and submitted (shown until corrected).
  void stroke_submitted(const Stroke& stroke);
  // The latest snapshot of the worker (its geometry filled by
  // geometry_preparer, else std::logic_error); when it or the menu's view
  // changed, swaps in the chunks that changed, and starts the feedback for a
  // new stroke.
  void show(const SketchSnapshot& snapshot, const ControllerView& view, double now);
  // Chunk actors that got new geometry at the last show that changed
  // something (the shown stack's and the compared one's).
  std::size_t chunks_swapped() const { return chunks_swapped_; }
  // Per frame: placement, hands, menu, workspace, fades.
  void update(const ControllerState& input, double now);

 private:
  viewer::SketchChunkActors sketch_, compare_;
  WorkspaceActors workspace_;
  HandActors hands_;
  CorrectionFeedback feedback_;
  std::uint64_t shown_version_ = ~std::uint64_t{0};
  std::size_t shown_strokes_ = 0;
  ControllerView shown_view_;
  std::size_t chunks_swapped_ = 0;
};

}  // namespace sketchlab::vr
