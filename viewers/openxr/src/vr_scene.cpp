#include "vr_scene.hpp"

#include <vtkProperty.h>

#include "vr_actor_utils.hpp"

namespace sketchlab::vr {
namespace {

std::vector<vtkActor*> all(const viewer::SceneActors& a) {
  std::vector<vtkActor*> out;
  for (vtkActor* x : {a.raw_strokes.Get(), a.scaffold_curves.Get(), a.shape_curves.Get(), a.other_curves.Get(),
                      a.nodes.Get(), a.patches.Get()})
    if (x) out.push_back(x);
  return out;
}

// Lit tubes for curves, shaded patches (see the header).
void restyle_for_vr(const viewer::SceneActors& a) {
  for (vtkActor* c : {a.scaffold_curves.Get(), a.shape_curves.Get(), a.other_curves.Get()}) {
    if (!c) continue;
    vtkProperty* p = c->GetProperty();
    p->LightingOn();
    p->SetRenderLinesAsTubes(true);
    p->SetAmbient(0.35);
    p->SetDiffuse(0.65);
    p->SetSpecular(0.2);  // a highlight that keeps dark curves dark
    p->SetSpecularPower(30.0);
  }
  if (vtkActor* patches = a.patches.Get()) {
    vtkProperty* p = patches->GetProperty();
    p->SetAmbient(0.25);
    p->SetDiffuse(0.75);
    p->SetSpecular(0.25);
    p->SetSpecularPower(20.0);
    p->SetOpacity(0.55);
  }
}

}  // namespace

viewer::SceneStyle vr_style() {
  viewer::SceneStyle style;
  style.multisamples = 0;
  style.background = sky_colour;
  return style;
}

VrScene::VrScene(vtkRenderer* renderer, const viewer::SceneStyle& style, std::vector<std::string> stack_names)
    : renderer_(renderer),
      style_(style),
      workspace_(renderer, style),
      hands_(renderer, style, std::move(stack_names)),
      feedback_(renderer, style) {}

void VrScene::remove_sketch_actors() {
  for (vtkActor* a : all(sketch_)) renderer_->RemoveActor(a);
  for (vtkActor* a : all(compare_)) renderer_->RemoveActor(a);
  sketch_ = {};
  compare_ = {};
}

void VrScene::stroke_submitted(const Stroke& stroke) { feedback_.stroke_submitted(stroke); }

void VrScene::show(const SketchSnapshot& snap, const openxr::MenuView& view, double now) {
  if (snap.stacks.empty() || (snap.version == shown_version_ && view == shown_view_)) return;
  shown_version_ = snap.version;
  shown_view_ = view;
  const std::size_t shown = view.stack % snap.stacks.size();
  const Sketch& sketch = snap.stacks[shown].sketch;
  remove_sketch_actors();
  viewer::SceneStyle style = style_;
  style.show_raw_strokes = view.raw_strokes;
  const double spacing = viewer::curve_spacing(viewer::scene_bounds({&sketch}), style);
  sketch_ = viewer::add_sketch_actors(renderer_, sketch, nullptr, style, spacing);
  restyle_for_vr(sketch_);
  if (view.compare && snap.stacks.size() > 1) {
    // The other stack's curves only, in one colour, on the same strokes.
    viewer::SceneStyle other = style_;
    other.show_raw_strokes = other.show_nodes = other.show_patches = false;
    other.scaffold_colour = other.shape_colour = other.curve_colour = compare_colour;
    compare_ = viewer::add_sketch_actors(renderer_, snap.stacks[(shown + 1) % snap.stacks.size()].sketch, nullptr,
                                         other, spacing);
    restyle_for_vr(compare_);
  }
  if (snap.strokes != shown_strokes_) {
    shown_strokes_ = snap.strokes;
    if (snap.stroke)
      feedback_.corrected(snap.strokes, *snap.stroke, sketch, snap.stacks[shown].constraints, view.rejected, now);
  }
}

void VrScene::update(const openxr::GestureInterpreter& input, const openxr::ControllerFrame& frame,
                     openxr::Hand dominant, double now) {
  const auto placement = placement_matrix(input.placement());
  for (vtkActor* a : all(sketch_)) a->SetUserMatrix(placement);
  for (vtkActor* a : all(compare_)) a->SetUserMatrix(placement);
  feedback_.set_live_stroke(input.stroke_in_progress());
  feedback_.update(placement, now);
  workspace_.update(input, frame, dominant);
  hands_.update(input, frame, dominant);
}

}  // namespace sketchlab::vr
