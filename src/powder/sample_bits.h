//! Sets of powder samples as bits over their ranks in a cavity (lowest
//! first, 64 to a word): set and test one, count the set bits before each
//! word, and count those below a fractional rank. Header-only, no state.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fabvdb::powder {

inline void set_bit(std::vector<uint64_t>& bits, size_t i) { bits[i >> 6] |= uint64_t(1) << (i & 63); }
inline bool bit(const std::vector<uint64_t>& bits, size_t i) { return (bits[i >> 6] >> (i & 63)) & 1u; }

//! Per word w (and one past the last): the set bits in the words before w.
inline std::vector<uint32_t> words_before(const std::vector<uint64_t>& bits) {
    std::vector<uint32_t> before(bits.size() + 1, 0);
    for (size_t w = 0; w < bits.size(); ++w) before[w + 1] = before[w] + uint32_t(__builtin_popcountll(bits[w]));
    return before;
}

//! Set bits below position `i` (fractional: the bit at floor(i) counts in
//! part) of the first `size`, given `before` = words_before(bits).
inline double count_below(const std::vector<uint64_t>& bits, const std::vector<uint32_t>& before, double i,
                          size_t size) {
    const size_t whole = std::min(size_t(i), size);
    const size_t w = whole >> 6;
    double count = before[w];
    if (whole & 63) count += __builtin_popcountll(bits[w] & ((uint64_t(1) << (whole & 63)) - 1));
    if (whole < size && bit(bits, whole)) count += i - double(whole);
    return count;
}

}  // namespace fabvdb::powder
