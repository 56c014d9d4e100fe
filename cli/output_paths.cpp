#include "output_paths.hpp"

#include "foldkit/devices/atomic_file.hpp"
#include "foldkit/devices/render.hpp"
#include "foldkit/error.hpp"

namespace foldkit::cli {

void refuse_output_over_inputs(const std::string& option, const std::filesystem::path& output,
                               const std::vector<std::filesystem::path>& inputs) {
  if (output.empty()) return;
  for (const std::filesystem::path& input : inputs) {
    if (input.empty() || !devices::is_same_file(output, input)) continue;
    throw Error(option + " " + output.string() + ": is the input file " + input.string() +
                    " (writing it would destroy it); choose another output name",
                ExitCode::Usage);
  }
}

std::filesystem::path sheet_output_path(const std::filesystem::path& output, std::size_t index) {
  if (output.empty() || devices::resolve_output(output).kind != devices::OutputKind::File) return output;
  return devices::sheet_file_path(output, index);
}

}  // namespace foldkit::cli
