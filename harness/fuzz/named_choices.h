#pragma once
// The fuzz generators' choices by name (case_generator.cpp, g73_case_generator.cpp). A generator
// draws its choices 0…9 as one RapidCheck container — the order of the draws is what a case seed
// regenerates, so it never changes — and reads them into a struct of named fields in one place;
// each decision then reads a named choice, never an index.
#include <cstddef>
#include <string>
#include <vector>

namespace cyclecert {

// Choice `i` of those drawn, or 0 when fewer were drawn (the choices shrink towards 0).
inline int choiceAt(const std::vector<int>& drawn, std::size_t i) { return i < drawn.size() ? drawn[i] : 0; }

// The profile a choice 0…9 picks: fanuc-0i-f six times in ten, fanuc-0i-c two, gsk two.
inline std::string profileChosen(int choice) {
  return choice < 6 ? "fanuc-0i-f" : choice < 8 ? "fanuc-0i-c" : "gsk";
}

}  // namespace cyclecert
