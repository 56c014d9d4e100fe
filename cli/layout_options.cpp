#include "layout_options.hpp"

#include "foldkit/layout/paper.hpp"
#include "limits.hpp"

namespace foldkit::cli {

void add_layout_options(CLI::App& cmd, LayoutCliOptions& o) {
  // --size stays text until to_layout_options: --fit excludes it and its absence means --fit.
  auto* size = cmd.add_option("--size", o.size,
                              "Largest model dimension on paper, e.g. 150mm (default: --fit; " +
                                  format_length_mm(kModelSize.min_mm) + " to " +
                                  format_length_mm(kModelSize.max_mm) + ")")
                   ->transform(length_in(kModelSize));
  cmd.add_flag("--fit", o.fit, "Largest size at which the model fits on one sheet")->excludes(size);
  cmd.add_option("--paper", o.paper, "Paper: " + layout::paper_names())
      ->check(paper_in(kSheetSide))
      ->capture_default_str();
  cmd.add_flag("--landscape", o.landscape, "Landscape sheets (default portrait)");
  add_length_option(cmd, "--margin", o.margin_mm, "Margin around the printable area", kMargin);
  add_length_option(cmd, "--tab-width", o.tab_width_mm, "Glue tab width (narrower on short edges)",
                    kTabWidth);
  cmd.add_flag("--no-tabs", o.no_tabs, "No glue tabs");
  cmd.add_flag("--no-split", o.no_split,
               "Keep every piece whole: a piece larger than the paper is an error naming the largest --size "
               "that fits");
  cmd.add_flag("--no-numbers", o.no_numbers, "No matching edge numbers");
  cmd.add_flag("--arrows", o.arrows, "Coloured direction arrows on both sides of each seam");
  cmd.add_flag("--hints", o.hints, "Assembly step beside each edge number and a glue-order list");
  cmd.add_flag("--regmarks", o.regmarks, "Silhouette registration marks for print-and-cut");
  add_length_option(cmd, "--regmark-inset", o.regmark_inset_mm, "Distance of the marks from the paper edges",
                    kRegMarkInset);
  add_length_option(cmd, "--regmark-square", o.regmark_square_mm, "Side of the square mark", kRegMarkSquare);
  add_length_option(cmd, "--regmark-arm", o.regmark_arm_mm, "Arm length of the L marks", kRegMarkArm);
  add_length_option(
      cmd, "--spacing", o.spacing_mm,
      "Least gap between pieces; unless given, closed to 1 mm where that saves a sheet and no colour "
      "bleeds into it",
      kSpacing)
      ->each([&o](const std::string&) { o.spacing_asked = true; });
  add_length_option(cmd, "--label-min", o.label_min_mm, "Smallest cap height of edge numbers", kLabelMin);
}

layout::LayoutOptions to_layout_options(const LayoutCliOptions& o) {
  layout::LayoutOptions out;
  // Both were validated when parsing.
  if (!o.size.empty() && !o.fit) out.size_mm = layout::parse_length_mm(o.size);
  out.fit = o.fit || o.size.empty();
  out.paper_mm =
      layout::oriented(layout::parse_paper(o.paper).value_or(Vec2{210, 297}),
                       o.landscape ? layout::Orientation::Landscape : layout::Orientation::Portrait);
  out.margin_mm = o.margin_mm;
  out.tabs = !o.no_tabs;
  out.split_oversized = !o.no_split;
  out.tab.width_mm = o.tab_width_mm;
  out.numbers = !o.no_numbers;
  out.arrows = o.arrows;
  out.hints = o.hints;
  out.regmarks = o.regmarks;
  out.regmark.inset_mm = o.regmark_inset_mm;
  out.regmark.square_mm = o.regmark_square_mm;
  out.regmark.arm_mm = o.regmark_arm_mm;
  out.pack.spacing_mm = o.spacing_mm;
  out.label.min_mm = o.label_min_mm;
  return out;
}

ChooseOptions choose_options_of(const LayoutCliOptions& options) {
  ChooseOptions choose;
  if (!options.spacing_asked) choose.closer_spacing_mm = kCloserSpacing_mm;
  return choose;
}

}  // namespace foldkit::cli
