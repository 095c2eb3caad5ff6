// Input that is not a document (issue 13, defect 7): a directory, a FIFO, a device or a file over
// the cap is refused at once with the reason — never read as nothing, never read forever.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/io/input_file.h"
#include "harness/spec/spec_case.h"
#include "tests/cli_fixture.h"

namespace cyclecert {
namespace {

namespace fs = std::filesystem;

// The message of the InputFileError reading `path` throws; "" when it reads.
std::string refusal(const std::string& path, std::size_t maxBytes = kMaxInputBytes) {
  try {
    readInputFile(path, maxBytes);
  } catch (const InputFileError& e) {
    return e.what();
  }
  return "";
}

class InputFile : public CliFixture {
 protected:
  // A sparse file of `bytes`: as large as it says, without writing it.
  std::string sparseFile(const std::string& name, std::uintmax_t bytes) const {
    std::ofstream(path(name)) << "G00 X1 Z1;\n";
    fs::resize_file(path(name), bytes);
    return path(name);
  }

  std::string fifo(const std::string& name) const {
    EXPECT_EQ(::mkfifo(path(name).c_str(), 0600), 0);
    return path(name);
  }
};

TEST_F(InputFile, ReadsARegularFileWhole) {
  const std::string text = "G00 X40 Z2;\n" + std::string(100000, ';');
  std::ofstream(path("p.nc")) << text;
  EXPECT_EQ(readInputFile(path("p.nc")), text);
}

TEST_F(InputFile, RefusesWhatIsNotARegularFileWithTheReason) {
  EXPECT_EQ(refusal(dir_.string()), "cannot read '" + dir_.string() + "': it is a directory; give a regular file");
  EXPECT_EQ(refusal("/dev/zero"),
            "cannot read '/dev/zero': it is a character device; give a regular file (a FIFO or a device could block "
            "or never end)");
  EXPECT_NE(refusal("/dev/urandom").find("it is a character device"), std::string::npos);
  EXPECT_NE(refusal(fifo("pipe")).find("it is a FIFO (named pipe); give a regular file"), std::string::npos);
  EXPECT_EQ(refusal(path("missing.nc")), "cannot read '" + path("missing.nc") + "': no such file");
}

TEST_F(InputFile, RefusesAFileOverTheCap) {
  EXPECT_EQ(kMaxInputBytes, 64u << 20);
  EXPECT_EQ(refusal(sparseFile("big.nc", kMaxInputBytes + 1)),
            "cannot read '" + path("big.nc") + "': it is 67108865 bytes, larger than the 64 MiB cyclecert reads from one input file");
  EXPECT_EQ(refusal(sparseFile("at-cap.nc", 4096), 4096), "");
  EXPECT_NE(refusal(sparseFile("over.nc", 4097), 4096).find("it is 4.001 KiB, larger than the 4 KiB"), std::string::npos);
  std::istringstream stream(std::string(4097, 'x'));
  EXPECT_THROW(readInputStream(stream, "standard input", 4096), InputFileError);
  std::istringstream small("{}");
  EXPECT_EQ(readInputStream(small, "standard input", 4096), "{}");
}

TEST(ByteSizeText, SaysSizesAsPeopleRead) {
  EXPECT_EQ(byteSizeText(12), "12 bytes");
  EXPECT_EQ(byteSizeText(1536), "1.5 KiB");
  EXPECT_EQ(byteSizeText(64ull << 20), "64 MiB");
  EXPECT_EQ(byteSizeText((64ull << 20) + 1), "64 MiB");
}

TEST_F(InputFile, ASpecCaseIsReadTheSameWay) {
  try {
    loadSpecCase("/dev/zero");
    ADD_FAILURE() << "read /dev/zero as a spec case";
  } catch (const InputFileError& e) {
    EXPECT_NE(std::string(e.what()).find("it is a character device"), std::string::npos) << e.what();
  }
}

// Every command that reads a file refuses these at once: exit 2 with the reason, well within the
// `timeout` that would otherwise stop a run reading forever (exit 124).
TEST_F(InputFile, EveryCommandRefusesThemAtOnceWithExit2) {
  const std::string program = path("p.nc");
  std::ofstream(program) << "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-10;\nN20 X40 Z-20;\n";
  const std::string caseFile = std::string(CYCLECERT_SOURCE_DIR) + "/specs/cases/fanuc-0i-f/g71/g01-head-stepped-shaft.json";
  const std::string big = sparseFile("big.nc", kMaxInputBytes + 1), pipe = fifo("pipe");
  const struct {
    std::string args, says;
  } inputs[] = {
      {"plan " + dir_.string(), "it is a directory"},
      {"plan /dev/urandom", "'/dev/urandom': it is a character device"},
      {"plan /dev/zero", "'/dev/zero': it is a character device"},
      {"plan " + pipe, "it is a FIFO"},
      {"plan " + big, "larger than the 64 MiB"},
      {"plan --case /dev/zero", "'/dev/zero': it is a character device"},
      {"plan --case " + dir_.string(), "it is a directory"},
      {"judge " + caseFile + " /dev/zero", "'/dev/zero': it is a character device"},
      {"judge " + caseFile + " " + pipe, "it is a FIFO"},
      {"judge --program " + pipe + " " + program, "it is a FIFO"},
      {"diff --engine reference --vs reference " + pipe, "it is a FIFO"},
  };
  for (const auto& input : inputs) {
    const auto started = std::chrono::steady_clock::now();
    const CliRun r = run(input.args, "timeout 20");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_EQ(r.exitCode, 2) << input.args << "\n" << r.err;
    EXPECT_NE(r.err.find(input.says), std::string::npos) << input.args << "\n" << r.err;
    EXPECT_LT(seconds, 10) << input.args;
  }
}

TEST_F(InputFile, ARunDirectoryWithAFifoForItsFilesIsRefused) {
  fs::create_directories(path("out"));
  fifo("out/run.json");
  CliRun r = run("report " + path("out"), "timeout 20");
  // report checks results.jsonl first: there is none.
  EXPECT_EQ(r.exitCode, 2) << r.err;
  std::ofstream(path("out/results.jsonl")) << "";
  r = run("report " + path("out"), "timeout 20");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("run.json': it is a FIFO"), std::string::npos) << r.err;
  r = run("fuzz --engine reference --no-save --seed 1 --cases 2 --resume --out " + path("out"), "timeout 20");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("run.json': it is a FIFO"), std::string::npos) << r.err;
  fs::remove(path("out/run.json"));
  fs::remove(path("out/results.jsonl"));
  fifo("out/results.jsonl");
  r = run("fuzz --engine reference --no-save --seed 1 --cases 2 --resume --out " + path("out"), "timeout 20");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("results.jsonl': it is not a regular file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace cyclecert
