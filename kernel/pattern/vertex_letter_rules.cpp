#include "kernel/pattern/vertex_letter_rules.hpp"

#include <cstdlib>
#include <stdexcept>
#include <utility>
#include <string>

namespace rigidfold {

namespace {

// Crimp reduction on copies (degree <= 20: at most 9 levels).
bool crimp_reduces(std::vector<double> s, std::vector<int> letter, double tol) {
  const int d = static_cast<int>(s.size());
  if (d == 2) return letter[0] == letter[1];
  auto at = [d](int i) { return ((i % d) + d) % d; };
  auto crimped = [&](int i) {
    // Sector k lies after crease k. Creases i and i+1 go; sectors i-1, i, i+1 become one
    // sector after crease i-1, in the place of sector i-1.
    std::vector<double> s2;
    std::vector<int> l2;
    const int prev = at(i - 1), next = at(i + 1);
    for (int k = 0; k < d; ++k) {
      if (k == i || k == next) continue;
      s2.push_back(k == prev ? s[prev] - s[i] + s[next] : s[k]);
    }
    for (int k = 0; k < d; ++k)
      if (k != i && k != at(i + 1)) l2.push_back(letter[k]);
    return std::make_pair(std::move(s2), std::move(l2));
  };
  bool any_strict = false;
  for (int i = 0; i < d; ++i) {
    const bool strict = s[i] < s[at(i - 1)] - tol && s[i] < s[at(i + 1)] - tol;
    if (!strict) continue;
    if (letter[i] == letter[at(i + 1)]) return false;  // big-little-big
    any_strict = true;
  }
  for (int i = 0; i < d; ++i) {
    const bool local_min = s[i] <= s[at(i - 1)] + tol && s[i] <= s[at(i + 1)] + tol;
    const bool strict = s[i] < s[at(i - 1)] - tol && s[i] < s[at(i + 1)] - tol;
    if (!local_min || letter[i] == letter[at(i + 1)]) continue;
    if (any_strict && !strict) continue;
    auto [s2, l2] = crimped(i);
    if (crimp_reduces(std::move(s2), std::move(l2), tol)) return true;
    if (strict) return false;  // crimping a strict minimum loses nothing: no other order helps
  }
  return false;
}

}  // namespace

bool letters_fold_flat(std::span<const double> sectors, std::span<const int> letters, double equal_tolerance) {
  const std::size_t d = sectors.size();
  if (d != letters.size() || d < 2 || d % 2 != 0) return false;
  for (int l : letters)
    if (l != 1 && l != -1) return false;
  return crimp_reduces(std::vector<double>(sectors.begin(), sectors.end()), std::vector<int>(letters.begin(), letters.end()),
                       equal_tolerance);
}

std::vector<std::uint32_t> flat_folding_letter_masks(std::span<const double> sectors, double equal_tolerance) {
  const int d = static_cast<int>(sectors.size());
  if (d > kMaxLetterDegree)
    throw std::invalid_argument("flat_folding_letter_masks: degree " + std::to_string(d) + " above " +
                                std::to_string(kMaxLetterDegree));
  std::vector<std::uint32_t> out;
  if (d < 2 || d % 2 != 0) return out;
  std::vector<int> letters(d);
  for (std::uint32_t mask = 0; mask < (1u << d); ++mask) {
    int valleys = 0;
    for (int i = 0; i < d; ++i) {
      letters[i] = (mask >> i) & 1u ? 1 : -1;
      valleys += letters[i] > 0;
    }
    if (std::abs(2 * valleys - d) != 2) continue;  // Maekawa, a necessary condition: skip early
    if (letters_fold_flat(sectors, letters, equal_tolerance)) out.push_back(mask);
  }
  return out;
}

}  // namespace rigidfold
