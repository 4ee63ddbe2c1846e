// read_file.cpp — see read_file.h.
#include "read_file.h"

#include <fstream>
#include <iostream>
#include <iterator>

namespace vgc::cli {

bool read_file(const std::filesystem::path& path, std::string* out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

void read_stdin(std::string* out) {
  out->assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
}

}  // namespace vgc::cli
