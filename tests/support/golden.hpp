#pragma once
// Golden files for byte streams: compared exactly; FOLDKIT_UPDATE_GOLDEN=1 rewrites them (review the diff).
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "test_paths.hpp"

namespace foldkit::test {

/// Compares `actual` with tests/data/golden/`name`, naming the first differing byte.
inline void expect_golden(const std::string& name, const std::string& actual) {
  const std::filesystem::path file = source_dir() / "tests" / "data" / "golden" / name;
  if (const char* update = std::getenv("FOLDKIT_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    std::ofstream(file, std::ios::binary) << actual;
    return;
  }
  ASSERT_TRUE(std::filesystem::is_regular_file(file))
      << file << " is missing (run with FOLDKIT_UPDATE_GOLDEN=1 and review it)";
  const std::string expected = slurp(file);
  std::size_t i = 0;
  while (i < expected.size() && i < actual.size() && expected[i] == actual[i])
    ++i;
  EXPECT_TRUE(expected == actual) << name << " differs at byte " << i << ": expected \""
                                  << expected.substr(i, 40) << "\", got \"" << actual.substr(i, 40) << "\"";
}

}  // namespace foldkit::test
