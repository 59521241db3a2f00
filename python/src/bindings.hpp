#pragma once
// Shared pieces of the Python bindings (module.cpp lists the parts). The
// bindings wrap the kernel's C++ API and convert at the boundary only:
// point lists <-> float64 numpy arrays of shape (n, 3), everything else
// through pybind11's standard casters. Long calls release the GIL.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <string>
#include <vector>

#include "sketchlab/types.hpp"

namespace sketchlab::python {

namespace py = pybind11;
using Points = py::array_t<double, py::array::c_style | py::array::forcecast>;

// (n, 3) float64 array, a copy of `points`.
py::array_t<double> to_array(const std::vector<Vec3>& points);
// Checks the shape (n, 3) (ValueError naming `what` and the shape given) and
// copies the rows.
std::vector<Vec3> from_array(const Points& points, const char* what);
// A (n,) float64 array, a copy of `values`.
py::array_t<double> to_array(const std::vector<double>& values);

void bind_geometry(py::module_& m);   // curves, network, edits, constraints, sketch
void bind_recording(py::module_& m);  // strokes, events, recordings
void bind_plugins(py::module_& m);    // plugin host, parameter specs, correctors
void bind_run(py::module_& m);        // stacks, sessions, replay, experiments, comparison

}  // namespace sketchlab::python
