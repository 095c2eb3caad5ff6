#pragma once
// The command that reproduces a failing result, stored with it in results.jsonl and shown in the
// reports: whoever reads the report runs it to see the failure again.
#include <cstdint>
#include <string>

namespace cyclecert {

// `text` as one word for sh: in single quotes, with any single quote inside closed and escaped.
std::string shellQuote(const std::string& text);

// A spec or regression case: `cyclecert diff --engine E --vs B FILE`, which shows where E's
// toolpath parts from B's — B being the engine the case must agree with, else the reference, which
// meets every spec case. The reference itself: `cyclecert plan --case FILE`, which says whether it
// meets the case's expectation.
std::string caseReproduceCommand(const std::string& engine, const std::string& caseFile, const std::string& agreesWith);

// A generated case: the campaign's command narrowed to that case's seed (`--cases 1`).
std::string fuzzReproduceCommand(const std::string& engine, const std::string& vs, std::uint64_t caseSeed);

}  // namespace cyclecert
