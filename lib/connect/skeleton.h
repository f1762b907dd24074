// skeleton.h: the medial skeleton (balls joined by edges and triangles) and its topology
// statistics: connected components, isolated balls, first Betti number of the complex.
#pragma once
#include "common.h"

namespace ca {

struct Skeleton {
    std::vector<Ball> balls;
    std::vector<std::array<uint32_t, 2>> edges;   // i < j, unique, includes every face edge
    std::vector<Tri> faces;                       // i < j < k, unique
};

struct TopologyStats {
    size_t components = 0;   // connected components of the 1-skeleton (isolated balls count)
    size_t isolated = 0;     // balls with no edge
    long betti1 = 0;         // first Betti number of the 2-complex over GF(2)
};

// A subspace of GF(2)^rows spanned by sparse vectors (sorted indices), kept in echelon form by
// largest index ("pivot"): the face boundaries of a complex, against which cycles are tested.
class Gf2Basis {
public:
    explicit Gf2Basis(size_t rows) : column_with_pivot_(rows, -1) {}
    bool add(std::vector<uint32_t> v);                 // true if v was independent (then kept)
    bool spans(std::vector<uint32_t> v) const;         // v is in the subspace
    size_t rank() const { return columns_.size(); }
private:
    void reduce(std::vector<uint32_t>& v) const;
    std::vector<std::vector<uint32_t>> columns_;
    std::vector<int64_t> column_with_pivot_;
};

// Sorts and de-duplicates edges/faces and adds every face edge as an edge.
void canonicalize(Skeleton& s);
TopologyStats topology(const Skeleton& s);

}  // namespace ca
