#include "csv_table.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

namespace pxflow {
namespace {

std::string csv_cell(const Json& v) {
  if (v.is_null()) return "";
  if (!v.is_string()) return v.dump();
  std::string s = "\"";
  for (char c : v.get<std::string>()) s += c == '"' ? std::string("\"\"") : std::string(1, c);
  return s + "\"";
}

}  // namespace

std::string csv_lines(const std::vector<std::string>& cols, const std::vector<const Json*>& rows) {
  std::ostringstream o;
  for (std::size_t i = 0; i < cols.size(); ++i) o << (i ? "," : "") << cols[i];
  o << "\n";
  for (const Json* r : rows) {
    for (std::size_t i = 0; i < cols.size(); ++i)
      o << (i ? "," : "") << (r->contains(cols[i]) ? csv_cell((*r)[cols[i]]) : "");
    o << "\n";
  }
  return o.str();
}

std::string csv_table(const std::vector<std::string>& cols, const Json& rows) {
  std::vector<const Json*> in_order;
  for (const auto& r : rows) in_order.push_back(&r);
  return csv_lines(cols, in_order);
}

}  // namespace pxflow
