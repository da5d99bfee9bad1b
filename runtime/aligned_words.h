// A zeroed array of register words on a cache-line boundary: the register
// files of the interpreter and of the JIT's executors.
#pragma once
#include <cstddef>
#include <cstring>
#include <new>

namespace glslrun::rt {

template <class W>
struct AlignedWords {
    static constexpr std::align_val_t kAlign{64};
    W* data = nullptr;
    explicit AlignedWords(size_t n) : data(static_cast<W*>(::operator new[](n * sizeof(W), kAlign))) {
        std::memset(data, 0, n * sizeof(W));
    }
    ~AlignedWords() { ::operator delete[](data, kAlign); }
    AlignedWords(const AlignedWords&) = delete;
    AlignedWords& operator=(const AlignedWords&) = delete;
};

}  // namespace glslrun::rt
