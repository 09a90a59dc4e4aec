// SPDX-License-Identifier: GPL-3.0-or-later
#include "certify.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <new>

#include "certify/certificate.hpp"
#include "certify/certify.hpp"
#include "certify/statements.hpp"
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

/// The typed request of the options: only the inputs the statement reads are parsed, in the order
/// of its registry entry (a, b, q, then the others).
certify::Request request_from(const CertifyOptions& o) {
  const certify::Statement& s = certify::statement(o.what);
  certify::Request r;
  r.what = o.what;
  r.certificate = !o.certificate.empty();
  r.period = o.period;
  r.word = o.word;
  r.segment = o.segment;
  for (const certify::Input in : s.inputs) {
    switch (in) {
      case certify::Input::a: r.a = number("a", o.a); break;
      case certify::Input::b:
      case certify::Input::b_box:
        if (!o.b.empty()) r.b = range("b", o.b);
        break;
      case certify::Input::q:
      case certify::Input::q_box:
      case certify::Input::q_ratio:
        if (!o.q.empty()) r.q = range("q", o.q);
        break;
      case certify::Input::window:
        if (!o.window.empty()) r.window = range("window", o.window);
        break;
      case certify::Input::segments:
        if (!o.J0.empty()) r.J0 = segment_ends("J0", o.J0);
        if (!o.J1.empty()) r.J1 = segment_ends("J1", o.J1);
        break;
      case certify::Input::segment:
      case certify::Input::period: break;  // copied above (checked by the statement)
    }
  }
  return r;
}

}  // namespace

namespace {

/// The options every statement takes: --certificate (every statement has a certificate format,
/// docs/certificates.md) and the budgets.
void add_common(CLI::App* s, CertifyOptions& o) {
  s->add_option("--certificate", o.certificate, "write the proof's certificate (JSON witnesses for dfchaos-recheck) to FILE, whole or not at all")
      ->type_name("FILE")
      ->check([](const std::string& v) { return v.empty() ? std::string("certificate: a file name (got '')") : std::string(); });
  s->add_option("--max-seconds", o.max_seconds, "time budget: give up (exit 1, one line) after S seconds, 0 < S <= 1e6")
      ->type_name("S")
      ->capture_default_str();
  s->add_option("--max-memory", o.max_memory, "memory budget: give up (exit 1, one line) beyond G GiB of address space, 0.25 <= G <= 1e4")
      ->type_name("G")
      ->capture_default_str();
}

/// -a (default 1).
void add_a(CLI::App* s, CertifyOptions& o) { s->add_option("-a,--a", o.a, "forcing amplitude a > 0")->type_name("FLOAT")->capture_default_str(); }

/// -b or -q: required; a number, or also a box LO:HI when `box`.
void add_parameter(CLI::App* s, std::string& v, const char* names, const char* what, bool box) {
  s->add_option(names, v, std::string(what) + (box ? ": one value, or a box LO:HI (proved for every value in it)" : ": one value"))
      ->type_name(box ? "X|LO:HI" : "FLOAT")
      ->required();
}

/// The usage line of `certify`: the statement is a subcommand; the hidden positional that catches a
/// word naming none would otherwise show as "[]" (CLI11 2.1 has no App::usage).
class CertifyUsage : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App* /*app*/, std::string name) const override {
    return get_label("Usage") + ": " + name + " STATEMENT [OPTIONS]\n";
  }
};

}  // namespace

CLI::App* add_certify(CLI::App& app, CertifyOptions& o) {
  auto* c = app.add_subcommand("certify", "certified verdicts in ball arithmetic (Arb): proved / not proved, as JSON");
  c->require_subcommand(0, 1);
  // A word that names no statement lands here and is refused by name (run_certify).
  c->add_option("statement", o.what)->group("");
  const char* kB = "-b,--b";
  const char* kQ = "-q,--q";
  const char* kBText = "b, half the constant force";
  const char* kQText = "q, the largest dry friction";
  // One subcommand per statement of the registry (certify/statements.hpp), its options those of the
  // inputs the statement reads.
  for (const certify::Statement& st : certify::statements()) {
    auto* s = c->add_subcommand(st.name, st.summary);
    for (const certify::Input in : st.inputs) {
      switch (in) {
        case certify::Input::a: add_a(s, o); break;
        case certify::Input::b: add_parameter(s, o.b, kB, kBText, false); break;
        case certify::Input::b_box: add_parameter(s, o.b, kB, kBText, true); break;
        case certify::Input::q: add_parameter(s, o.q, kQ, kQText, false); break;
        case certify::Input::q_box: add_parameter(s, o.q, kQ, kQText, true); break;
        case certify::Input::q_ratio:
          add_parameter(s, o.q, kQ, "q, the largest dry friction (q/a is what the proof is about; 0 < q <= a)", true);
          break;
        case certify::Input::segment:
          s->add_option("--segment", o.segment, "L0 = [101pi/100, 3pi/2] or L2 = [101pi/100, 51pi/50]")->type_name("L0|L2")->capture_default_str();
          break;
        case certify::Input::period: {
          auto* pm =
              s->add_option("--period", o.period, "the minimal period M, 1 <= M <= 64: the orbit of itinerary (0^(M-1)1)^infinity")->type_name("M");
          auto* pw = s->add_option("--word", o.word,
                                   "instead of --period: the orbit of itinerary (W)^infinity, W a primitive word of 1..64 letters 0 and 1\n"
                                   "(0 for J0, 1 for J1; its least period is the length of W)")
                         ->type_name("W");
          pm->excludes(pw);
          break;
        }
        case certify::Input::window:
          s->add_option("--window", o.window, "certify the window LO:HI in b (a floating estimate) and its edges, at this q")->type_name("LO:HI");
          break;
        case certify::Input::segments: {
          auto* j0 = s->add_option("--J0", o.J0,
                                   "prove this segment J0, given as TOP:T2 (the phases where T >= 3pi/2 and T = t2; e.g. from "
                                   "certified_region's data), with --J1, instead of searching candidates")
                         ->type_name("TOP:T2");
          auto* j1 = s->add_option("--J1", o.J1, "the segment J1 (right of J0), as TOP:T2")->type_name("TOP:T2");
          j0->needs(j1);
          j1->needs(j0);
          break;
        }
      }
    }
    add_common(s, o);
  }

  // A word that names no statement, with the options after it, lands in `what` and is refused
  // first, by name (set after the statements, which would inherit it: they refuse extras).
  c->allow_extras();
  for (CLI::App* s : c->get_subcommands([](CLI::App*) { return true; }))  // every statement (without a filter: the parsed ones)
    s->footer(
        "Prints one JSON object: \"proved\", \"statement\", the enclosures (decimal mid and radius) and, when not proved,\n"
        "\"failed_step\". Exit status 0 proved, 1 not proved (an answer, not an error) or a budget ran out, 2 bad input.");
  c->footer(
      "One subcommand per statement: 'dfchaos certify STATEMENT --help' lists its options, defaults and ranges.\n"
      "A proof whose cost is not bounded by its input (a tiny b/a needs many branches of T1) gives up within the\n"
      "budget: one line on stderr naming the budget that ran out, nothing on stdout, exit status 1.");
  c->formatter(std::make_shared<CertifyUsage>());  // after the statements, which would inherit it
  return c;
}

int run_certify(const CertifyOptions& o) {
  certify::Result c;
  try {
    kit::apply_process_budget("dfchaos", kit::parse_budget(o.max_seconds, o.max_memory));
    certified::on_allocation_failure(kit::exit_for_memory_budget);
    const certify::Request request = request_from(o);
    if (!o.certificate.empty()) certify::check_certificate_path(o.certificate);  // before the proof, not after it
    c = certify::certify(request);
    kit::stop_time_budget();
  } catch (const InvalidParameter& e) {
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return 2;
  } catch (const kit::OutputError& e) {
    std::fprintf(stderr, "dfchaos: error: %s\n", kit::one_line(e.what()).c_str());
    return e.bad_path() ? 2 : 1;
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
  return {c, [o, c] {
            // The statement comes first: a word before it (or instead of it) and options before it
            // are refused, never dropped. No statement, or a word that names none: run_certify
            // refuses it, naming the statements.
            const CLI::App* chosen = nullptr;
            for (const CLI::App* s : c->get_subcommands())
              if (s->parsed()) chosen = s;
            const std::vector<std::string> extras = c->remaining();
            if (chosen && (!o->what.empty() || !extras.empty())) {
              const std::string stray = !extras.empty() ? extras.front() : o->what;
              std::fprintf(stderr, "dfchaos: error: certify: '%s' before the statement %s (write 'dfchaos certify %s OPTIONS')\n",
                           kit::one_line(stray).c_str(), chosen->get_name().c_str(), chosen->get_name().c_str());
              return 2;
            }
            if (chosen) o->what = chosen->get_name();
            return run_certify(*o);
          }};
}

}  // namespace dfchaos::cli
