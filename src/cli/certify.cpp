#include "certify.hpp"

#include <memory>

#include "cli.hpp"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

#include "dfchaos/certified/json.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/parameters.hpp"
#include "kit/budget.hpp"
#include "kit/output.hpp"
#include "kit/options.hpp"

namespace dfchaos::cli {

namespace {

using namespace dfchaos::certified;

/// A finite number, the whole string consumed, in the parameters' range. @throws InvalidParameter naming `name`.
double bounded_number(const std::string& name, const std::string& s) {
  const double v = kit::parse_number(name, s, false);
  if (!(std::fabs(v) <= kMaxParameter)) throw InvalidParameter(name, "|" + name + "| <= " + format_double(kMaxParameter), v);
  return v;
}

/// "X" or "LO:HI" with LO <= HI.
std::pair<double, double> range(const std::string& name, const std::string& s) {
  const auto colon = s.find(':');
  if (colon == std::string::npos) {
    const double v = bounded_number(name, s);
    return {v, v};
  }
  const double lo = bounded_number(name, s.substr(0, colon)), hi = bounded_number(name, s.substr(colon + 1));
  if (!(lo <= hi)) throw InvalidParameter(name, "LO <= HI in LO:HI (got '" + s + "')");
  return {lo, hi};
}

ParamBox box_from(const CertifyOptions& o, bool need_q, bool allow_box) {
  const double a = bounded_number("a", o.a);
  if (!(a > 0)) throw InvalidParameter("a", "a > 0", a);
  if (o.b.empty()) throw InvalidParameter("b", "required for certify " + o.what);
  const auto [blo, bhi] = range("b", o.b);
  if (!(blo > 0)) throw InvalidParameter("b", "b > 0", blo);
  if (!(2 * bhi < a)) throw InvalidParameter("b", "b < a/2", bhi);
  double qlo = 0.5 * a + 2 * bhi, qhi = qlo;
  if (need_q) {
    if (o.q.empty()) throw InvalidParameter("q", "required for certify " + o.what);
    std::tie(qlo, qhi) = range("q", o.q);
    if (!(qlo > 2 * bhi)) throw InvalidParameter("q", "q > 2b (every progression stops)", qlo);
    if (!(qhi - 2 * blo < a)) throw InvalidParameter("q", "q - 2b < a (t0, t1 exist)", qhi);
  }
  if (!allow_box && (blo != bhi || qlo != qhi))
    throw InvalidParameter(blo != bhi ? "b" : "q", "a single value (certify " + o.what + " works at a parameter point)");
  return ParamBox{a, blo, bhi, qlo, qhi};
}

}  // namespace

CLI::App* add_certify(CLI::App& app, CertifyOptions& o) {
  auto* c = app.add_subcommand("certify", "certified verdicts in ball arithmetic (Arb): proved / not proved, as JSON");
  c->add_option("what", o.what, "vartheta0 | lemma1 | b0 | discontinuities | covering | periodic | superstable")->required();
  c->add_option("--a", o.a, "forcing amplitude a > 0 (default 1)");
  c->add_option("--b", o.b, "b, or a box LO:HI (lemma1, covering)");
  c->add_option("--q", o.q, "q, or a box LO:HI (lemma1, covering)");
  c->add_option("--period", o.period, "periodic: minimal period m, 1..64");
  c->add_option("--segment", o.segment, "discontinuities: L0 (default) or L2");
  c->add_option("--window", o.window, "superstable: certify the window LO:HI (floating estimate of b) and its edges");
  c->add_option("--max-seconds", o.max_seconds, "time budget: give up (exit 1, one line) after S seconds, 0 < S <= 1e6 [default 60]")->type_name("S");
  c->add_option("--max-memory", o.max_memory, "memory budget: give up (exit 1, one line) beyond G GiB of address space, 0.25 <= G <= 1e4 [default 2]")
      ->type_name("G");
  c->footer("A proof whose cost is not bounded by its input (a tiny b/a needs many branches of T1) gives up within the\n"
            "budget: one line on stderr naming the budget that ran out, nothing on stdout, exit status 1.");
  return c;
}

CertifyResult certify(const CertifyOptions& o) {
  Json out;
  bool proved = false;
  {
    if (o.what == "vartheta0") {
      const Vartheta0 v = certify_vartheta0(200);
      out = to_json(v);
      proved = v.verdict.proved;
    } else if (o.what == "lemma1") {
      const ParamBox box = box_from(o, true, true);
      const Lemma1Proof p = certify_lemma1(Model(box));
      out = to_json(box, p);
      proved = p.verdict.proved;
    } else if (o.what == "b0") {
      const double a = bounded_number("a", o.a);
      if (!(a > 0)) throw InvalidParameter("a", "a > 0", a);
      if (o.q.empty()) throw InvalidParameter("q", "required for certify b0");
      const double q = bounded_number("q", o.q);
      if (!(q > 0 && q < a)) throw InvalidParameter("q", "0 < q < a", q);
      const Lemma1Bound p = lemma1_b0_lower_bound(a, q);
      out = to_json(a, q, p);
      proved = p.verdict.proved;
    } else if (o.what == "discontinuities") {
      const ParamBox box = box_from(o, false, false);
      if (o.segment != "L0" && o.segment != "L2") throw InvalidParameter("segment", "L0 or L2 (got '" + o.segment + "')");
      const bool l2 = o.segment == "L2";
      const DiscontinuityProof p = prove_discontinuities(box.a, box.b_lo, L_101pi_100(), l2 ? L_51pi_50() : L_3pi_2());
      out = to_json(box.a, box.b_lo, p, l2 ? "L2 = [101pi/100, 51pi/50]" : "L0 = [101pi/100, 3pi/2]");
      proved = p.verdict.proved;
    } else if (o.what == "covering") {
      const ParamBox box = box_from(o, true, true);
      const CoveringProof p = prove_covering(box);
      out = to_json(p);
      proved = p.verdict.proved;
    } else if (o.what == "periodic") {
      const ParamBox box = box_from(o, true, false);
      if (o.period < 1 || o.period > 64) throw InvalidParameter("period", "an integer 1 <= m <= 64", o.period);
      const CoveringProof c = prove_covering(box);
      const PeriodicProof p = prove_periodic(c, o.period);
      out = to_json(c, p);
      proved = p.verdict.proved;
    } else if (o.what == "superstable") {
      const ParamBox box = box_from(o, true, false);
      if (o.window.empty()) {
        const SuperstableProof p = prove_superstable(box.a, box.b_lo, box.q_lo);
        out = to_json(box.a, box.b_lo, box.q_lo, p);
        proved = p.verdict.proved;
      } else {
        const auto [lo, hi] = range("window", o.window);
        if (!(lo > 0 && lo < hi && 2 * hi < box.a)) throw InvalidParameter("window", "0 < LO < HI < a/2", lo);
        const WindowProof w = prove_window(box.a, box.q_lo, lo, hi);
        out = to_json(box.a, box.q_lo, w);
        proved = w.verdict.proved;
      }
    } else {
      throw InvalidParameter("what", "one of vartheta0, lemma1, b0, discontinuities, covering, periodic, superstable (got '" + o.what + "')");
    }
  }
  return CertifyResult{proved, out.dump(2)};
}

int run_certify(const CertifyOptions& o) {
  CertifyResult r;
  try {
    kit::apply_process_budget("dfchaos", kit::parse_budget(o.max_seconds, o.max_memory));
    on_allocation_failure(kit::exit_for_memory_budget);
    r = certify(o);
    kit::stop_time_budget();
  } catch (const InvalidParameter& e) {
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "dfchaos: gave up: %s\n", kit::memory_budget_line().c_str());
    return 1;
  }
  const std::string text = r.json + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return r.proved ? 0 : 1;
}

Command add_certify_command(CLI::App& app) {
  auto o = std::make_shared<CertifyOptions>();
  CLI::App* c = add_certify(app, *o);
  return {c, [o] { return run_certify(*o); }};
}

}  // namespace dfchaos::cli
