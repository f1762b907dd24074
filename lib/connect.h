// connect.h: step 3 of the pipeline: edges and triangles between the selected balls.
// Power-diagram route (paper 4.3): the regular triangulation of the selected balls (weight r'^2)
// together with surface samples (weight delta^2), by Qhull's 4-D lifting; an edge or triangle of
// the triangulation whose vertices are all selected balls becomes a skeleton edge or triangle.
#pragma once
#include "candidates.h"
#include "selection.h"
#include "skeleton.h"

namespace ca {

enum class ConnectMethod : int32_t { power = 0 };

struct ConnectOptions {
    ConnectMethod method = ConnectMethod::power;
};

// Skeleton in internal units; its balls are the selected balls (undilated radii), in selection order.
Status connect_balls(const CandidateSet& set, const Selection& sel, const ConnectOptions& opt,
                     const Monitor& monitor, Skeleton& out);

}  // namespace ca
