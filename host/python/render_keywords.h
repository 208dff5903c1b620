// render_keywords.h — render()'s keywords as Python sees them: one typed
// keyword a flag of `wavefront render`, made from the command line's own list
// of flags (cli.h, render_flags), so that help(), inspect.signature and an
// editor's completion show every flag with its default and help, and cannot
// drift from the command line. A value of the wrong type is a TypeError that
// names its keyword; the values are then checked by the command line's own
// validators, which word their errors as the command line does.
#pragma once

#include <string>
#include <vector>

#include <pybind11/pybind11.h>

namespace wf {

// The keywords as command-line words: spp=64 becomes --spp 64, True a flag
// alone, False and None nothing; a path may be any os.PathLike, aov= a list of
// names, device= a Device, an index, a name or a list of them. Throws
// TypeError for a keyword that names no flag or a value of the wrong type.
std::vector<std::string> render_words(const std::string& scene, const pybind11::dict& keywords);

// Gives `function`, a Python function render(scene, progress=None,
// **keywords), the signature and help of every keyword, after `summary`.
void describe_render(pybind11::object function, const std::string& summary);

} // namespace wf
