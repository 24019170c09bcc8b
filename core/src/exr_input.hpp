#pragma once
// Opening an OpenEXR file for reading only after checking what its header claims against the
// file and the limits (gfield/limits.hpp), so that OpenEXR never allocates or loops on an
// untrusted count: every attribute must fit in the file (a preview image in its attribute), the
// data window must be non-empty and within the given size, the named channels unsubsampled, the
// chunk offsets must fit in the file, and the pixels claimed must fit in the file at
// kMaxCompressionRatio. Single-part scanline files and single-level tiled files only. Internal
// to gfield_core (exr_io.cpp, thickness_io.cpp, image_io.cpp).

#include <OpenEXR/ImfInputFile.h>

#include <initializer_list>
#include <memory>
#include <string>

namespace gfield {

/// Opens `filename` after the checks above. `max_width` x `max_height` bounds the data window;
/// each of `channels` that the file has must be sampled at every pixel. False with a one-line
/// "FILE: problem" (also when OpenEXR throws).
bool open_exr_input(const std::string& filename, int max_width, int max_height,
                    std::initializer_list<const char*> channels,
                    std::unique_ptr<Imf::InputFile>& file, std::string& error);

/// An OpenEXR exception's text on one line (printable.hpp).
std::string exr_exception_text(const std::exception& e);

}  // namespace gfield
