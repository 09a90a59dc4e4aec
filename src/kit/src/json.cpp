#include "kit/json.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "dfchaos/errors.hpp"

namespace dfchaos::kit {

Json Json::array() {
  Json j;
  j.v_ = std::make_shared<Array>();
  return j;
}
Json Json::object() {
  Json j;
  j.v_ = std::make_shared<Object>();
  return j;
}
Json& Json::set(const std::string& key, Json value) {
  auto* o = std::get_if<std::shared_ptr<Object>>(&v_);
  if (!o) throw std::logic_error("Json::set on a non-object");
  for (auto& kv : **o)
    if (kv.first == key) {
      kv.second = std::move(value);
      return *this;
    }
  (*o)->emplace_back(key, std::move(value));
  return *this;
}
Json& Json::push(Json value) {
  auto* a = std::get_if<std::shared_ptr<Array>>(&v_);
  if (!a) throw std::logic_error("Json::push on a non-array");
  (*a)->push_back(std::move(value));
  return *this;
}
bool Json::is_object() const { return std::holds_alternative<std::shared_ptr<Object>>(v_); }

bool Json::empty() const {
  if (auto* o = std::get_if<std::shared_ptr<Object>>(&v_)) return (*o)->empty();
  if (auto* a = std::get_if<std::shared_ptr<Array>>(&v_)) return (*a)->empty();
  return false;
}

namespace {
std::string escape(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", ch);
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}
}  // namespace

void Json::dump_to(std::string& out, int indent, int depth) const {
  const std::string pad(static_cast<std::size_t>(indent * (depth + 1)), ' '), pad_end(static_cast<std::size_t>(indent * depth), ' ');
  const char* nl = indent > 0 ? "\n" : "";
  if (std::holds_alternative<std::nullptr_t>(v_)) out += "null";
  else if (auto* b = std::get_if<bool>(&v_)) out += *b ? "true" : "false";
  else if (auto* d = std::get_if<double>(&v_)) out += std::isfinite(*d) ? format_double(*d) : "null";
  else if (auto* i = std::get_if<long long>(&v_)) out += std::to_string(*i);
  else if (auto* s = std::get_if<std::string>(&v_)) out += escape(*s);
  else if (auto* a = std::get_if<std::shared_ptr<Array>>(&v_)) {
    if ((*a)->empty()) { out += "[]"; return; }
    out += "[";
    out += nl;
    for (std::size_t k = 0; k < (*a)->size(); ++k) {
      out += pad;
      (**a)[k].dump_to(out, indent, depth + 1);
      if (k + 1 < (*a)->size()) out += ",";
      out += nl;
    }
    out += pad_end + "]";
  } else if (auto* o = std::get_if<std::shared_ptr<Object>>(&v_)) {
    if ((*o)->empty()) { out += "{}"; return; }
    out += "{";
    out += nl;
    for (std::size_t k = 0; k < (*o)->size(); ++k) {
      out += pad + escape((**o)[k].first) + (indent > 0 ? ": " : ":");
      (**o)[k].second.dump_to(out, indent, depth + 1);
      if (k + 1 < (*o)->size()) out += ",";
      out += nl;
    }
    out += pad_end + "}";
  }
}

std::string Json::dump(int indent) const {
  std::string out;
  dump_to(out, indent, 0);
  return out + "\n";
}

}  // namespace dfchaos::kit
