// SIEMENS.SUB: a contour subprogram as a sibling file of the main program (NAME.spf, NAME.SPF).
#include <filesystem>
#include <fstream>
#include <sstream>

#include "reference/model/ascii.h"
#include "reference/siemens/siemens_subprograms.h"

namespace cyclecert {

std::optional<std::pair<std::string, std::string>> readSiblingSubprogram(const std::string& directory,
                                                                         const std::string& name) {
  std::string upper = name;
  for (char& c : upper) c = asciiUpper(c);
  for (const std::string& fileName : {name + ".spf", name + ".SPF", upper + ".spf", upper + ".SPF"}) {
    const std::filesystem::path path = std::filesystem::path(directory) / fileName;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) continue;
    std::ifstream in(path, std::ios::binary);
    if (!in) continue;
    std::ostringstream text;
    text << in.rdbuf();
    return std::pair{path.string(), text.str()};
  }
  return std::nullopt;
}

}  // namespace cyclecert
