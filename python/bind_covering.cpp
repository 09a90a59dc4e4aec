// SPDX-License-Identifier: GPL-3.0-or-later
/// @file bind_covering.cpp
/// @brief dfchaos.covering_segments and dfchaos.lemma4_covering: the covering segments of Lemma 4
/// (Eq. 18), closed segments on which T is continuous and whose image contains [t2, top].
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "convert.hpp"
#include "dfchaos/certified/periodic.hpp"
#include "dfchaos/continuation.hpp"
#include "dfchaos/covering.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/phase.hpp"
#include "dfchaos/return_map.hpp"
#include "dfchaos/symbolic.hpp"

namespace dfchaos::python {

namespace {

py::dict label_dict(const ContinuityLabel& l) {
  py::dict d;
  d["t1_branch"] = l.t1_branch;
  d["t3_passed"] = l.t3_passed;
  d["scenario_d"] = l.scenario_d;
  return d;
}

py::dict segment_dict(const CoveringSegment& s) {
  py::dict d;
  d["lo"] = s.lo;
  d["hi"] = s.hi;
  d["theta_at_t2"] = s.theta_at_t2;
  d["theta_at_top"] = s.theta_at_top;
  d["T_at_top"] = s.T_at_top;
  d["label"] = label_dict(s.label);
  d["rechecked"] = s.rechecked;
  return d;
}

// The ranges of the search options that the library does not check itself (it checks scan >= 2
// and uniform >= 0, covering.cpp). Upper bounds: kMaxElements, the module's bound on every loop.
/// Least `recheck`: with fewer than 2 points recheck_segment() (covering.cpp) checks nothing and
/// with fewer than 4 it skips the test for a jump of T, yet marks the segment rechecked.
constexpr int kMinRecheck = 4;
/// Least `refine`: the refinement steps by 1/refine of a grid step (0 would give NaN phases).
constexpr int kMinRefine = 1;

/// v unless it lies outside [lo, hi]. @throws InvalidParameter naming `name` with the condition
/// spelled as the CLI spells a count's ("4 <= recheck <= 1e8").
int count_in(const char* name, int v, long long lo, long long hi) {
  if (v < lo || v > hi)
    throw InvalidParameter(name, format_shortest(static_cast<double>(lo)) + " <= " + name + " <= " + format_shortest(static_cast<double>(hi)), v);
  return v;
}

/// "dense" or "branchwise" (CoveringMethod); the re-check defaults to each method's own. Every
/// option is checked, also those the chosen method does not use.
CoveringSearch search_options(const std::string& method, int scan, int uniform, std::optional<int> recheck, int refine, bool descend,
                              int max_segments, long long max_branches) {
  CoveringSearch s;
  if (method == "branchwise")
    s = CoveringSearch::branchwise();
  else if (method != "dense")
    throw InvalidParameter("method", "'dense' or 'branchwise' (got '" + method + "')");
  // scan and uniform: the library's lower bounds (checked by covering_segments), ours above.
  if (scan > kMaxElements) throw InvalidParameter("scan", "scan <= " + format_shortest(static_cast<double>(kMaxElements)), scan);
  if (uniform > kMaxElements) throw InvalidParameter("uniform", "uniform <= " + format_shortest(static_cast<double>(kMaxElements)), uniform);
  s.scan = scan;
  s.uniform = uniform;
  if (recheck) s.recheck = count_in("recheck", *recheck, kMinRecheck, kMaxElements);
  s.refine = count_in("refine", refine, kMinRefine, kMaxElements);
  s.descend = descend;
  if (max_segments < 0) throw InvalidParameter("max_segments", "max_segments >= 0 (0: all)", max_segments);
  s.max_segments = max_segments;
  if (max_branches < 1) throw InvalidParameter("max_branches", "max_branches >= 1", static_cast<double>(max_branches));
  s.max_branches = max_branches;
  return s;
}

py::list covering_segments_py(const Parameters& p, std::optional<double> lo, std::optional<double> hi, std::optional<double> top,
                              const std::string& method, int scan, int uniform, std::optional<int> recheck, int refine, bool descend,
                              int max_segments, long long max_branches) {
  p.require_return_map();
  const double l = lo ? finite("lo", *lo) : p.t2_required();
  const double h = hi ? finite("hi", *hi) : 1.5 * pi;
  const double t = top ? finite("top", *top) : 1.5 * pi;
  const double t2 = p.t2_required(), t3 = p.t3_required();
  if (!(t > t2 && t < t3))  // T lies in [t2, t3): any other top gives no segment, or empty ones
    throw InvalidParameter("top", "t2 < top < t3 = (" + format_shortest(t2) + ", " + format_shortest(t3) + ")", t);
  const CoveringSearch s = search_options(method, scan, uniform, recheck, refine, descend, max_segments, max_branches);
  const std::vector<CoveringSegment> segs = interruptible([&] { return covering_segments(p, l, h, t, s); });
  py::list out;
  for (const auto& seg : segs) out.append(segment_dict(seg));
  return out;
}

py::dict lemma4_covering_py(const Parameters& p, const std::string& method, int scan, int uniform, std::optional<int> recheck, int refine,
                            bool descend, int max_segments, long long max_branches) {
  const CoveringSearch s = search_options(method, scan, uniform, recheck, refine, descend, max_segments, max_branches);
  const Lemma4Covering r = interruptible([&] { return lemma4_covering(p, s); });
  py::dict d;
  d["holds"] = r.holds;
  d["J0"] = r.holds ? py::object(segment_dict(r.J0)) : py::object(py::none());
  d["J1"] = r.holds ? py::object(segment_dict(r.J1)) : py::object(py::none());
  d["segments_found"] = r.segments_found;
  return d;
}

}  // namespace

void bind_covering(py::module_& m) {
  // Each docstring opens with its own signature line (with the result types pybind11 cannot name).
  py::options options;
  options.disable_function_signatures();
  const CoveringSearch def;
  m.def("covering_segments", &covering_segments_py, py::arg("p"), py::arg("lo") = py::none(), py::arg("hi") = py::none(), py::arg("top") = py::none(),
        py::kw_only(), py::arg("method") = "dense", py::arg("scan") = def.scan, py::arg("uniform") = def.uniform, py::arg("recheck") = py::none(),
        py::arg("refine") = def.refine, py::arg("descend").noconvert() = def.descend, py::arg("max_segments") = def.max_segments,
        py::arg("max_branches") = def.max_branches,
        R"doc(covering_segments(p, lo=t2, hi=3 pi/2, top=3 pi/2, *, method="dense", scan=48, uniform=8000, recheck=None,
                  refine=32, descend=True, max_segments=0, max_branches=1000000) -> list of dict

Disjoint covering segments J inside [lo, hi], ascending (Lemma 4, Eq. 18): closed segments on which
T is continuous (one continuity label) and which hold a point with T = t2 and a point with
T >= top, so that T(J) contains [t2, top] by the intermediate value theorem. Sampled evidence.
method="dense": found on a grid (scan points per continuity branch of T1, at least the density of
`uniform` points; refine and descend as in covering.hpp). method="branchwise": each branch of T1 is
read from the ends of theta2 (about 100 evaluations of T; scan, uniform, refine and descend unused).
Either way each segment is re-checked on `recheck` points inside it (default 400 dense, 64
branchwise). Each dict: lo, hi, theta_at_t2, theta_at_top, T_at_top, label (dict t1_branch,
t3_passed, scenario_d) and rechecked (sampled on a finer grid, not proved).
Raises ValueError (dfchaos.InvalidParameter, naming the argument) unless the map is defined,
t2 <= lo < hi < t3, t2 < top < t3, method is known, 2 <= scan, 0 <= uniform, 4 <= recheck (fewer
points would not re-check), 1 <= refine (each of them <= max_elements), max_segments >= 0 and
max_branches >= 1; TypeError unless descend is a bool. max_branches is the work budget: with more
continuity branches of T1 in [lo, hi] (about 0.16 a/b) the search raises dfchaos.GaveUp before any
work (docs/reliability.md).)doc");
  m.def("lemma4_covering", &lemma4_covering_py, py::arg("p"), py::kw_only(), py::arg("method") = "dense", py::arg("scan") = def.scan,
        py::arg("uniform") = def.uniform, py::arg("recheck") = py::none(), py::arg("refine") = def.refine,
        py::arg("descend").noconvert() = def.descend, py::arg("max_segments") = def.max_segments, py::arg("max_branches") = def.max_branches,
        R"doc(lemma4_covering(p, *, method="dense", scan=48, uniform=8000, recheck=None, refine=32, descend=True,
                max_segments=0, max_branches=1000000) -> dict

Lemma 4's conclusion at one parameter set: two disjoint closed segments J0, J1 of [t2, 3 pi/2], each
with T continuous and T(J) containing [t2, 3 pi/2]. Keys: holds, J0, J1 (dicts as from
covering_segments, None unless holds), segments_found (the search stops after 2 when
max_segments is 0). Sampled evidence, as covering_segments; its options are checked as there.)doc");

  m.def(
      "periodic_orbit",
      [](const Parameters& p, const std::string& word) {
        p.require_return_map();
        const auto [orb, T] = interruptible([&] {
          ItineraryOrbit o = periodic_orbit(p, word);
          std::vector<double> t(o.x.size());
          for (std::size_t j = 0; j < o.x.size(); ++j) t[j] = return_map_step(p, o.x[j]).T;
          return std::pair{std::move(o), std::move(t)};
        });
        py::dict d;
        d["word"] = orb.word;
        d["x"] = py::array_t<double>(static_cast<py::ssize_t>(orb.x.size()), orb.x.data());
        d["T"] = py::array_t<double>(static_cast<py::ssize_t>(T.size()), T.data());
        d["log_multiplier"] = orb.log_expansion;
        d["max_step_residual"] = orb.max_step_residual;
        d["precision_floor"] = orb.precision_floor;
        d["itinerary_ok"] = orb.itinerary_ok;
        return d;
      },
      py::arg("p"), py::arg("word"), R"doc(periodic_orbit(p, word) -> dict

`dfchaos periodic --word` (to the last bit): the orbit of T with itinerary (word)^infinity over
Lemma 4's J0 (letter 0) and J1 (letter 1), word primitive of 1 to 1000 letters (least period
len(word)). Returns word, x (x_(j+1) = T(x_j)), T (T(x_j) as computed), log_multiplier
(ln|(T^m)'(x_0)|), max_step_residual, precision_floor and itinerary_ok; errors as the tool's.
certify("periodic", p, word=word) encloses it in ball arithmetic.)doc");
  m.def(
      "follow_orbit",
      [](const Parameters& p, const std::string& word, double b_end, double step, double min_step, long long max_steps, bool certify) {
        p.require_return_map();
        require_itinerary_word("word", word, kMaxContinuedPeriod);
        ContinuationSettings s;
        s.step = finite("step", step);
        s.min_step = finite("min-step", min_step);
        s.max_steps = max_steps;
        s.validate();
        Parameters(p.a(), finite("to", b_end), p.q()).require_return_map();
        const auto [br, proved] = interruptible([&] {
          const ItineraryOrbit start = periodic_orbit(p, word);
          OrbitBranch b = follow_periodic_orbit(p.a(), p.q(), p.b(), start.x, b_end, s);
          std::vector<int> c = certify ? certified::prove_branch_steps(p.a(), p.q(), b) : std::vector<int>(b.points.size(), -1);
          return std::pair{std::move(b), std::move(c)};
        });
        const auto n = static_cast<py::ssize_t>(br.points.size()), m = static_cast<py::ssize_t>(word.size());
        py::array_t<double> b(n), lm(n), res(n), x(std::vector<py::ssize_t>{n, m});
        py::array_t<int> cert(n);
        for (py::ssize_t k = 0; k < n; ++k) {
          const BranchPoint& pt = br.points[static_cast<std::size_t>(k)];
          b.mutable_at(k) = pt.b;
          lm.mutable_at(k) = pt.log_multiplier;
          res.mutable_at(k) = pt.residual;
          cert.mutable_at(k) = proved[static_cast<std::size_t>(k)];
          for (py::ssize_t j = 0; j < m; ++j) x.mutable_at(k, j) = pt.x[static_cast<std::size_t>(j)];
        }
        py::dict d;
        d["b"] = b;
        d["certified"] = cert;
        d["log_multiplier"] = lm;
        d["residual"] = res;
        d["x"] = x;
        d["end"] = std::string(branch_end_name(br.end));
        d["end_point"] = br.end_point;
        d["b_lost"] = br.b_lost;
        d["detail"] = br.detail;
        return d;
      },
      py::arg("p"), py::arg("word"), py::arg("b_end"), py::kw_only(), py::arg("step") = ContinuationSettings{}.step,
      py::arg("min_step") = ContinuationSettings{}.min_step, py::arg("max_steps") = ContinuationSettings{}.max_steps, py::arg("certify") = false,
      R"doc(follow_orbit(p, word, b_end, *, step=1e-3, min_step=1e-12, max_steps=10000, certify=False) -> dict

`dfchaos continue` (to the last bit): the orbit periodic_orbit(p, word) followed in b to b_end until it
ends. Returns the tool's columns b, certified (1/0 per interval from the row before; -1 none),
log_multiplier, residual and x (one row per b), and end, end_point, b_lost, detail as its # lines.)doc");
}

}  // namespace dfchaos::python
