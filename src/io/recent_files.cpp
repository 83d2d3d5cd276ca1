#include "io/recent_files.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"

namespace s4d {

namespace fs = std::filesystem;

std::vector<fs::path> RecentFiles::read() const {
  std::vector<fs::path> out;
  std::ifstream in(list_);
  std::string line;
  std::error_code ec;
  while (std::getline(in, line) && out.size() < kMax) {
    if (line.empty() || line.find('\0') != std::string::npos) continue;
    const fs::path p(line);
    if (p.is_absolute() && fs::is_regular_file(p, ec) && std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  }
  return out;
}

bool RecentFiles::add(const fs::path& file) const {
  std::error_code ec;
  const fs::path abs = fs::absolute(file, ec);
  if (ec || abs.empty()) return false;
  std::vector<fs::path> list = read();
  std::erase(list, abs);
  list.insert(list.begin(), abs);
  if (list.size() > kMax) list.resize(kMax);
  std::ostringstream text;
  for (const fs::path& p : list) text << p.string() << "\n";
  try {
    fs::create_directories(list_.parent_path(), ec);
    write_file_atomically(list_, text.str());
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace s4d
