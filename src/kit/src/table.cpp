// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/table.hpp"

#include <stdexcept>

#include "dfchaos/errors.hpp"
#include "kit/format.hpp"

namespace dfchaos::kit {

Table::Table(std::vector<std::string> columns) : columns_(std::move(columns)) {}

Table& Table::row(std::vector<Cell> cells) {
  if (cells.size() != columns_.size()) throw std::logic_error("Table::row: wrong number of cells");
  rows_.push_back(std::move(cells));
  return *this;
}

std::string Table::render() const { return render(""); }

std::string Table::render(const std::string& comments) const {
  std::string out;
  for (std::size_t k = 0; k < columns_.size(); ++k) out += (k ? "\t" : "") + columns_[k];
  out += "\n" + comments;
  for (const auto& r : rows_) {
    for (std::size_t k = 0; k < r.size(); ++k) {
      if (k) out += "\t";
      if (const auto* d = std::get_if<double>(&r[k]))
        out += format_double(*d);
      else if (const auto* i = std::get_if<long long>(&r[k]))
        out += std::to_string(*i);
      else
        out += std::get<std::string>(r[k]);
    }
    out += "\n";
  }
  return out;
}

LatexTable::LatexTable(std::string spec, std::vector<std::string> header) : spec_(std::move(spec)), columns_(header.size()) {
  for (std::size_t k = 0; k < header.size(); ++k) head_ += (k ? " & " : "") + header[k];
  head_ += "\\\\\n";
}

LatexTable& LatexTable::row(const std::vector<std::string>& cells) {
  if (cells.size() != columns_) throw std::logic_error("LatexTable::row: wrong number of cells");
  // a cell that is a number in exponent notation ("8.7e-05") is typeset as one (latex_number)
  for (std::size_t k = 0; k < cells.size(); ++k) body_ += (k ? " & " : "") + latex_number(cells[k]);
  body_ += "\\\\\n";
  ++rows_;
  return *this;
}

LatexTable& LatexTable::rule() {
  body_ += "\\midrule\n";
  return *this;
}

std::string LatexTable::render() const {
  return "\\begin{tabular}{" + spec_ + "}\n\\toprule\n" + head_ + "\\midrule\n" + body_ + "\\bottomrule\n\\end{tabular}\n";
}

}  // namespace dfchaos::kit
