// The glslrun command's operator new: blocks of 1 MB or more in transparent
// huge pages (raster/huge_pages.h), everything else from malloc as before.
// The framebuffer's vectors are std::vector<float> (the public API), so the
// library cannot choose their pages; here the command does. A 512x512
// framebuffer took 1,282 page faults (2.7 ms of a 26 ms process, perf) when
// it was allocated; in huge pages it takes a few.
#include <cstdlib>
#include <new>

#include "raster/huge_pages.h"

void* operator new(std::size_t bytes) {
    void* p = bytes >= glslrun::raster::kHugePageMinimum ? glslrun::raster::allocate_huge(bytes)
                                                         : std::malloc(bytes ? bytes : 1);
    if (!p) throw std::bad_alloc();
    return p;
}

// Both kinds of block are released by free().
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
