#include "harness/spec/spec_suite_hash.h"

#include <openssl/evp.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace cyclecert {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> suiteFiles(const fs::path& specsDir) {
  std::vector<std::string> files;
  if (fs::is_regular_file(specsDir / "rules.json")) files.push_back("rules.json");
  if (fs::is_directory(specsDir / "cases")) {
    for (const auto& entry : fs::recursive_directory_iterator(specsDir / "cases")) {
      if (entry.is_regular_file() && entry.path().extension() == ".json") {
        files.push_back(fs::relative(entry.path(), specsDir).generic_string());
      }
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string contentsOf(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string specSuiteHash(const std::string& specsDir) {
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) throw std::runtime_error("SHA-256 unavailable");
  const auto feed = [&](const std::string& bytes) {
    EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size());
    EVP_DigestUpdate(ctx.get(), "", 1);  // the NUL after each field
  };
  for (const std::string& relative : suiteFiles(specsDir)) {
    const std::string contents = contentsOf(fs::path(specsDir) / relative);
    feed(relative);
    feed(std::to_string(contents.size()));
    EVP_DigestUpdate(ctx.get(), contents.data(), contents.size());
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 15];
  }
  return out;
}

}  // namespace cyclecert
