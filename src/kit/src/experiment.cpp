// SPDX-License-Identifier: GPL-3.0-or-later
#include "kit/experiment.hpp"

#include <CLI/CLI.hpp>

#include <climits>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "dfchaos/errors.hpp"
#include "kit/format.hpp"
#include "kit/output.hpp"
#include "kit/provenance.hpp"

namespace dfchaos::kit {

bool OutputSpec::matches(const std::string& k, const std::string& p) const {
  if (k != kind) return false;
  if (!part.empty() && part.back() == '*') return p.compare(0, part.size() - 1, part, 0, part.size() - 1) == 0;
  return p == part;
}

OutputSpec data(std::string part, std::string description) { return OutputSpec{"data", std::move(part), std::move(description)}; }
OutputSpec latex(std::string file, std::string description) { return OutputSpec{"latex", std::move(file), std::move(description)}; }
OutputSpec certificate(std::string file, std::string description) { return OutputSpec{"certificate", std::move(file), std::move(description)}; }

int Run::count_int(const std::string& name) const {
  const long long v = values_.count(name);
  if (v < INT_MIN || v > INT_MAX) throw std::logic_error("option --" + name + " does not fit an int: declare a smaller range");
  return static_cast<int>(v);
}

namespace {
/// The declared data output for a part (its description), or a logic error.
const OutputSpec& declared(const std::vector<OutputSpec>& outputs, const std::string& kind, const std::string& part) {
  for (const auto& o : outputs)
    if (o.matches(kind, part)) return o;
  throw std::logic_error("output " + kind + " '" + part + "' is not declared in the experiment");
}
}  // namespace

Json Experiment::describe(const std::string& name) const {
  Json j = Json::object();
  j.set("name", name).set("title", title);
  Json p = Json::array();
  Json p_tex = Json::array();  // the same items escaped for LaTeX: the one escaper is the kit's
  for (const auto& s : paper) {
    p.push(s);
    p_tex.push(latex_escape(s));
  }
  j.set("paper", p).set("paper_tex", p_tex);
  Json t = Json::array();
  for (const auto& s : tests) t.push(s);
  j.set("tests", t);
  Json o = Json::array();
  for (const auto& s : options) o.push(s.to_json());
  j.set("options", o);
  Json out = Json::array();
  for (const auto& s : outputs) {
    Json e = Json::object();
    e.set("kind", s.kind).set("name", s.kind == "data" ? (s.part.empty() ? name : name + "-" + s.part) : s.part).set("description", s.description);
    out.push(e);
  }
  j.set("outputs", out);
  return j;
}

int Experiment::main(const std::string& name, int argc, char** argv) const {  // NOLINT(bugprone-exception-escape): not the program's main
  remove_temporaries_on_signals();
  const int status = run_main(name, argc, argv);
  // What went to stdout (--describe, --help) must have reached it: a failed write is not a success.
  const int err = stdout_failure();
  if (err != 0) {
    std::fprintf(stderr, "%s: error: cannot write the output: %s\n", name.c_str(), std::strerror(err));
    return status == 2 ? 2 : 1;
  }
  return status;
}

int Experiment::run_main(const std::string& name, int argc, char** argv) const {
  std::string help_footer = "Exit status: 0 every claim it asserts holds, 1 one fails (or a bounded search gave up, or writing failed), 2 bad input.";
  CLI::App app{name + ": " + title};
  app.footer(help_footer);
  std::string out_root = "build";
  bool fast = false, describe_only = false;
  app.add_option("--out", out_root, "output root: data/, tables/, claims/ are written below it [default build]");
  app.add_flag("--fast", fast, "smoke mode: coarse grids, the same code paths (run by CTest)");
  app.add_flag("--describe", describe_only, "print this experiment's declaration as JSON and exit");
  std::vector<std::vector<std::string>> raw(options.size());
  std::vector<CLI::Option*> handles;
  for (std::size_t k = 0; k < options.size(); ++k) {
    const OptionSpec& s = options[k];
    std::string help = s.help + " [default ";
    auto show = [&](const std::vector<double>& v) {
      std::string t;
      for (double x : v)
        t += (t.empty() ? "" : " ") + (s.type == OptionType::Count ? std::to_string(static_cast<long long>(x)) : format_significant(x, 6));
      return t;
    };
    help += show(s.value) + "; " + s.condition();
    if (s.fast) help += "; with --fast " + show(*s.fast);
    help += "]";
    CLI::Option* opt = app.add_option("--" + s.name, raw[k], help);
    if (s.type == OptionType::Reals)
      opt->expected(1, -1)->type_name("FLOAT ...");
    else
      opt->expected(1)->type_name(s.type == OptionType::Count ? "INT" : "FLOAT");
    handles.push_back(opt);
  }
  // An empty value would be read as 0 by a number parser: refuse it whatever the option.
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '\0') {
      std::fprintf(stderr, "%s: error: %s: empty value (a number is required)\n", name.c_str(), i > 1 ? argv[i - 1] : "argument");
      return 2;
    }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), one_line(e.what()).c_str());
    return 2;
  }
  if (describe_only) {
    std::fputs(describe(name).dump().c_str(), stdout);
    return 0;
  }
  try {
    OptionValues values;
    values.set_defaults(options, fast);
    for (std::size_t k = 0; k < options.size(); ++k)
      if (handles[k]->count() > 0) values.set(options[k], raw[k]);
    require_output_root(out_root);
    Output out(name, out_root);
    out.parameter("mode", fast ? "fast" : "full");
    for (const auto& s : options) {
      if (!s.recorded) continue;
      if (s.type == OptionType::Count)
        out.parameter(s.record_key(), std::to_string(values.count(s.name)));
      else if (s.type == OptionType::Real)
        out.parameter(s.record_key(), values.real(s.name));
      else {
        std::string t;
        for (double x : values.reals(s.name)) t += (t.empty() ? "" : " ") + format_shortest(x);
        out.parameter(s.record_key(), t);
      }
    }
    Run run(values, fast, outputs, out);
    body(run);
    // Every output written was declared, and every declared output (without a wildcard) written.
    for (const auto& [kind, part] : out.written()) declared(outputs, kind, part);
    for (const auto& o : outputs) {
      if (!o.part.empty() && o.part.back() == '*') continue;
      bool found = false;
      for (const auto& [kind, part] : out.written()) found = found || (kind == o.kind && part == o.part);
      if (!found) throw std::logic_error("declared output " + o.kind + " '" + o.part + "' was not written");
    }
    // Certificates of an earlier run that this one did not write again (their proof no longer
    // succeeds, or no longer runs): stale, removed once the new outputs are in place, so that no
    // certificate outlives its proof.
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(out_root) / "certificates", ec)) {
      if (e.path().extension() != ".json") continue;
      const std::string stem = e.path().stem().string();
      bool ours = false, written = false;
      for (const auto& o : outputs) ours = ours || o.matches("certificate", stem);
      for (const auto& [kind, part] : out.written()) written = written || (kind == "certificate" && part == stem);
      if (ours && !written) out.retire(e.path());
    }
    return out.finish();
  } catch (const InvalidParameter& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), one_line(e.what()).c_str());
    return 2;
  } catch (const GaveUp& e) {
    std::fprintf(stderr, "%s: gave up: %s\n", name.c_str(), one_line(e.what()).c_str());
    return 1;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), one_line(e.what()).c_str());
    return e.bad_path() ? 2 : 1;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: error: out of memory (no output written)\n", name.c_str());
    return 1;
  }
}

void Run::table(const std::string& part, const Table& t) { out.table(part, t, declared(outputs_, "data", part).description); }
void Run::latex(const std::string& file, const std::string& tex) {
  declared(outputs_, "latex", file);
  out.latex(file, tex);
}
void Run::certificate(const std::string& file, const std::string& json) {
  declared(outputs_, "certificate", file);
  out.certificate(file, json);
}

}  // namespace dfchaos::kit
