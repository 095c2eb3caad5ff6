#pragma once
// Running the `cyclecert` binary as a user or a CI job does, from GoogleTest: each test gets a
// private scratch folder, writes its input files there and reads the exit code, stdout and stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

struct CliRun {
  int exitCode;
  std::string out, err;
};

class CliFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cyclecert-cli-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name() + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }

  static std::string read(const std::string& file) {
    std::ifstream in(file);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  // A small spec suite in the scratch folder: these cases of the repository's specs/cases (by id)
  // and its rule catalogue, so that `check --specs` is quick. Returns the suite's folder.
  std::string copySpecSuite(const std::vector<std::string>& caseIds) const {
    const std::string source = CYCLECERT_SOURCE_DIR;
    std::filesystem::create_directories(dir_ / "specs");
    std::filesystem::copy_file(source + "/specs/rules.json", dir_ / "specs/rules.json");
    for (const std::string& id : caseIds) {
      const std::filesystem::path to = dir_ / "specs/cases" / (id + ".json");
      std::filesystem::create_directories(to.parent_path());
      std::filesystem::copy_file(source + "/specs/cases/" + id + ".json", to);
    }
    return path("specs");
  }

  // A JSON-lines file (results.jsonl), one value per line.
  static std::vector<nlohmann::json> jsonLines(const std::string& file) {
    std::vector<nlohmann::json> lines;
    std::istringstream in(read(file));
    for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
    return lines;
  }

  // `prefix`: shell text run before the command in the same shell (e.g. "ulimit -f 16; exec").
  CliRun run(const std::string& args, const std::string& prefix = "") const {
    const std::string errFile = path("stderr.txt");
    const std::string command = prefix + " " + std::string(CYCLECERT_CLI) + " " + args + " 2>" + errFile;
    FILE* pipe = ::popen(command.c_str(), "r");
    std::string out;
    char buf[4096];
    while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
    const int status = ::pclose(pipe);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out, read(errFile)};
  }

  std::filesystem::path dir_;
};
