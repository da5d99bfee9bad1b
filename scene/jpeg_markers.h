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
// Blocks visited by all scans together (each scan visits every 8x8 block of
// its components): stb's work grows with them. Under the scan limit alone,
// 500 refinement scans of a 4096x4096 image, a 213 KB file, took 5 s of
// CPU, and 500 DC scans of it (48 MB) 11 s. A progressive file of the
// largest texture (4096x4096, 4:4:4, libjpeg's 10 scans) visits 3.7M
// blocks; at 2^24 the worst file allowed (one refinement scan 50 times,
// 199 KB) takes 1.7 s of CPU in all, 0.4 s of it the plain file's.
inline constexpr uint64_t kMaxJpegBlockVisits = uint64_t(1) << 24;

// Refuses a JPEG with more than kMaxJpegScans scans or kMaxJpegBlockVisits
// block visits, and one whose entropy-coded data is too short for the
// blocks its frame header states (a Huffman-coded block takes at least 1
// bit, 2 in a baseline scan).
// Other faults are left to the decoder, which names them.
Status check_jpeg_work(const std::string& path, const std::vector<unsigned char>& data);

}  // namespace glslrun::scene
