//! Seeded operator routines (see sandpile_routine.h).
#include "powder/sandpile_routine.h"

#include <random>

#include "core/error.h"

namespace fabvdb::powder {

std::vector<Vec3> operator_routine(const Vec3& first, const std::vector<Vec3>& orientation_set, int turns,
                                   uint64_t seed) {
    if (turns < 1) throw Error(FABVDB_ERR_INVALID_ARGUMENT, "a routine needs at least one turn");
    if (turns > 1 && orientation_set.empty())
        throw Error(FABVDB_ERR_INVALID_ARGUMENT, "the orientation set is empty");
    std::vector<Vec3> routine{first};
    std::mt19937_64 generator(seed);
    for (int turn = 1; turn < turns; ++turn)
        routine.push_back(orientation_set[size_t(generator() % orientation_set.size())]);
    return routine;
}

}  // namespace fabvdb::powder
