//! Whether a mesh is a closed cycle (see closed_cycle.h).
#include "volume/closed_cycle.h"

namespace fabvdb::volume {

bool is_closed_cycle(const EdgeTable& welded_edges) {
    for (size_t e = 0; e < welded_edges.edge_count(); ++e) {
        int sum = 0;
        for (size_t u = welded_edges.begin[e]; u < welded_edges.begin[e + 1]; ++u)
            sum += welded_edges.uses[u].forward ? 1 : -1;
        if (sum != 0) return false;
    }
    return true;
}

}  // namespace fabvdb::volume
