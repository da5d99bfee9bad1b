// An allocator for draw()'s large working arrays: blocks of 1 MB or more are
// 2 MB-aligned and marked for transparent huge pages (madvise), so that a
// first draw takes one page fault per 2 MB instead of one per 4 KB. Page
// faults cost about 1.8 us each on the 2-vCPU machine of docs/performance.md;
// a first 512x512 draw of the spot teapot took about 400 of them, half on
// its set-up primitives. Where transparent huge pages are off, the advice
// does nothing and this is an aligned allocation.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <new>

#include <sys/mman.h>

namespace glslrun::raster {

inline constexpr size_t kHugePage = size_t(2) << 20;
inline constexpr size_t kHugePageMinimum = size_t(1) << 20;

// A block of `bytes` >= kHugePageMinimum: 2 MB-aligned, its size rounded up
// to 2 MB, advised for huge pages; std::free releases it. Null when out of memory.
inline void* allocate_huge(size_t bytes) {
    if (bytes > size_t(-1) - kHugePage) return nullptr;
    size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p) (void)madvise(p, rounded, MADV_HUGEPAGE);  // advice: refused, small pages stay
    return p;
}

template <class T>
struct HugePageAllocator {
    using value_type = T;
    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) {}

    T* allocate(size_t n) {
        if (n > size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        size_t bytes = n * sizeof(T);
        if (bytes < kHugePageMinimum) return static_cast<T*>(::operator new(bytes));
        void* p = allocate_huge(bytes);
        if (!p) throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, size_t n) {
        if (n * sizeof(T) < kHugePageMinimum)
            ::operator delete(p);
        else
            std::free(p);
    }
    template <class U>
    bool operator==(const HugePageAllocator<U>&) const { return true; }
};

}  // namespace glslrun::raster
