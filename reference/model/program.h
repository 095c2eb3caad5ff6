#pragma once
// A parsed ISO-6983 (G-code) program: blocks of address words, each word remembering where it
// stood in the source, so that every error and alarm can name file, line and column.
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cyclecert {

struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;
};

struct Word {
  char letter = 0;          // upper case address letter
  double value = 0;         // the number as written (no unit conversion, no scaling)
  bool hasDecimalPoint = false;
  std::string text;         // the source text of the word, e.g. "X-0.6"
  int line = 0;
  int column = 0;
};

// The words of a block with one address, in source order: for (const Word* g : block.all('G')).
// A view over the block's words (nothing copied); valid while the block is.
class WordsWith {
 public:
  class Iterator {
   public:
    Iterator(const Word* at, const Word* end, char letter) : at_(at), end_(end), letter_(letter) { skip(); }
    const Word* operator*() const { return at_; }
    Iterator& operator++() {
      ++at_;
      skip();
      return *this;
    }
    bool operator!=(const Iterator& other) const { return at_ != other.at_; }

   private:
    void skip() {
      while (at_ != end_ && at_->letter != letter_) ++at_;
    }
    const Word* at_;
    const Word* end_;
    char letter_;
  };
  WordsWith(const std::vector<Word>& words, char letter) : words_(words), letter_(letter) {}
  Iterator begin() const { return {words_.data(), words_.data() + words_.size(), letter_}; }
  Iterator end() const { return {words_.data() + words_.size(), words_.data() + words_.size(), letter_}; }

 private:
  const std::vector<Word>& words_;
  char letter_;
};

struct Block {
  int line = 0;                    // source line where the block starts
  std::optional<long> sequence;    // N number
  std::vector<Word> words;         // in source order, N and O excluded
  std::string comment;             // text of (...) comments, joined
  bool blockDelete = false;        // leading '/'
  std::string text;                // the block's source text

  const Word* find(char letter) const;            // first word with that address
  WordsWith all(char letter) const { return {words, letter}; }
  bool has(char letter) const { return find(letter) != nullptr; }
  // True when a G word with this code is present; code is ×10 (G74.1 -> 741, G01 -> 10).
  bool hasG(int codeTimes10) const;
};

// A program named on its '%' line, as Huazhong writes it ("%3304").
struct PercentName {
  std::string text;  // "%3304"
  int line = 0;
};

struct Program {
  std::string file;
  std::optional<long> number;  // O number
  std::optional<PercentName> percentName;
  std::vector<Block> blocks;

  // Index of the first block with sequence number n, or nothing.
  std::optional<std::size_t> findSequence(long n) const;
};

// Malformed source text: where, and what was expected there.
class ParseError : public std::runtime_error {
 public:
  ParseError(SourceLoc loc, std::string expected, std::string found);
  const SourceLoc& loc() const { return loc_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  SourceLoc loc_;
  std::string expected_;
  std::string found_;
};

// G-code value ×10 rounded, so G74.1 compares as 741 and G01 as 10.
int gCode10(double value);

}  // namespace cyclecert
