#pragma once
// Generators the fuzz case generators share (case_generator.cpp, g73_case_generator.cpp,
// siemens_case_generator.cpp).
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <rapidcheck.h>

namespace cyclecert {

// Hundredths of a millimetre as a program writes them: "12.5", "-0.05", "3" (no trailing zeros,
// as an ostream of precision 12 writes the value).
inline std::string mm(long hundredths) {
  std::string text = hundredths < 0 ? "-" : "";
  const unsigned long h = static_cast<unsigned long>(std::labs(hundredths));
  text += std::to_string(h / 100);
  if (const unsigned long fraction = h % 100) {
    text += '.';
    text += static_cast<char>('0' + fraction / 10);
    if (fraction % 10) text += static_cast<char>('0' + fraction % 10);
  }
  return text;
}

// A whole number in [from, to) drawn over the whole range at every size (RapidCheck scales inRange
// by the case's size); it still shrinks towards `from`.
inline rc::Gen<int> wholeRange(int from, int to) { return rc::gen::resize(100, rc::gen::inRange(from, to)); }

// RapidCheck's container of `element`s (as many as it draws, 0 … size, and the same elements) cut
// to the first `most`: a case uses no more, and drawing the rest (up to 100) was a third of the time
// spent generating. Shrinks as RapidCheck's containers do: elements removed, then each shrunk.
template <typename T>
inline rc::Gen<std::vector<T>> firstOf(std::size_t most, rc::Gen<T> element) {
  using Elements = std::vector<rc::Shrinkable<T>>;
  return [=](const rc::Random& random, int size) {
    rc::Random r = random;
    const std::size_t drawn = static_cast<std::size_t>(r.split().next() % static_cast<std::uint64_t>(size + 1));
    Elements elements;
    for (std::size_t i = 0; i < std::min(drawn, most); ++i) elements.push_back(element(r.split(), size));
    return rc::shrinkable::map(
        rc::shrinkable::shrinkRecur(std::move(elements),
                                    [](const Elements& e) {
                                      return rc::seq::concat(
                                          rc::shrink::removeChunks(e),
                                          rc::shrink::eachElement(e, [](const rc::Shrinkable<T>& s) { return s.shrinks(); }));
                                    }),
        [](const Elements& e) {
          std::vector<T> values;
          for (const rc::Shrinkable<T>& s : e) values.push_back(s.value());
          return values;
        });
  };
}

}  // namespace cyclecert
