#pragma once
// The spec suite's fingerprint for run.json and the reports: which rules and cases a run was judged
// by. SHA-256 (hex) over specs/rules.json and every specs/cases/**/*.json in the order of their
// paths relative to the specs directory ("/"-separated), each fed as: path, NUL, size in decimal,
// NUL, contents — so that no two different suites can feed the same bytes.
#include <string>

namespace cyclecert {

std::string specSuiteHash(const std::string& specsDir);  // throws std::runtime_error naming a file it cannot read

}  // namespace cyclecert
