// SPDX-License-Identifier: GPL-3.0-or-later
/// @file cmd_sweep.cpp
/// @brief `dfchaos sweep` (observables over the (q/a, b/a) plane, OpenMP threads, shards, resume)
/// and `dfchaos sweep-merge` (shard files joined into the unsharded output), over the sweep engine
/// (src/sweep). The MPI driver dfchaos-sweep-mpi takes the same options.
#include <memory>

#include "cli.hpp"
#include "sweep/engine.hpp"
#include "sweep/merge.hpp"
#include "sweep/options.hpp"
#include "sweep/stream.hpp"

namespace dfchaos::cli {

Command add_sweep(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("sweep", "observables over a (q/a, b/a) grid: covering, superstable, lyapunov, rate, period, certified, region, entropy");
  auto args = std::make_shared<sweep::SweepArguments>();
  args->add_to(cmd);
  return {cmd, [args] {
            sweep::Run run(args->resolve());
            return sweep::run_on_threads(run);
          }};
}

Command add_sweep_merge(CLI::App& app) {
  auto* cmd = app.add_subcommand("sweep-merge", "join the shard files of one sweep (any order) into the unsharded output");
  struct Opts {
    std::vector<std::string> files;
    std::string out;
  };
  auto o = std::make_shared<Opts>();
  cmd->add_option("files", o->files, "the shard files (from dfchaos sweep --shard i/N), each once")->required()->type_name("FILE ...");
  cmd->add_option("--out", o->out, "write to FILE (atomically) instead of stdout")->type_name("FILE");
  cmd->footer(
      "Prints exactly what the unsharded sweep prints. Refused (exit 2, nothing written): a missing or duplicate\n"
      "shard, shards of different sweeps (spec or build), an incomplete or damaged shard file.");
  return {cmd, [o] {
            std::unique_ptr<sweep::Stream> out;
            if (o->out.empty())
              out = std::make_unique<sweep::StdoutStream>();
            else
              out = std::make_unique<sweep::AtomicFile>(o->out);
            sweep::merge_shards(o->files, *out);
            out->commit();
            return 0;
          }};
}

}  // namespace dfchaos::cli
