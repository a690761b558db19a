#include "kernel/pattern/read_pattern.hpp"

#include <algorithm>
#include <cctype>

#include "kernel/pattern/fold_io.hpp"
#include "kernel/pattern/opx_reader.hpp"
#include "kernel/pattern/svg_reader.hpp"

namespace rigidfold {

bool is_svg_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".svg";
}

CreasePattern read_pattern(const std::string& path) {
  if (is_svg_path(path)) return read_svg(path);
  if (is_opx_path(path)) return read_opx(path);
  return read_fold(path);
}

}  // namespace rigidfold
