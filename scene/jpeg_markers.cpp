// The work a JPEG asks of its decoder, read from its markers before stb_image
// decodes anything: stb bounds the size, not the work. A progressive file
// that repeats one tiny scan 100,000 times took 110 s to decode, and a header
// that claims 4000x4000 over 1 KB of data decoded to 16M grey texels, the
// missing data read as zeros, and passed.
#include "scene/jpeg_markers.h"

#include <algorithm>
#include <array>

#include <fmt/format.h>

namespace glslrun::scene {

namespace {

struct Component {
    int id = 0, h = 1, v = 1;
};

struct Frame {
    bool seen = false, huffman = false, progressive = false;
    int width = 0, height = 0;
    std::vector<Component> components;
};

// Blocks of 8x8 samples of component c (its sampling factors against the largest).
uint64_t blocks_of(const Frame& f, const Component& c) {
    int hmax = 1, vmax = 1;
    for (const Component& k : f.components) hmax = std::max(hmax, k.h), vmax = std::max(vmax, k.v);
    uint64_t w = (uint64_t(f.width) * uint64_t(c.h) + uint64_t(hmax) - 1) / uint64_t(hmax);
    uint64_t h = (uint64_t(f.height) * uint64_t(c.v) + uint64_t(vmax) - 1) / uint64_t(vmax);
    return ((w + 7) / 8) * ((h + 7) / 8);
}

bool read_frame(const unsigned char* s, size_t length, uint8_t marker, Frame& f) {
    if (length < 6) return false;
    f.seen = true;
    // Huffman coding (SOF0..SOF2): stb's only kinds; the others fail in stb.
    f.huffman = marker <= 0xC2;
    f.progressive = marker == 0xC2;
    f.height = s[1] << 8 | s[2];
    f.width = s[3] << 8 | s[4];
    const size_t n = s[5];
    if (length < 6 + 3 * n) return false;
    for (size_t i = 0; i < n; ++i)
        f.components.push_back({s[6 + 3 * i], std::max(1, s[7 + 3 * i] >> 4), std::max(1, s[7 + 3 * i] & 15)});
    return true;
}

}  // namespace

Status check_jpeg_work(const std::string& path, const std::vector<unsigned char>& d) {
    auto corrupt = [&](const char* why) { return Error(fmt::format("the JPEG '{}' is corrupt: {}", path, why)); };
    Frame frame;
    size_t scans = 0, entropy_bytes = 0;
    uint64_t block_visits = 0;  // blocks of each scan's components, summed over the scans
    std::vector<int> dc_first;  // the components a progressive DC-first scan codes
    size_t pos = 2;             // after SOI
    while (pos + 1 < d.size()) {
        if (d[pos] != 0xFF) return corrupt("bytes between its markers");
        while (pos + 1 < d.size() && d[pos + 1] == 0xFF) ++pos;  // fill bytes
        const uint8_t marker = d[pos + 1];
        if (marker == 0xD9) break;  // EOI
        if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length
            pos += 2;
            continue;
        }
        if (pos + 4 > d.size()) return corrupt("it ends inside a marker");
        const size_t length = size_t(d[pos + 2]) << 8 | d[pos + 3];
        if (length < 2 || pos + 2 + length > d.size()) return corrupt("a marker's length runs past its end");
        const unsigned char* body = d.data() + pos + 4;
        const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (sof && !read_frame(body, length - 2, marker, frame)) return corrupt("a short frame header");
        pos += 2 + length;
        if (marker != 0xDA) continue;
        if (++scans > kMaxJpegScans)
            return Error(fmt::format("the JPEG '{}' has more than {} scans: its decoding would take minutes, not "
                                     "its size (progressive files have about 10)",
                                     path, kMaxJpegScans));
        const size_t ns = length > 2 ? body[0] : 0;
        // The decoder visits every block of each of the scan's components, coded or not.
        for (size_t i = 0; i < ns && 1 + 2 * i < length - 2; ++i)
            for (const Component& c : frame.components)
                if (c.id == body[1 + 2 * i]) block_visits += blocks_of(frame, c);
        if (block_visits > kMaxJpegBlockVisits)
            return Error(fmt::format("the JPEG '{}' asks its decoder for more than {} block decodes ({} scans of "
                                     "{}x{} pixels so far), glslrun's limit (docs/limits.md): its decoding would "
                                     "take seconds, not its size (a progressive file of the largest texture "
                                     "needs about 4M)",
                                     path, kMaxJpegBlockVisits, scans, frame.width, frame.height));
        // Ss = 0 and Ah = 0: a DC scan's first pass, which codes every block of its components.
        if (length >= 6 + 2 * ns && body[1 + 2 * ns] == 0 && body[3 + 2 * ns] >> 4 == 0)
            for (size_t i = 0; i < ns; ++i) dc_first.push_back(body[1 + 2 * i]);
        // The entropy-coded data runs to the next marker that is not a byte
        // stuffing (FF 00) or a restart marker.
        const size_t start = pos;
        while (pos + 1 < d.size() && !(d[pos] == 0xFF && d[pos + 1] != 0 && (d[pos + 1] < 0xD0 || d[pos + 1] > 0xD7)))
            ++pos;
        entropy_bytes += pos - start;
    }
    if (!frame.seen || !frame.huffman) return Ok{};  // stb says what is wrong
    // Every block costs at least one bit in a progressive DC-first scan, and
    // at least two in a baseline scan (a DC code and an AC end of block);
    // a file with less data than that cannot hold the size its header states.
    uint64_t least_bits = 0;
    for (const Component& c : frame.components) {
        const bool coded = !frame.progressive || std::find(dc_first.begin(), dc_first.end(), c.id) != dc_first.end();
        if (!coded) return corrupt("a component has no DC scan: the image would be left empty");
        least_bits += blocks_of(frame, c) * (frame.progressive ? 1 : 2);
    }
    if (uint64_t(entropy_bytes) * 8 < least_bits)
        return Error(fmt::format("the JPEG '{}' states {}x{} pixels, but its {} bytes of image data cannot hold "
                                 "that many (at least {}): the header lies about the size or the file is cut short",
                                 path, frame.width, frame.height, entropy_bytes, (least_bits + 7) / 8));
    return Ok{};
}

}  // namespace glslrun::scene
