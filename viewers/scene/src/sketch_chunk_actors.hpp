#pragma once
// Internal to viewers/: draws a SketchGeometry (sketch_geometry.hpp) as one
// actor per chunk, on the render thread. Showing a new geometry converts the
// chunks that changed to polydata (VTK re-uploads those at the next render)
// and leaves the others' actors and buffers alone, so the frame after an
// edit costs the edited chunks, not the sketch.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>

#include <vtkActor.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "sketch_geometry.hpp"
#include "sketchlab/viewer/scene_style.hpp"

namespace sketchlab::viewer {

class SketchChunkActors {
 public:
  // Each new actor is styled by make_sketch_actor(style), then `restyle`
  // (optional: a viewer's own look, e.g. VR's lit tubes). Classes the style
  // does not draw (drawn() false) get no actors. `renderer` must outlive this.
  SketchChunkActors(vtkRenderer* renderer, const SceneStyle& style,
                    std::function<void(DrawClass, vtkActor*)> restyle = {});
  ~SketchChunkActors();
  SketchChunkActors(const SketchChunkActors&) = delete;
  SketchChunkActors& operator=(const SketchChunkActors&) = delete;

  // Draws `geometry` (not null) from now on: chunks new to it get an actor,
  // chunks gone lose theirs, chunks whose data is not the one drawn (a
  // different DrawData object) get new polydata. Returns how many actors got
  // new polydata (new ones included): what the next render re-uploads.
  std::size_t show(std::shared_ptr<const SketchGeometry> geometry);
  // Removes every actor.
  void clear();
  // Hides or shows a class without touching its geometry.
  void set_visible(DrawClass cls, bool visible);
  // The workspace placement of every actor (may be null).
  void set_user_matrix(vtkMatrix4x4* matrix);
  std::size_t actor_count() const { return chunks_.size(); }

 private:
  vtkRenderer* renderer_;
  SceneStyle style_;
  std::function<void(DrawClass, vtkActor*)> restyle_;
  std::map<DrawClass, bool> hidden_;
  vtkSmartPointer<vtkMatrix4x4> matrix_;
  struct Chunk {
    std::shared_ptr<const DrawData> data;
    vtkSmartPointer<vtkActor> actor;
  };
  std::map<ChunkKey, Chunk> chunks_;
};

}  // namespace sketchlab::viewer
