#pragma once
// Checks on output paths that every command makes before any work: an output is never one of the
// command's own input files.
#include <filesystem>
#include <string>
#include <vector>

namespace foldkit::cli {

/// Throws a usage error (exit 2) when `output`, given to `option`, is the same file as one of `inputs`
/// (same device and inode, so also through symbolic and hard links). Empty paths are ignored.
void refuse_output_over_inputs(const std::string& option, const std::filesystem::path& output,
                               const std::vector<std::filesystem::path>& inputs);

/// The path that sheet `index` (0-based) of a multi-sheet output goes to: name.ext, name-2.ext, … for a
/// file; standard output ("-") and a device node take every sheet themselves.
std::filesystem::path sheet_output_path(const std::filesystem::path& output, std::size_t index);

}  // namespace foldkit::cli
