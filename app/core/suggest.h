// "Did you mean ...?" for unknown keys and enum values: a small edit
// distance over a short candidate list, so typos get a one-line fix.
#pragma once
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace ms {

// Optimal string alignment distance: Levenshtein plus swapping two adjacent
// letters as one edit ("lihgt" -> "light" is 1, plain Levenshtein says 2).
// ASCII case-insensitive, because "FOV" for "fov" is a typo, not a new word.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The first candidate nearest to `word`, or "" when none is close enough:
// at most 1 edit for words of up to 4 letters, 2 for longer ones.
std::string_view closest(std::string_view word, std::span<const std::string_view> candidates);

// "did you mean 'fov'?", or "" when nothing is close.
std::string did_you_mean(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace ms
