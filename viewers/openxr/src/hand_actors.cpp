#include "hand_actors.hpp"

#include <cmath>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkConeSource.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include "vr_actor_utils.hpp"

namespace sketchlab::vr {
namespace {

constexpr double body_radius = 0.012, body_length = 0.10;  // m: a pen-sized controller
constexpr viewer::Rgb pen_colour{0.55, 0.56, 0.60}, off_hand_colour{0.75, 0.75, 0.78};
constexpr viewer::Rgb label_colour{0.08, 0.08, 0.10};

// The controller: a pen-shaped cone whose point is the aim point, its body
// along the hand's +z (towards the user; the aim points along -z).
vtkSmartPointer<vtkActor> make_body() {
  vtkNew<vtkConeSource> cone;
  cone->SetRadius(body_radius);
  cone->SetHeight(body_length);
  cone->SetResolution(16);
  cone->SetDirection(0.0, 0.0, -1.0);
  cone->SetCenter(0.0, 0.0, 0.5 * body_length);
  return actor_for(cone);
}

// The menu's squares in the holding hand's frame, one quad per item, a
// little inset so the items read apart.
vtkSmartPointer<vtkPolyData> menu_squares(const ControllerMenu& menu) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  const double h = 0.42 * menu.cell;
  for (const ControllerMenuItem& item : menu.items) {
    const Vec3& c = item.centre;
    const vtkIdType ids[4] = {points->InsertNextPoint(c.x() - h, c.y() - h, c.z()),
                              points->InsertNextPoint(c.x() + h, c.y() - h, c.z()),
                              points->InsertNextPoint(c.x() + h, c.y() + h, c.z()),
                              points->InsertNextPoint(c.x() - h, c.y() + h, c.z())};
    quads->InsertNextCell(4, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(quads);
  return data;
}

// Item labels in the upper part of each square, just in front of it.
vtkSmartPointer<vtkPolyData> menu_label_data(const ControllerMenu& menu) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (const ControllerMenuItem& item : menu.items) {
    const Vec3 c = item.centre + Vec3(0.0, 0.12 * menu.cell, 0.001);
    const auto text = text_data(item.label, 0.0045, c, true);
    const vtkIdType base = points->GetNumberOfPoints();
    for (vtkIdType p = 0; p < text->GetNumberOfPoints(); ++p) points->InsertNextPoint(text->GetPoint(p));
    vtkCellArray* cells = text->GetPolys();
    cells->InitTraversal();
    vtkIdType n;
    const vtkIdType* ids;
    while (cells->GetNextCell(n, ids)) {
      std::vector<vtkIdType> shifted(ids, ids + n);
      for (vtkIdType& id : shifted) id += base;
      polys->InsertNextCell(n, shifted.data());
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  return data;
}

vtkSmartPointer<vtkActor> flat_actor(vtkPolyData* data, const viewer::Rgb& colour) {
  auto actor = actor_for(data);
  set_colour(actor, colour);
  actor->GetProperty()->LightingOff();
  return actor;
}

}  // namespace

viewer::Rgb mode_colour(Layer mode, bool correction) {
  viewer::Rgb c;
  switch (mode) {
    case Layer::scaffold: c = {0.20, 0.45, 0.85}; break;
    case Layer::shape: c = {0.85, 0.25, 0.20}; break;
    case Layer::free: c = {0.20, 0.65, 0.30}; break;
    default: c = {0.40, 0.40, 0.45}; break;
  }
  if (!correction)
    for (double& x : c) x = 0.5 * x + 0.5;
  return c;
}

viewer::Rgb tip_colour(const ControllerState& input, const viewer::SceneStyle& style) {
  switch (input.tool) {
    case ControllerTool::patch: return style.patch_colour;
    case ControllerTool::erase: return erase_colour;
    case ControllerTool::draw: break;
  }
  return mode_colour(input.mode, input.correction);
}

std::string mode_label(const ControllerState& input) {
  std::string text = input.tool == ControllerTool::patch   ? "patch"
                     : input.tool == ControllerTool::erase ? "erase"
                     : input.mode == Layer::automatic      ? "auto"
                                                           : std::string(to_string(input.mode));
  if (!input.correction) text += ", correction off";
  return text;
}

std::pair<double, std::string> scale_bar(double scale) {
  if (!(scale > 0.0) || !std::isfinite(scale)) scale = 1.0;
  // Smallest 1-2-5 length at least 3 cm on the stage.
  double decade = std::pow(10.0, std::floor(std::log10(0.03 / scale)));
  for (;;) {
    for (int f : {1, 2, 5}) {
      const double length = f * decade;
      if (length * scale >= 0.03 - 1e-12) {
        char text[32];
        if (length >= 1.0)
          std::snprintf(text, sizeof text, "%g m", length);
        else if (length >= 0.01)
          std::snprintf(text, sizeof text, "%g cm", length * 100.0);
        else
          std::snprintf(text, sizeof text, "%g mm", length * 1000.0);
        return {length, text};
      }
    }
    decade *= 10.0;
  }
}

HandActors::HandActors(vtkRenderer* renderer, const viewer::SceneStyle& style, std::vector<std::string> stack_names)
    : style_(style), stack_names_(std::move(stack_names)) {
  for (auto& body : bodies_) {
    body = make_body();
    body->GetProperty()->SetSpecular(0.3);
    body->VisibilityOff();
    renderer->AddActor(body);
  }
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(brush_tip_radius);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  tip_ = actor_for(sphere);
  tip_->GetProperty()->SetAmbient(0.5);
  tip_->GetProperty()->SetDiffuse(0.5);
  tip_->VisibilityOff();
  renderer->AddActor(tip_);
  mode_label_ = flat_actor(vtkNew<vtkPolyData>().GetPointer(), label_colour);
  renderer->AddActor(mode_label_);

  // The menu's geometry comes with the input's first state (set_menu).
  menu_colours_ = vtkSmartPointer<vtkUnsignedCharArray>::New();
  menu_colours_->SetNumberOfComponents(3);
  menu_ = actor_for(vtkNew<vtkPolyData>().GetPointer());
  auto* mapper = vtkPolyDataMapper::SafeDownCast(menu_->GetMapper());
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  menu_->GetProperty()->LightingOff();
  renderer->AddActor(menu_);
  menu_labels_ = flat_actor(vtkNew<vtkPolyData>().GetPointer(), label_colour);
  renderer->AddActor(menu_labels_);
  stack_label_ = flat_actor(vtkNew<vtkPolyData>().GetPointer(), label_colour);
  renderer->AddActor(stack_label_);
  scale_bar_ = flat_actor(vtkNew<vtkPolyData>().GetPointer(), label_colour);
  scale_bar_->GetProperty()->SetLineWidth(3.0f);
  renderer->AddActor(scale_bar_);
  scale_label_ = flat_actor(vtkNew<vtkPolyData>().GetPointer(), label_colour);
  renderer->AddActor(scale_label_);
}

void HandActors::set_text(vtkActor* actor, std::string& shown, const std::string& text, double height,
                          const Vec3& origin, bool centred) {
  if (text == shown) return;
  shown = text;
  set_data(actor, text_data(text, height, origin, centred));
}

void HandActors::set_menu(const ControllerMenu& menu) {
  std::vector<std::string> labels;
  for (const ControllerMenuItem& item : menu.items) labels.push_back(item.label);
  if (labels == menu_shown_) return;
  menu_shown_ = std::move(labels);
  const auto squares = menu_squares(menu);
  menu_colours_->SetNumberOfTuples(static_cast<vtkIdType>(menu.items.size()));
  squares->GetCellData()->SetScalars(menu_colours_);
  set_data(menu_, squares);
  set_data(menu_labels_, menu_label_data(menu));
}

void HandActors::update(const ControllerState& input) {
  const std::array<const ControllerHand*, 2> hands{&input.pen, &input.holder};
  for (std::size_t h = 0; h < 2; ++h) {
    const ControllerHand& hand = *hands[h];
    bodies_[h]->SetVisibility(hand.tracked);
    if (hand.tracked) bodies_[h]->SetUserMatrix(pose_matrix(hand.aim));
  }
  const ControllerHand& pen = input.pen;
  const viewer::Rgb tip = tip_colour(input, style_);
  set_colour(bodies_[0], pen_colour);
  set_colour(bodies_[1], off_hand_colour);
  tip_->SetVisibility(pen.tracked);
  mode_label_->SetVisibility(pen.tracked);
  if (pen.tracked) {
    tip_->SetUserMatrix(pose_matrix(pen.aim));
    set_colour(tip_, tip);
    mode_label_->SetUserMatrix(pose_matrix(pen.aim));
    set_text(mode_label_, mode_text_, mode_label(input), 0.008, Vec3(0.0, body_radius + 0.008, 0.03), true);
  }

  const ControllerHand& holder = input.holder;
  const ControllerMenu& menu = input.menu;
  const bool show_menu = holder.tracked && !menu.items.empty();
  for (vtkActor* a : {menu_.Get(), menu_labels_.Get(), stack_label_.Get(), scale_bar_.Get(), scale_label_.Get()})
    a->SetVisibility(show_menu);
  if (!show_menu) return;
  set_menu(menu);
  const auto at_hand = pose_matrix(holder.aim);
  for (vtkActor* a : {menu_.Get(), menu_labels_.Get(), stack_label_.Get(), scale_bar_.Get(), scale_label_.Get()})
    a->SetUserMatrix(at_hand);
  for (std::size_t i = 0; i < menu.items.size(); ++i) {
    const ControllerMenuItem& item = menu.items[i];
    const viewer::Rgb& c = item.hovered ? menu_hover_colour : item.active ? menu_active_colour : menu_item_colour;
    for (int k = 0; k < 3; ++k)
      menu_colours_->SetComponent(static_cast<vtkIdType>(i), k, std::lround(255.0 * c[static_cast<std::size_t>(k)]));
  }
  menu_colours_->Modified();

  // The stack's name above the panel's top left corner; the scale bar from
  // its left edge, between the controller and the panel.
  const Vec3 top = menu.centre + Vec3(-menu.half_size.x(), menu.half_size.y() + 0.006, 0.0);
  const double left = menu.centre.x() - menu.half_size.x();
  const std::size_t shown = input.view.stack;
  std::string stack = stack_names_.empty() ? std::string() : stack_names_[shown % stack_names_.size()];
  if (stack_names_.size() > 1) {
    stack = std::to_string(shown % stack_names_.size() + 1) + "/" + std::to_string(stack_names_.size()) + " " + stack;
    if (input.view.compare)
      stack += " vs " + stack_names_[(shown + 1) % stack_names_.size()];
  }
  set_text(stack_label_, stack_text_, stack, 0.007, top, false);

  // Scale bar between the controller and the menu: a round workspace length
  // drawn at its stage length, so it grows as the user zooms in.
  const double scale = input.placement.scale;
  const auto [length, text] = scale_bar(scale);
  const double bar = length * scale;
  if (bar != bar_length_) {
    bar_length_ = bar;
    const double y = 0.018, x0 = left;
    set_data(scale_bar_, polyline_data({Vec3(x0, y + 0.004, 0), Vec3(x0, y, 0), Vec3(x0 + bar, y, 0),
                                        Vec3(x0 + bar, y + 0.004, 0)}));
  }
  char zoom[32];
  std::snprintf(zoom, sizeof zoom, "  x%.2f", scale);
  set_text(scale_label_, scale_text_, text + zoom, 0.006,
           Vec3(left, 0.024, 0.0), false);
}

}  // namespace sketchlab::vr
