// Copyright (c) 2026 Geodesic_ridge developers.
//
// The meshes a benchmark runs on when none is given: every .off file of
// ../shared/data, or of the repository's data/ when ../shared is absent,
// smallest file first.
#ifndef GEODESIC_RIDGE_BENCHMARK_MESHES_H
#define GEODESIC_RIDGE_BENCHMARK_MESHES_H

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

inline std::vector<std::string> benchmark_meshes(std::vector<std::string> files)
{
  namespace fs = std::filesystem;
  if(files.empty())
  {
    fs::path dir = GEODESIC_RIDGE_SHARED_DATA_DIR;
    if(!fs::is_directory(dir)) dir = GEODESIC_RIDGE_DATA_DIR;
    for(const auto& entry : fs::directory_iterator(dir))
      if(entry.path().extension() == ".off") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end(),
            [](const std::string& a, const std::string& b) { return fs::file_size(a) < fs::file_size(b); });
  return files;
}

#endif
