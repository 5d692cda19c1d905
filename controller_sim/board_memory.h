// Storage for the controller's large buffers (the depth buffer): a std::vector allocator
// that gives a buffer of 2 MiB or more whole 2 MiB pages and asks Linux to back it with
// transparent huge pages (madvise MADV_HUGEPAGE, honoured where the system's setting is
// "madvise" or "always"). A frame's depth buffer is made at its DEPTH_CLEAR; on 4 KiB pages
// its first fill took one page fault per 1,024 words, the larger part of a DEPTH_CLEAR's
// time on a virtual machine. Smaller buffers, and systems without the call, get plain
// operator new.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace fb89::controller {

template <class T>
struct BoardMemoryAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage = std::size_t{2} << 20;

    BoardMemoryAllocator() = default;
    template <class U>
    BoardMemoryAllocator(const BoardMemoryAllocator<U>&) {}

    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return static_cast<T*>(::operator new(bytes));
        const std::size_t whole = (bytes + kHugePage - 1) / kHugePage * kHugePage;
        void* p = ::operator new (whole, std::align_val_t{kHugePage});
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        ::madvise(p, whole, MADV_HUGEPAGE);  // advice only: refused, the pages are 4 KiB
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) {
        if (n * sizeof(T) < kHugePage)
            ::operator delete(p);
        else
            ::operator delete (p, std::align_val_t{kHugePage});
    }

    friend bool operator==(const BoardMemoryAllocator&, const BoardMemoryAllocator&) = default;
};

template <class T>
using BoardVector = std::vector<T, BoardMemoryAllocator<T>>;

}  // namespace fb89::controller
