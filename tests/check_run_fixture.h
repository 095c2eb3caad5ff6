#pragma once
// A scratch folder with a specs/cases tree holding three real cases (a G71 toolpath, a G71 alarm,
// a G72 toolpath: the check runs them in that order), for check runs against faulty engines.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/run/check_run.h"

namespace cyclecert {

namespace fs = std::filesystem;

inline std::string source(const std::string& relative) { return std::string(CYCLECERT_SOURCE_DIR) + "/" + relative; }

class CheckRun : public ::testing::Test {
 protected:
  // The three cases, in the order the check runs them.
  static std::vector<std::string> caseIds() {
    return {"fanuc-0i-f/g71/g01-head-stepped-shaft", "fanuc-0i-f/g71/ps0064-z-reverse", "gsk/g72/first-infeed-g01"};
  }
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cyclecert-check-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    for (const std::string& id : caseIds()) {
      const fs::path to = dir_ / "specs/cases" / (id + ".json");
      fs::create_directories(to.parent_path());
      fs::copy_file(source("specs/cases/" + id + ".json"), to);
    }
  }
  void TearDown() override { fs::remove_all(dir_); }

  CheckOptions options() const { return {(dir_ / "specs").string(), "", (dir_ / "out").string(), false}; }
  std::vector<nlohmann::json> results() const {
    std::vector<nlohmann::json> lines;
    std::ifstream in(dir_ / "out/results.jsonl");
    std::string line;
    while (std::getline(in, line)) lines.push_back(nlohmann::json::parse(line));
    return lines;
  }
  std::string script(const std::string& name) const { return "sh " + source("tests/data/engines/" + name); }
  std::string cli() const { return CYCLECERT_CLI; }

  fs::path dir_;
};

}  // namespace cyclecert
