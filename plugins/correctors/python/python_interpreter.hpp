#pragma once
// The Python interpreter the python corrector runs its classes in.
//
// In a Python process (the plugin loaded through `import sketchlab`) that is
// the running interpreter. Anywhere else (the CLI, the viewers, the
// experiment runner) the first call starts one embedded interpreter for the
// process: Debian's python3 the module was built for (its sys.path, so its
// numpy), with the `sketchlab` package of this build or install added to
// sys.path. It is never finalised: plugin objects may outlive any scope that
// could own it, and finalising with extension modules loaded is unsafe.
// After the call the GIL is free; callers take it with
// pybind11::gil_scoped_acquire (safe from any thread).
namespace sketchlab::python_corrector {

// Throws std::runtime_error when the interpreter cannot start or `sketchlab`
// cannot be imported (the message says why and what was searched).
void ensure_interpreter();

}  // namespace sketchlab::python_corrector
