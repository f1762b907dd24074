// test_large_pages.cpp: reserve_large keeps a vector's contents and, on Linux with transparent
// huge pages, leaves the huge-page advice on the array's 2 MiB-aligned part (the "hg" flag of
// its mapping in /proc/self/smaps).
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

TEST_CASE("reserve_large: a large array's aligned part carries the huge-page advice") {
    struct stat st;
    if (stat("/sys/kernel/mm/transparent_hugepage", &st) != 0) return;   // no THP in this kernel: nothing to advise
    std::vector<double> v;
    ca::reserve_large(v, size_t(4) << 20);   // 32 MiB
    const uintptr_t huge = uintptr_t(2) << 20;
    const uintptr_t aligned = (reinterpret_cast<uintptr_t>(v.data()) + huge - 1) & ~(huge - 1);
    const std::string flags = vm_flags(aligned);
    REQUIRE(!flags.empty());
    CHECK(flags.find(" hg") != std::string::npos);
}
