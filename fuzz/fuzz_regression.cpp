// Copyright (c) 2026 Geodesic_ridge developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Runs every fuzz target over its committed corpus (fuzz/corpus/<name>/), with
// any compiler: CI has no clang, so this is how the crashes the fuzzers found
// stay fixed. One translation unit for all targets (CGAL compiles slowly).
//   fuzz_regression CORPUS_ROOT [NAME]
// Exits non-zero if a corpus directory is missing or empty; a finding aborts
// or throws out of main, which fails the test as well.

#include "fuzz_targets.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <vector>

namespace {

struct Target
{
  const char* name;
  int (*run)(const uint8_t*, std::size_t);
};

const Target targets[] = {{"off", gr_fuzz::fuzz_off},
                          {"obj", gr_fuzz::fuzz_obj},
                          {"ply", gr_fuzz::fuzz_ply},
                          {"pipeline", gr_fuzz::fuzz_pipeline},
                          {"options", gr_fuzz::fuzz_options},
                          {"query", gr_fuzz::fuzz_query},
                          {"sources", gr_fuzz::fuzz_sources}};

} // namespace

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  if(argc < 2 || argc > 3)
  {
    std::cerr << "usage: fuzz_regression CORPUS_ROOT [NAME]\n";
    return 2;
  }
  const fs::path root = argv[1];
  const std::string only = argc == 3 ? argv[2] : "";
  int status = 0;
  bool known = only.empty();
  for(const Target& t : targets)
  {
    if(!only.empty() && only != t.name) continue;
    known = true;
    const fs::path dir = root / t.name;
    std::vector<fs::path> files;
    if(fs::is_directory(dir))
      for(const auto& entry : fs::directory_iterator(dir))
        if(entry.is_regular_file()) files.push_back(entry.path());
    if(files.empty())
    {
      std::cerr << t.name << ": no corpus in " << dir << "\n";
      status = 1;
      continue;
    }
    std::sort(files.begin(), files.end()); // the same order on every machine
    for(const fs::path& file : files)
    {
      std::ifstream in(file, std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::cout << t.name << ": " << file.filename().string() << " (" << bytes.size() << " bytes)" << std::endl;
      t.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    }
    std::cout << t.name << ": " << files.size() << " inputs, no finding\n";
  }
  if(!known)
  {
    std::cerr << "unknown target '" << only << "'\n";
    return 2;
  }
  return status;
}
