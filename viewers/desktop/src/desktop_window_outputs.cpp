// DesktopWindow's file outputs: the recording, sketch JSON, PLY/OBJ/.mlp
// exports and screenshots, all written under the export directory.
#include <filesystem>

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkWindowToImageFilter.h>

#include "desktop_window.hpp"
#include "sketchlab/io/mesh_export.hpp"
#include "sketchlab/io/sketch_json.hpp"
#include "sketchlab/io/text_file.hpp"
#include "sketchlab/recording/recording_writer.hpp"

namespace sketchlab::desktop {
namespace {

// File-name-safe version of a stack name.
std::string file_stem(const std::string& name) {
  std::string s = name;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return s.empty() ? "stack" : s;
}

}  // namespace

void DesktopWindow::save_recording() {
  try {
    write_recording(options_.save, model_.events(), true);
    notify("saved " + options_.save.string());
  } catch (const std::exception& e) {
    notify(std::string("save failed: ") + e.what());
  }
}

void DesktopWindow::export_json() {
  try {
    for (std::size_t i = 0; i < model_.stack_count(); ++i) {
      const auto file = options_.export_dir / (file_stem(model_.stack_name(i)) + ".json");
      write_text_file(file, sketch_to_json(model_.sketch(i)));
    }
    notify("exported sketch JSON to " + options_.export_dir.string());
  } catch (const std::exception& e) {
    notify(std::string("export failed: ") + e.what());
  }
}

void DesktopWindow::export_meshes() {
  try {
    std::vector<MeshLabLayer> layers;
    for (std::size_t i = 0; i < model_.stack_count(); ++i) {
      const std::string stem = file_stem(model_.stack_name(i));
      const Sketch& s = model_.sketch(i);
      write_text_file(options_.export_dir / (stem + "_curves.ply"), network_to_ply(s.network));
      write_text_file(options_.export_dir / (stem + ".obj"), network_to_obj(s.network));
      layers.push_back({model_.stack_name(i) + " curves", stem + "_curves.ply"});
      std::vector<const Mesh*> meshes;
      for (const auto& [id, patch] : s.network.patches()) meshes.push_back(&patch.mesh);
      if (!meshes.empty()) {
        write_text_file(options_.export_dir / (stem + "_patches.ply"), meshes_to_ply(meshes));
        layers.push_back({model_.stack_name(i) + " patches", stem + "_patches.ply"});
      }
    }
    write_text_file(options_.export_dir / "sketch.mlp", meshlab_project(layers));
    notify("exported PLY/OBJ/.mlp to " + options_.export_dir.string());
  } catch (const std::exception& e) {
    notify(std::string("export failed: ") + e.what());
  }
}

void DesktopWindow::screenshot() {
  const auto file =
      options_.export_dir / ("screenshot-" + std::to_string(++screenshots_) + ".png");
  std::filesystem::create_directories(options_.export_dir);
  render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window_);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  const auto tmp = file.string() + ".tmp.png";
  writer->SetFileName(tmp.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  std::error_code ec;
  std::filesystem::rename(tmp, file, ec);  // whole files only, for pollers
  if (writer->GetErrorCode() != 0 || ec) notify("screenshot failed: " + file.string());
  else notify("screenshot " + file.string());
}


}  // namespace sketchlab::desktop
