// libFuzzer target: the scene parser (TOML and every value check). The path
// is in a directory that does not exist, so texture and OBJ references fail
// at once instead of reading the machine's files.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "glslrun/scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    (void)glslrun::scene::parse_scene(text, "/nonexistent-fuzz-dir/fuzz.toml");
    return 0;
}
