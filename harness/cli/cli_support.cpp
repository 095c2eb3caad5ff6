#include "harness/cli/cli_support.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "harness/io/input_file.h"
#include "harness/run/ci_shard.h"
#include "harness/run/parallel_run.h"
#include "reference/model/params.h"

namespace cyclecert::cli {

std::vector<std::string> parseOptions(const std::vector<std::string>& args, const std::vector<Option>& table,
                                      const std::string& command) {
  std::vector<std::string> positional;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a[0] != '-') {
      positional.push_back(a);
      continue;
    }
    const Option* option = nullptr;
    for (const Option& o : table) if (o.name == a) option = &o;
    if (!option) throw UsageError("unknown option " + a + " (see `cyclecert " + command + " --help`)");
    if (option->flag) {
      option->flag();
      continue;
    }
    if (i + 1 >= args.size()) throw UsageError(a + " needs a value (see `cyclecert " + command + " --help`)");
    option->withValue(args[++i]);
  }
  return positional;
}

bool wantsHelp(const std::vector<std::string>& args) {
  for (const auto& a : args) if (a == "--help" || a == "-h") return true;
  return false;
}

std::string readFile(const std::string& path) { return readInputFile(path); }

void writeFile(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();  // a full disk shows here, when the buffer is written
  if (!out) throw UsageError("cannot write '" + path + "'");
}

double numberArg(const std::string& option, const std::string& text, double min, double max) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v) || v < min || v > max) {
    std::ostringstream s;
    s << option << " expects a number from " << min << " to " << max << ", got '" << text << "'";
    throw UsageError(s.str());
  }
  return v;
}

int jobsArg(const std::string& text) {
  const bool digits = !text.empty() && text.size() <= 4 && text.find_first_not_of("0123456789") == std::string::npos;
  const int jobs = digits ? std::stoi(text) : 0;
  if (jobs < 1 || jobs > kMaxJobs) {
    throw UsageError("--jobs expects a whole number of workers from 1 to " + std::to_string(kMaxJobs) +
                     " (default: the number of cores, " + std::to_string(defaultJobs()) + " here), got '" + text + "'");
  }
  return jobs;
}

std::pair<int, int> shardArg(const std::string& text) {
  try {
    const Shard s = shardOption(text);
    return {s.index, s.count};
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string(text == "auto" ? "--shard auto: " : "--shard K/N or auto: ") + e.what());
  }
}

std::vector<std::pair<std::string, double>> parsedParams(const std::vector<std::string>& texts) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& t : texts) {
    MachineParams probe;
    probe.setFromText(t);  // validates the name and value
    const auto eq = t.find('=');
    out.emplace_back(t.substr(0, eq), probe.get(t.substr(0, eq)));
  }
  return out;
}

}  // namespace cyclecert::cli
