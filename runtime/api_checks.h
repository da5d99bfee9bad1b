// What the public API checks of its arguments before it uses them: every
// enum within its enumerators (a value cast from an int past the last one
// indexed tables and arrays: TextureTarget(200) wrote past
// GLState::TextureUnit::bound), and the sizes of batches before their
// storage is allocated. Internal to the library.
#pragma once
#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>

#include "glslrun/glslrun.h"

namespace glslrun::rt {

// Whether `value` is one of E's enumerators 0..last.
template <class E>
constexpr bool enum_in_range(E value, E last) {
    return uint64_t(value) <= uint64_t(last);
}

Status check_exec_options(const ExecOptions& exec);
// Every enum of the state, and of the sampler state of every bound texture
// (GL_INVALID_ENUM).
Status check_gl_enums(const GLState& gl);
Status check_texture_enums(TextureTarget target, TextureFormat format);

// Elements a draw or a run_* call takes (vertices, fragments), and the words
// of storage one element needs there: refused past kMaxBatchElements or
// kMaxBatchBytes of outputs, before anything is allocated (a count of
// 2^32 - 1 without arrays ended in std::bad_alloc).
inline constexpr uint64_t kMaxBatchElements = uint64_t(1) << 26;  // as many as the framebuffer's pixels
inline constexpr uint64_t kMaxBatchBytes = uint64_t(1) << 30;  // 1 GiB
Status check_batch_size(uint64_t count, uint64_t words_per_element, const char* what);

// call(), with an allocation failure (std::bad_alloc, std::length_error)
// returned as an Error naming `what`: the API's functions return errors and
// never throw. Sizes are checked before allocating; this catches the memory
// that runs out below the limits.
Error out_of_memory(const char* what);
template <class F>
auto without_throwing(const char* what, F&& call) -> decltype(call()) {
    try {
        return call();
    } catch (const std::bad_alloc&) {
        return out_of_memory(what);
    } catch (const std::length_error&) {
        return out_of_memory(what);
    }
}

}  // namespace glslrun::rt
