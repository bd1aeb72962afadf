// Names that become one component of a path inside an output folder: a sweep's workload
// (DIR/traces/NAME, DIR/points/NAME-ID), a regression case (OUT/cases/NAME), a chart's id
// (images/ID.png). A name from a spec or a document read back must not leave its folder or hide
// in it, so every such name is checked here before anything is written.
#pragma once

#include <cstddef>
#include <string>

namespace rtsim {

// The longest name taken: a component is at most 255 bytes on common file systems, and some
// names get a suffix (a sweep point's "-HASH").
constexpr size_t kMaxPathNameBytes = 200;

// Why `name` cannot be one path component (empty if it can): it is empty or longer than
// kMaxPathNameBytes, holds a '/' or '\\' or a control character, or starts with '.' (".", ".."
// and hidden files).
std::string path_name_problem(const std::string& name);

}  // namespace rtsim
