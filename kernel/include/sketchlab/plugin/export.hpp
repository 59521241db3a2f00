#pragma once
// Symbol visibility across the plugin boundary. Plugins are built with hidden
// visibility (cmake/SketchlabPlugin.cmake); what the host must find in them
// (the entry point, SKETCHLAB_PLUGIN) is marked default. GCC and Clang on ELF.
#define SKETCHLAB_SYMBOL_EXPORT __attribute__((visibility("default")))
