// A whole file as a string (empty when it cannot be read): the tests compare outputs, golden
// texts and stderr logs byte for byte; and a file written from one.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rugosim::testing {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace rugosim::testing
