#pragma once
// Private to the plugin host: what can be checked about a plugin file before
// dlopen() maps it. The loader maps each segment of a shared library straight
// from the file; a segment reaching past the end of a truncated file is mapped
// all the same, and the first touch of its missing pages kills the process
// with SIGBUS inside dlopen (issue 17, D1). Reading the ELF headers first
// turns that into an error naming the file.
#include <filesystem>
#include <string>

namespace sketchlab::plugin_detail {

// Empty when `file` is a regular file holding an ELF shared object for this
// host (class, byte order and machine of the running executable) whose
// program headers, segments and section header table all lie inside the file;
// otherwise the reason, e.g. "truncated: segment 2 (LOAD) needs 61440 bytes,
// the file has 30720". Reads only the headers.
std::string check_elf_library(const std::filesystem::path& file);

}  // namespace sketchlab::plugin_detail
