// large_pages.h: arrays of many megabytes on transparent huge pages where the system offers them.
// The first write to each 4 KiB page of a fresh allocation is a page fault, and on virtual
// machines a fault costs microseconds: for the arrays a mesh of millions of triangles needs
// (trees, hash tables, buckets) the faults take longer than the work that fills them. A 2 MiB
// page takes one fault where 4 KiB pages take 512. Linux only (madvise MADV_HUGEPAGE, honoured
// when transparent huge pages are in "madvise" or "always" mode); elsewhere, and below
// kLargeArrayBytes, a plain reserve. The advice changes where memory lives, never its contents.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace ca {

// Below this an array spans too few 2 MiB pages for the advice to matter.
constexpr size_t kLargeArrayBytes = size_t(4) << 20;

constexpr uintptr_t kHugePageBytes = uintptr_t(2) << 20;

// The part of [data, data + bytes) the advice covers: from the first 2 MiB boundary at or after
// data to the last at or before its end (begin >= end: none); none below kLargeArrayBytes.
struct HugePageRange {
    uintptr_t begin = 0, end = 0;
};
inline HugePageRange huge_page_range(const void* data, size_t bytes) {
    if (bytes < kLargeArrayBytes) return {};
    const uintptr_t a = reinterpret_cast<uintptr_t>(data);
    return {(a + kHugePageBytes - 1) & ~(kHugePageBytes - 1), (a + bytes) & ~(kHugePageBytes - 1)};
}

// Advises huge pages for huge_page_range(data, bytes); pages already written keep their size.
// Failure (no THP support) is harmless and ignored.
inline void advise_huge_pages(const void* data, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const HugePageRange r = huge_page_range(data, bytes);
    if (r.end > r.begin) (void)madvise(reinterpret_cast<void*>(r.begin), r.end - r.begin, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

// v.reserve(n), with the new storage advised before anything is written to it.
template <class T>
void reserve_large(std::vector<T>& v, size_t n) {
    if (n <= v.capacity()) return;
    v.reserve(n);
    advise_huge_pages(v.data(), n * sizeof(T));
}

}  // namespace ca
