// The glslrun command's operator new: blocks of 4 MB or more in transparent
// huge pages (raster/huge_pages.h), everything else from malloc as before.
// The framebuffer's vectors are std::vector<float> (the public API), so the
// library cannot choose their pages; here the command does. A 512x512
// framebuffer took 1,282 page faults (2.7 ms of a 26 ms process, perf) when
// it was allocated; with its colour (4 MB) in huge pages, about 260.
// Smaller blocks stay in small pages: with 1 MB, `glslrun test` (a child
// process per test, 1 MB framebuffers at piglit's 250x250) took longer.
#include <cstddef>
#include <cstdlib>
#include <new>

#include "raster/huge_pages.h"

namespace {
constexpr std::size_t kHugeNewMinimum = std::size_t(4) << 20;
}

void* operator new(std::size_t bytes) {
    void* p = bytes >= kHugeNewMinimum ? glslrun::raster::allocate_huge(bytes) : std::malloc(bytes ? bytes : 1);
    if (!p) throw std::bad_alloc();
    return p;
}

// Both kinds of block are released by free().
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
