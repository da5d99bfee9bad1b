// The glslrun command's operator new: blocks of 4 MB or more in transparent
// huge pages (raster/huge_pages.h), everything else from malloc as before.
// The framebuffer's vectors are std::vector<float> (the public API), so the
// library cannot choose their pages; here the command does. A 512x512
// framebuffer took 1,282 page faults (2.7 ms of a 26 ms process, perf) when
// it was allocated; with its colour (4 MB) in huge pages, about 260.
// Smaller blocks stay in small pages: with 1 MB, `glslrun test` (a child
// process per test, 1 MB framebuffers at piglit's 250x250) took longer.
#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>

#include "raster/huge_pages.h"

namespace {

constexpr std::size_t kHugeNewMinimum = std::size_t(4) << 20;

void* allocate(std::size_t bytes) noexcept {
    return bytes >= kHugeNewMinimum ? glslrun::raster::allocate_huge(bytes) : std::malloc(bytes ? bytes : 1);
}

void* allocate_or_throw(std::size_t bytes) {
    void* p = allocate(bytes);
    if (!p) throw std::bad_alloc();
    return p;
}

void* allocate_aligned(std::size_t bytes, std::align_val_t align) noexcept {
    std::size_t a = std::max(std::size_t(align), sizeof(void*));
    return std::aligned_alloc(a, (std::max<std::size_t>(bytes, 1) + a - 1) / a * a);
}

void* allocate_aligned_or_throw(std::size_t bytes, std::align_val_t align) {
    void* p = allocate_aligned(bytes, align);
    if (!p) throw std::bad_alloc();
    return p;
}

}  // namespace

// Every form is replaced, so that each block is released by the family that
// made it: a sanitizer's operator new[] freed by this delete (or the reverse)
// would be an alloc-dealloc mismatch. All blocks are released by free().
void* operator new(std::size_t bytes) { return allocate_or_throw(bytes); }
void* operator new[](std::size_t bytes) { return allocate_or_throw(bytes); }
void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept { return allocate(bytes); }
void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept { return allocate(bytes); }
void* operator new(std::size_t bytes, std::align_val_t a) { return allocate_aligned_or_throw(bytes, a); }
void* operator new[](std::size_t bytes, std::align_val_t a) { return allocate_aligned_or_throw(bytes, a); }
void* operator new(std::size_t bytes, std::align_val_t a, const std::nothrow_t&) noexcept {
    return allocate_aligned(bytes, a);
}
void* operator new[](std::size_t bytes, std::align_val_t a, const std::nothrow_t&) noexcept {
    return allocate_aligned(bytes, a);
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
