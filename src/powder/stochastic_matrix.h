//! A sparse row-stochastic matrix in compressed rows: row i's entries are
//! column[row_start[i] .. row_start[i+1]) with their weights, which sum to 1.
//! The transfer T(g) and settle S(g) matrices of the drainability model.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fabvdb::powder {

struct StochasticMatrix {
    std::vector<uint32_t> row_start{0};
    std::vector<uint32_t> column;
    std::vector<float> weight;

    size_t rows() const { return row_start.size() - 1; }
};

}  // namespace fabvdb::powder
