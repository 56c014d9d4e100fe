// Cairo has no API for the document catalog's /ViewerPreferences, so the finished PDF gets an
// incremental update (ISO 32000-1 §7.5.6): a new revision of the catalog object with
// << /PrintScaling /None >> and a cross-reference section for it, appended after the original bytes.
// Nothing already written moves, so every offset in the original stays valid; a PDF this code does
// not understand (no classic trailer, an earlier update) is left exactly as it is.
#include <cstdio>
#include <string>

#include "render_internal.hpp"

namespace foldkit::devices::detail {
namespace {

// The dictionary (with its << >>) that starts at or after `from`, nested dictionaries included.
std::string dictionary_at(const std::string& pdf, std::size_t from) {
  const std::size_t start = pdf.find("<<", from);
  if (start == std::string::npos) return "";
  int depth = 0;
  for (std::size_t i = start; i + 1 < pdf.size(); ++i) {
    if (pdf.compare(i, 2, "<<") == 0) {
      ++depth;
      ++i;
    } else if (pdf.compare(i, 2, ">>") == 0) {
      --depth;
      ++i;
      if (depth == 0) return pdf.substr(start, i + 1 - start);
    }
  }
  return "";
}

// The integer after `key` in `dict` ("/Size 12" -> 12), -1 when absent.
long long integer_after(const std::string& dict, const std::string& key) {
  const std::size_t at = dict.find(key);
  if (at == std::string::npos) return -1;
  long long value = -1;
  return std::sscanf(dict.c_str() + at + key.size(), " %lld", &value) == 1 ? value : -1;
}

}  // namespace

bool ask_viewers_not_to_scale(std::string& pdf) {
  const std::size_t startxref = pdf.rfind("startxref");
  const std::size_t trailer_at = pdf.rfind("trailer", startxref);
  if (startxref == std::string::npos || trailer_at == std::string::npos) return false;
  const std::string trailer = dictionary_at(pdf, trailer_at);
  long long previous = -1;
  if (std::sscanf(pdf.c_str() + startxref + 9, " %lld", &previous) != 1 || previous < 0) return false;
  if (trailer.empty() || trailer.find("/Prev") != std::string::npos) return false;
  const long long size = integer_after(trailer, "/Size"), root = integer_after(trailer, "/Root");
  if (size <= 0 || root <= 0 || root >= size) return false;
  long long generation = -1;
  {
    const std::size_t at = trailer.find("/Root");
    long long object = -1;
    if (std::sscanf(trailer.c_str() + at + 5, " %lld %lld R", &object, &generation) != 2) return false;
  }
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on chained literal + string concatenation.
  const std::string object_id = std::to_string(root).append(" ").append(std::to_string(generation));
  std::string header("\n");
  header.append(object_id).append(" obj");
  const std::size_t object_at = pdf.find(header);
  if (object_at == std::string::npos) return false;
  const std::string catalog = dictionary_at(pdf, object_at + header.size());
  if (catalog.size() < 4 || catalog.find("/Catalog") == std::string::npos ||
      catalog.find("/ViewerPreferences") != std::string::npos)
    return false;

  std::string update("\n");
  const std::size_t offset = pdf.size() + update.size();
  update.append(object_id).append(" obj\n").append(catalog, 0, catalog.size() - 2);
  update.append(" /ViewerPreferences << /PrintScaling /None >> >>\nendobj\n");
  const std::size_t xref = pdf.size() + update.size();
  char entry[32];
  std::snprintf(entry, sizeof entry, "%010zu %05lld n \n", offset, generation);
  update.append("xref\n").append(std::to_string(root)).append(" 1\n").append(entry);
  update.append("trailer\n").append(trailer, 0, trailer.size() - 2).append(" /Prev ");
  update.append(std::to_string(previous)).append(" >>\nstartxref\n").append(std::to_string(xref));
  update.append("\n%%EOF\n");
  pdf += update;
  return true;
}

}  // namespace foldkit::devices::detail
