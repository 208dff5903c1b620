// denoiser.h — a rendered image denoised by Intel Open Image Denoise 2.x's
// "RT" filter (the denoiser Blender and most CPU renderers ship), guided by
// the first hit's albedo and normal (--aov albedo,normal). The library is
// opened at run time (oidn_api.h): Debian 12 packages none, PyPI's pyoidn
// wheel bundles it, and scripts/setup.sh installs that wheel into
// build/oidn-venv. Where it is looked for, in order:
//   1. $WF_OIDN_LIBRARY, a path to libOpenImageDenoise.so.2, alone when set;
//   2. the build's own build/oidn-venv (the path CMake bakes in, WF_OIDN_VENV);
//   3. pyoidn beside the program running this, or beside the module's
//      package: the site-packages that `pip install .[denoise]` fills;
//   4. libOpenImageDenoise.so.2 on the loader's default search path.
#pragma once

#include <string>

#include "image/image.h"

namespace wf {

// The path of the library that denoise() uses, opening it the first time;
// throws InputError, one line naming where it looked and how to install it,
// when none can be opened.
std::string denoiser_library();

// Whether denoiser_library() finds one; `why` receives its error when not.
bool denoiser_available(std::string* why = nullptr);

// `beauty` denoised as OIDN's documentation recommends for final frames: the
// auxiliary images prefiltered first (the RT filter run on the albedo alone
// and on the normal alone), then the beauty filtered with hdr on and
// cleanAux on. All three must have the same size. Throws InputError without
// the library (as denoiser_library()), DeviceError when OIDN reports a failure.
Image denoise(const Image& beauty, const Image& albedo, const Image& normal);

} // namespace wf
