// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify.hpp"

#include <memory>

#include "cli.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <new>

#include "certify/certificate.hpp"
#include "certify/certify.hpp"
#include "dfchaos/certified/ball.hpp"
#include "dfchaos/errors.hpp"
#include "kit/budget.hpp"
#include "kit/options.hpp"
#include "kit/output.hpp"

namespace dfchaos::cli {

namespace {

/// A finite number, the whole string consumed (the range of the parameters is checked by certify::certify).
double number(const std::string& name, const std::string& s) { return kit::parse_number(name, s, false); }

/// "X" or "LO:HI" with LO <= HI.
certify::Range range(const std::string& name, const std::string& s) {
  const auto colon = s.find(':');
  if (colon == std::string::npos) return certify::Range::point(number(name, s));
  const double lo = number(name, s.substr(0, colon)), hi = number(name, s.substr(colon + 1));
  if (!(lo <= hi)) throw InvalidParameter(name, "LO <= HI in LO:HI (got '" + s + "')");
  return certify::Range{lo, hi};
}

/// "TOP:T2": the two candidate ends of a covering segment (either order on the line).
certify::SegmentEnds segment_ends(const std::string& name, const std::string& s) {
  const auto colon = s.find(':');
  if (colon == std::string::npos) throw InvalidParameter(name, "two phases TOP:T2 (got '" + s + "')");
  return certify::SegmentEnds{number(name, s.substr(0, colon)), number(name, s.substr(colon + 1))};
}

/// The typed request of the options: only the options the statement reads are parsed, in the order
/// a, b, q, window (b0 takes one number q, not a box).
certify::Request request_from(const CertifyOptions& o) {
  certify::check_statement(o.what);
  if (!o.certificate.empty() && !certify::has_certificate(o.what))
    throw InvalidParameter(
        "certificate", std::string("a statement with a certificate format: ") + certify::kCertificateStatements + " (not certify " + o.what + ")");
  certify::Request r;
  r.what = o.what;
  r.certificate = !o.certificate.empty();
  r.period = o.period;
  r.segment = o.segment;
  if (o.what == "vartheta0") return r;
  r.a = number("a", o.a);
  if (o.what == "b0") {
    if (!o.q.empty()) r.q = certify::Range::point(number("q", o.q));
    return r;
  }
  if (!o.b.empty()) r.b = range("b", o.b);
  if (o.what == "discontinuities") return r;
  if (!o.q.empty()) r.q = range("q", o.q);
  if (o.what == "superstable" && !o.window.empty()) r.window = range("window", o.window);
  if (o.what == "covering") {
    if (!o.J0.empty()) r.J0 = segment_ends("J0", o.J0);
    if (!o.J1.empty()) r.J1 = segment_ends("J1", o.J1);
  }
  return r;
}

}  // namespace

CLI::App* add_certify(CLI::App& app, CertifyOptions& o) {
  auto* c = app.add_subcommand("certify", "certified verdicts in ball arithmetic (Arb): proved / not proved, as JSON");
  c->add_option("what", o.what, "vartheta0 | lemma1 | b0 | discontinuities | covering | periodic | superstable")->required();
  c->add_option("-a,--a", o.a, "forcing amplitude a > 0 (default 1)");
  c->add_option("-b,--b", o.b, "b, or a box LO:HI (lemma1, covering)");
  c->add_option("-q,--q", o.q, "q, or a box LO:HI (lemma1, covering)");
  c->add_option("--period", o.period, "periodic: minimal period m, 1..64");
  c->add_option("--segment", o.segment, "discontinuities: L0 (default) or L2");
  c->add_option("--window", o.window, "superstable: certify the window LO:HI (floating estimate of b) and its edges");
  c->add_option("--J0", o.J0,
                "covering: prove this segment J0, given as TOP:T2 (the phases where T >= 3pi/2 and T = t2; e.g. from "
                "certified_region's data), with --J1, instead of searching candidates");
  c->add_option("--J1", o.J1, "covering: the segment J1 (right of J0), as TOP:T2");
  c->add_option("--certificate", o.certificate,
                "write the proof's certificate (JSON witnesses for dfchaos-recheck) to FILE, whole or not at all; vartheta0, lemma1, b0, covering, "
                "superstable, discontinuities")
      ->type_name("FILE")
      ->check([](const std::string& s) { return s.empty() ? std::string("certificate: a file name (got '')") : std::string(); });
  c->add_option("--max-seconds", o.max_seconds, "time budget: give up (exit 1, one line) after S seconds, 0 < S <= 1e6 [default 60]")->type_name("S");
  c->add_option("--max-memory", o.max_memory, "memory budget: give up (exit 1, one line) beyond G GiB of address space, 0.25 <= G <= 1e4 [default 2]")
      ->type_name("G");
  c->footer(
      "A proof whose cost is not bounded by its input (a tiny b/a needs many branches of T1) gives up within the\n"
      "budget: one line on stderr naming the budget that ran out, nothing on stdout, exit status 1.");
  return c;
}

int run_certify(const CertifyOptions& o) {
  certify::Result c;
  try {
    kit::apply_process_budget("dfchaos", kit::parse_budget(o.max_seconds, o.max_memory));
    certified::on_allocation_failure(kit::exit_for_memory_budget);
    c = certify::certify(request_from(o));
    kit::stop_time_budget();
  } catch (const InvalidParameter& e) {
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "dfchaos: gave up: %s\n", kit::memory_budget_line().c_str());
    return 1;
  }
  if (!o.certificate.empty()) {
    if (c.certificate.value().is_null()) {
      c.record.set("certificate",
                   kit::Json::object()
                       .set("written", false)
                       .set("reason", c.no_certificate.empty() ? std::string("not proved: no certificate") : "not written: " + c.no_certificate));
    } else {
      try {
        c.record.set("certificate", certify::to_json(certify::write_certificate(o.certificate, c.certificate)));
      } catch (const kit::OutputError& e) {
        std::fprintf(stderr, "dfchaos: error: certificate: %s\n", kit::one_line(e.what()).c_str());
        return e.bad_path() ? 2 : 1;
      }
    }
  }
  const std::string text = c.record.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  if (!o.certificate.empty() && c.proved && !c.no_certificate.empty()) {
    std::fprintf(stderr, "dfchaos: certificate not written: %s\n", kit::one_line(c.no_certificate).c_str());
    return 1;
  }
  return c.proved ? 0 : 1;
}

Command add_certify_command(CLI::App& app) {
  auto o = std::make_shared<CertifyOptions>();
  CLI::App* c = add_certify(app, *o);
  return {c, [o] { return run_certify(*o); }};
}

}  // namespace dfchaos::cli
