// median.h: the median of a list of values as the library takes it everywhere: the element at
// position n / 2 of the sorted list (the upper one of an even count), found in linear time; 0 for
// an empty list.
#pragma once
#include <algorithm>
#include <vector>

namespace ca {

inline double median_of(std::vector<double> v) {
    if (v.empty()) return 0;
    const size_t mid = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + long(mid), v.end());
    return v[mid];
}

}  // namespace ca
