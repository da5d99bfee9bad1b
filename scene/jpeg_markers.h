// A JPEG's markers read before it is decoded: the work it asks for
// (docs/limits.md). Internal to the scene library.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "glslrun/glslrun.h"

namespace glslrun::scene {

// Scans per JPEG: a progressive file has about 10 (libjpeg's default
// script); stb's work grows with scans times blocks.
inline constexpr size_t kMaxJpegScans = 500;

// Refuses a JPEG with more than kMaxJpegScans scans, and one whose
// entropy-coded data is too short for the blocks its frame header states
// (a Huffman-coded block takes at least 1 bit, 2 in a baseline scan).
// Other faults are left to the decoder, which names them.
Status check_jpeg_work(const std::string& path, const std::vector<unsigned char>& data);

}  // namespace glslrun::scene
