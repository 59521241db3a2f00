#include "sketch_chunk_actors.hpp"

#include <stdexcept>

#include <vtkPolyDataMapper.h>

#include "scene_actors.hpp"

namespace sketchlab::viewer {

SketchChunkActors::SketchChunkActors(vtkRenderer* renderer, const SceneStyle& style,
                                     std::function<void(DrawClass, vtkActor*)> restyle)
    : renderer_(renderer), style_(style), restyle_(std::move(restyle)) {
  // As add_sketch_actors: patches behind curves behind nodes (process-wide;
  // set before the first frame, so whatever else the viewer draws is
  // offset the same way from the start).
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();
}

SketchChunkActors::~SketchChunkActors() { clear(); }

std::size_t SketchChunkActors::show(std::shared_ptr<const SketchGeometry> geometry) {
  if (!geometry) throw std::invalid_argument("SketchChunkActors::show: no geometry");
  std::size_t swapped = 0;
  for (auto it = chunks_.begin(); it != chunks_.end();) {
    if (geometry->chunks.count(it->first)) {
      ++it;
      continue;
    }
    renderer_->RemoveActor(it->second.actor);
    it = chunks_.erase(it);
  }
  for (const auto& [key, data] : geometry->chunks) {
    if (!drawn(key.cls, style_)) continue;
    auto it = chunks_.find(key);
    if (it != chunks_.end() && it->second.data == data) continue;
    const vtkSmartPointer<vtkPolyData> poly = to_polydata(*data);
    if (it == chunks_.end()) {
      vtkSmartPointer<vtkActor> actor = make_sketch_actor(key.cls, poly, style_);
      if (restyle_) restyle_(key.cls, actor);
      actor->SetUserMatrix(matrix_);
      actor->SetVisibility(!hidden_[key.cls]);
      renderer_->AddActor(actor);
      chunks_.emplace(key, Chunk{data, actor});
    } else {
      vtkPolyDataMapper::SafeDownCast(it->second.actor->GetMapper())->SetInputData(poly);
      it->second.data = data;
    }
    ++swapped;
  }
  return swapped;
}

void SketchChunkActors::clear() {
  for (const auto& [key, chunk] : chunks_) renderer_->RemoveActor(chunk.actor);
  chunks_.clear();
}

void SketchChunkActors::set_visible(DrawClass cls, bool visible) {
  hidden_[cls] = !visible;
  for (const auto& [key, chunk] : chunks_)
    if (key.cls == cls) chunk.actor->SetVisibility(visible);
}

void SketchChunkActors::set_user_matrix(vtkMatrix4x4* matrix) {
  matrix_ = matrix;
  for (const auto& [key, chunk] : chunks_) chunk.actor->SetUserMatrix(matrix);
}

}  // namespace sketchlab::viewer
