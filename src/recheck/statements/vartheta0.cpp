// SPDX-License-Identifier: GPL-3.0-or-later
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "../ball.hpp"
#include "../interval.hpp"
#include "../paper.hpp"
#include "../reading.hpp"
#include "../statements.hpp"
#include "../steps.hpp"

namespace recheck {

long check_vartheta0(const json& c, std::string& what) {
  Steps st;
  const json& w = field(c, "witnesses", "");
  const json& br = field(w, "bracket", "witnesses.");
  const Num lo = exact(field(field(br, "lo", "witnesses.bracket."), "hex", "witnesses.bracket.lo."), "witnesses.bracket.lo.hex");
  const Num hi = exact(field(field(br, "hi", "witnesses.bracket."), "hex", "witnesses.bracket.hi."), "witnesses.bracket.hi.hex");
  vartheta0_steps(st, lo, hi);
  const Iv bracket(lo, hi);
  // A double d is the nearest to every point of X when X lies strictly between the midpoints of d
  // and its neighbours (exact at kPrecision bits).
  auto rounds_to = [](const Iv& X, double d) {
    const Iv D(d), below = 0.5 * (D + Iv(std::nextafter(d, -INFINITY))), above = 0.5 * (D + Iv(std::nextafter(d, INFINITY)));
    return (X - below).positive() && (above - X).positive();
  };
  if (w.contains("value_double")) st.require(rounds_to(bracket, parameter(w, "value_double", "witnesses.")), "vartheta0 rounds to value_double");
  if (w.contains("sine_double"))
    st.require(rounds_to(sin(bracket), parameter(w, "sine_double", "witnesses.")), "sin(vartheta0) rounds to sine_double");
  // Printed decimals "0.d1...dn" (the paper's): the value lies in [x - 5e-(n+1), x + 5e-(n+1)), the
  // numbers that round to x at n decimals (the decimal ends enclosed by MPFI).
  std::string printed;  // the decimals verified, for the verdict line
  if (w.contains("decimals")) {
    const json& list = w["decimals"];
    if (!list.is_array()) throw Malformed("'witnesses.decimals' is not an array");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string where = "witnesses.decimals[" + std::to_string(i) + "].";
      const json& of = field(list[i], "of", where);
      const json& jv = field(list[i], "value", where);
      const std::string v = jv.is_string() ? jv.get<std::string>() : "";
      const std::size_t n = v.size() > 2 ? v.size() - 2 : 0;
      if ((of != "vartheta0" && of != "sine") || v.compare(0, 2, "0.") != 0 || n < 1 || n > 30 ||
          !std::all_of(v.begin() + 2, v.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)) != 0; }))
        throw Malformed("'" + where + "' is not {\"of\": \"vartheta0\" or \"sine\", \"value\": \"0.<1 to 30 digits>\"}");
      Iv x, half(5.0);
      mpfi_set_str(x.x, v.c_str(), 10);
      for (std::size_t d = 0; d <= n; ++d) half = half / Iv(10.0);
      const Iv X = of == "vartheta0" ? bracket : sin(bracket);
      st.require(le(x - half, X) && lt(X, x + half),
                 "the printed " + v + " is " + of.get<std::string>() + " correctly rounded to " + std::to_string(n) + " decimals");
      printed += (printed.empty() ? "" : ", ") + of.get<std::string>() + " " + v;
    }
  }
  what = "vartheta0, the zero of Eq. (1) in (0, pi/2), lies in [" + hex(lo) + ", " + hex(hi) + "]";
  if (w.contains("value_double")) what += "; its nearest double is " + exact_text(parameter(w, "value_double", "witnesses."));
  if (w.contains("sine_double")) what += "; that of sin(vartheta0) is " + exact_text(parameter(w, "sine_double", "witnesses."));
  if (!printed.empty()) what += "; correctly rounded: " + printed;
  return st.n;
}

}  // namespace recheck
