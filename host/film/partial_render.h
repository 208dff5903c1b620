// partial_render.h — an unfinished render on disk (--checkpoint-every, Ctrl-C),
// and reading it back for --resume. An EXR whose RGB is the image so far and
// whose other channels hold the film's sums, compensations and counts exactly
// as the device had them, beside the options that shaped them: a resumed
// render adds its samples to the same floats in the same order, so it ends
// with the bytes of one that was never stopped (tests/cli/test_interrupt.cpp).
#pragma once

#include <string>

#include "film/film.h"
#include "image/image_io.h"

namespace wf {

struct PartialRender {
    FilmState film;
    ImageOptions options; // as written
};

// The partial file of an output: OUT.partial.exr.
std::string partial_render_path(const std::string& output);

// Written atomically (image_io.h). Throws InputError naming the file.
void write_partial_render(const std::string& path, const FilmState& film, const ImageMetadata& metadata);

// Throws InputError naming the file when it is not a partial render.
PartialRender read_partial_render(const std::string& path);

// Throws InputError naming the file (`path`) and the first of `expected`'s
// options that the partial render was not written with.
void check_partial_options(const PartialRender& partial, const std::string& path, const ImageOptions& expected);

} // namespace wf
