// test_large_pages.cpp: reserve_large keeps a vector's contents; the range it advises is the
// array's 2 MiB-aligned part (against a walk over the boundaries, on every system), and on Linux
// with transparent huge pages that part carries the advice (the "hg" flag of its mapping in
// /proc/self/smaps).
#include <doctest/doctest.h>

#include "large_pages.h"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>

namespace {

// The VmFlags line of the mapping that contains address `a` ("" when not found).
std::string vm_flags(uintptr_t a) {
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-') {
            inside = lo <= a && a < hi;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

}  // namespace

TEST_CASE("reserve_large: the capacity asked for, the contents kept") {
    std::vector<uint64_t> v = {1, 2, 3};
    ca::reserve_large(v, size_t(1) << 21);   // 16 MiB
    CHECK(v.capacity() >= size_t(1) << 21);
    CHECK(v == std::vector<uint64_t>{1, 2, 3});
    const uint64_t* before = v.data();
    ca::reserve_large(v, 10);   // already enough: unchanged
    CHECK(v.data() == before);
    std::vector<int> small;
    ca::reserve_large(small, 100);   // below kLargeArrayBytes: a plain reserve
    CHECK(small.capacity() >= 100);
}

// The advised range against a walk over the 2 MiB boundaries (checked on every system, THP or not).
TEST_CASE("huge_page_range: from the first 2 MiB boundary in the array to the last") {
    const uintptr_t huge = uintptr_t(2) << 20;
    for (uintptr_t start : {huge * 8, huge * 8 + 1, huge * 9 - 1, huge * 9 - 4096, huge * 8 + 12345})
        for (size_t bytes : {ca::kLargeArrayBytes - 1, ca::kLargeArrayBytes, size_t(5) << 20, (size_t(7) << 20) + 3}) {
            CAPTURE(start);
            CAPTURE(bytes);
            uintptr_t begin = 0, end = 0;   // by walking the boundaries in [start, start + bytes]
            for (uintptr_t b = huge * 8; b <= start + bytes; b += huge) {
                if (b >= start && begin == 0) begin = b;
                if (b >= start) end = b;
            }
            const ca::HugePageRange r = ca::huge_page_range(reinterpret_cast<const void*>(start), bytes);
            if (bytes < ca::kLargeArrayBytes) {
                CHECK(r.begin >= r.end);   // too small to advise
                continue;
            }
            CHECK(r.begin == begin);
            CHECK(r.end == end);
        }
}

TEST_CASE("reserve_large: a large array's aligned part carries the huge-page advice") {
    std::vector<double> v;
    ca::reserve_large(v, size_t(4) << 20);   // 32 MiB
    const ca::HugePageRange r = ca::huge_page_range(v.data(), v.capacity() * sizeof(double));
    REQUIRE(r.end > r.begin);
    const std::string flags = vm_flags(r.begin);
    REQUIRE(!flags.empty());   // the range lies in a mapping of this process
    struct stat st;
    // without THP in this kernel there is no advice to see; the range above is still checked
    if (stat("/sys/kernel/mm/transparent_hugepage", &st) == 0) CHECK(flags.find(" hg") != std::string::npos);
}
