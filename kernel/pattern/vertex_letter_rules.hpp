#pragma once
// Which mountain-valley letters fold one flat-foldable vertex flat (local flat foldability).
//
// A vertex with sectors s_0 .. s_{d-1} (s_i between creases i and i+1, cyclic; Kawasaki holds:
// the alternating sum is 0 and the sum is 2 pi) and a letter per crease folds flat iff the
// crimp reduction succeeds: repeatedly take a sector that is no larger than both neighbours
// and whose two creases carry opposite letters, crimp it (the two creases go, the three
// sectors become one of s_{i-1} - s_i + s_{i+1}), until two creases with the same letter
// remain. A sector strictly smaller than both neighbours must have opposite letters
// (big-little-big); among equal small sectors the reduction tries each candidate. Each crimp
// removes one M and one V, so Maekawa (|#M - #V| = 2) follows.
// Degree 4 with distinct smallest sector: the 4 letter sets of the two rigid modes, up to
// sign; d equal sectors: 2 C(d, d/2 - 1) letter sets (Hull 2003).
// Units: radians. equal_tolerance: sectors closer than this count as equal.
#include <cstdint>
#include <span>
#include <vector>

namespace rigidfold {

// letters[i] = +1 valley, -1 mountain (crease i). False for odd degree or a letter not +-1.
bool letters_fold_flat(std::span<const double> sectors, std::span<const int> letters, double equal_tolerance = 1e-9);

// Every letter set that folds the vertex flat, as bit masks (bit i set: crease i is a valley),
// in increasing order. Throws std::invalid_argument for degree > kMaxLetterDegree.
inline constexpr int kMaxLetterDegree = 20;
std::vector<std::uint32_t> flat_folding_letter_masks(std::span<const double> sectors, double equal_tolerance = 1e-9);

}  // namespace rigidfold
