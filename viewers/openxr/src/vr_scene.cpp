#include "vr_scene.hpp"

#include <stdexcept>

#include <vtkProperty.h>

#include "vr_actor_utils.hpp"

namespace sketchlab::vr {
namespace {

// Lit tubes for curves, shaded patches (see the header).
void restyle_for_vr(viewer::DrawClass cls, vtkActor* actor) {
  vtkProperty* p = actor->GetProperty();
  switch (cls) {
    case viewer::DrawClass::scaffold:
    case viewer::DrawClass::shape:
    case viewer::DrawClass::other:
      p->LightingOn();
      p->SetRenderLinesAsTubes(true);
      p->SetAmbient(0.35);
      p->SetDiffuse(0.65);
      p->SetSpecular(0.2);  // a highlight that keeps dark curves dark
      p->SetSpecularPower(30.0);
      break;
    case viewer::DrawClass::patches:
      p->SetAmbient(0.25);
      p->SetDiffuse(0.75);
      p->SetSpecular(0.25);
      p->SetSpecularPower(20.0);
      p->SetOpacity(0.55);
      break;
    default:
      break;
  }
}

// The other stack's curves only, in one colour, on the same strokes.
viewer::SceneStyle compare_style(viewer::SceneStyle style) {
  style.show_raw_strokes = style.show_nodes = style.show_patches = false;
  style.scaffold_colour = style.shape_colour = style.curve_colour = compare_colour;
  return style;
}

}  // namespace

viewer::SceneStyle vr_style() {
  viewer::SceneStyle style;
  style.multisamples = 0;
  style.background = sky_colour;
  return style;
}

CorrectionWorker::Prepare geometry_preparer(const viewer::SceneStyle& style) {
  auto builders = std::make_shared<std::vector<viewer::SketchGeometryBuilder>>();
  return [builders, style](SketchSnapshot& snap) {
    while (builders->size() < snap.stacks.size()) builders->emplace_back(style);
    snap.geometry.clear();
    for (std::size_t i = 0; i < snap.stacks.size(); ++i)
      snap.geometry.push_back((*builders)[i].update(snap.stacks[i].sketch));
  };
}

VrScene::VrScene(vtkRenderer* renderer, const viewer::SceneStyle& style, std::vector<std::string> stack_names)
    : sketch_(renderer, style, restyle_for_vr),
      compare_(renderer, compare_style(style), restyle_for_vr),
      workspace_(renderer, style),
      hands_(renderer, style, std::move(stack_names)),
      feedback_(renderer, style) {}

void VrScene::stroke_submitted(const Stroke& stroke) { feedback_.stroke_submitted(stroke); }

void VrScene::show(const SketchSnapshot& snap, const ControllerView& view, double now) {
  if (snap.stacks.empty() || (snap.version == shown_version_ && view == shown_view_)) return;
  if (snap.geometry.size() != snap.stacks.size())
    throw std::logic_error("VrScene::show: the snapshot carries no scene geometry (give the CorrectionWorker "
                           "geometry_preparer)");
  shown_version_ = snap.version;
  shown_view_ = view;
  const std::size_t shown = view.stack % snap.stacks.size();
  chunks_swapped_ = sketch_.show(snap.geometry[shown]);
  sketch_.set_visible(viewer::DrawClass::raw_strokes, view.raw_strokes);
  if (view.compare && snap.stacks.size() > 1)
    chunks_swapped_ += compare_.show(snap.geometry[(shown + 1) % snap.stacks.size()]);
  else
    compare_.clear();
  if (snap.strokes != shown_strokes_) {
    shown_strokes_ = snap.strokes;
    if (snap.stroke)
      feedback_.corrected(snap.strokes, *snap.stroke, snap.stacks[shown].sketch, snap.stacks[shown].constraints,
                          view.rejected, now);
  }
}

void VrScene::update(const ControllerState& input, double now) {
  const auto placement = placement_matrix(input.placement);
  sketch_.set_user_matrix(placement);
  compare_.set_user_matrix(placement);
  feedback_.set_live_stroke(input.stroke);
  feedback_.update(placement, now);
  workspace_.update(input);
  hands_.update(input);
}

}  // namespace sketchlab::vr
