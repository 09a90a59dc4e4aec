// SPDX-License-Identifier: GPL-3.0-or-later
#include "sweep/run.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "dfchaos/errors.hpp"
#include "kit/output.hpp"
#include "sweep/header.hpp"

namespace dfchaos::sweep {

namespace fs = std::filesystem;

std::vector<Interval> plan_chunks(long long positions, const std::vector<Interval>& done, long long chunk) {
  std::vector<Interval> plan;
  long long at = 0;
  auto cut = [&](long long end) {
    for (; at < end; at = std::min(end, at + chunk)) plan.push_back(Interval{at, std::min(end, at + chunk)});
  };
  for (const auto& d : done) {
    cut(d.begin);
    at = d.end;
  }
  cut(positions);
  return plan;
}

Run::Run(RunOptions options) : o_(std::move(options)) {
  o_.spec.validate();
  if (o_.chunk < 1 || o_.chunk > kMaxChunk)
    throw InvalidParameter("chunk", "1 <= chunk <= " + format_shortest(static_cast<double>(kMaxChunk)), static_cast<double>(o_.chunk));
  if (!o_.out.empty() && !o_.resume.empty()) throw InvalidParameter("resume", "give --out FILE or --resume FILE, not both");
  if (o_.max_chunks < 0 || o_.max_chunks > kMaxChunks)
    throw InvalidParameter("max-chunks", "0 <= max-chunks <= " + format_shortest(static_cast<double>(kMaxChunks)),
                           static_cast<double>(o_.max_chunks));
  if (o_.max_chunks > 0 && o_.resume.empty()) throw InvalidParameter("max-chunks", "needs --resume FILE (the chunks done are kept there)");
  shard_ = o_.shard.value_or(Shard{});
  if (shard_.count < 1 || shard_.index < 0 || shard_.index >= shard_.count || shard_.count > o_.spec.cells())
    throw InvalidParameter("shard", "0 <= i < N <= cells (got " + shard_.canonical() + ")");
  positions_ = shard_.size(o_.spec.cells());
  if ((positions_ + o_.chunk - 1) / o_.chunk > kMaxChunks)
    throw InvalidParameter("chunk",
                           "at most " + format_shortest(static_cast<double>(kMaxChunks)) + " chunks: chunk >= " +
                               std::to_string((positions_ + kMaxChunks - 1) / kMaxChunks) + " for " + std::to_string(positions_) + " cells",
                           static_cast<double>(o_.chunk));
  const std::string header = header_text(o_.spec, o_.shard);
  std::vector<Interval> done;
  if (!o_.resume.empty()) {
    const fs::path file = o_.resume;
    std::error_code ec;
    if (!fs::exists(Checkpoint::directory(file), ec) && fs::exists(file, ec)) {
      // A finished run: its output is in place (written atomically). Accept it only if it is the
      // complete, undamaged output of this run: sealed, this header, every row well-formed.
      require_regular_file("resume", file);  // before opening: a FIFO would block the open
      std::ifstream in(file, std::ios::binary);
      try {
        (void)check_sweep_file("resume", file.string(), in);
      } catch (const InvalidParameter& e) {
        const std::string why = std::string(e.what()).substr(e.parameter().size() + 2);  // after "resume: "
        throw InvalidParameter("resume", why + "; it cannot be resumed (no FILE.chunks/ beside it): remove it to compute it again");
      }
      std::string head(header.size(), '\0');
      in.clear();
      in.seekg(0);
      in.read(head.data(), static_cast<std::streamsize>(head.size()));
      if (!in || head != header)
        throw InvalidParameter("resume", file.string() +
                                             " exists and is not the output of this run (another spec, build or shard); "
                                             "remove it or choose another FILE");
      already_complete_ = true;
      std::fprintf(stderr, "sweep: %s is already complete\n", file.c_str());
    } else {
      checkpoint_ = std::make_unique<Checkpoint>(file, header, shard_, positions_, o_.spec.columns());
      done = checkpoint_->done();
      if (!done.empty())
        std::fprintf(stderr, "sweep: resuming %s: %lld of %lld cells already done\n", file.c_str(), checkpoint_->done_positions(), positions_);
    }
  } else {
    if (o_.out.empty())
      stream_ = std::make_unique<StdoutStream>();
    else
      stream_ = std::make_unique<AtomicFile>(o_.out);
    stream_->write(header);
    sealer_.add(header, 0);
  }
  if (!already_complete_) chunks_ = plan_chunks(positions_, done, o_.chunk);
  if (o_.max_chunks > 0 && static_cast<long long>(chunks_.size()) > o_.max_chunks) chunks_.resize(static_cast<std::size_t>(o_.max_chunks));
  long long todo = 0;
  for (const auto& c : chunks_) todo += c.size();
  progress_ = std::make_unique<kit::Progress>("sweep", todo, o_.progress);
}

Run::~Run() = default;

std::vector<long long> Run::cells_of(const Interval& chunk) const {
  std::vector<long long> cells;
  cells.reserve(static_cast<std::size_t>(chunk.size()));
  for (long long p = chunk.begin; p < chunk.end; ++p) cells.push_back(shard_.cell(p));
  return cells;
}

void Run::deliver(std::size_t k, const std::string& rows) {
  if (k != delivered_ || k >= chunks_.size()) throw std::logic_error("Run::deliver: chunks must be delivered once each, in order");
  if (checkpoint_)
    checkpoint_->save(chunks_[k], rows);
  else {
    stream_->write(rows);
    sealer_.add(rows, chunks_[k].size());
  }
  ++delivered_;
}

int Run::finish() {
  if (delivered_ != chunks_.size()) throw std::logic_error("Run::finish before every chunk was delivered");
  progress_->done();
  if (already_complete_) return 0;
  if (checkpoint_) {
    if (!checkpoint_->complete()) {
      std::fprintf(stderr, "sweep: stopped after %zu chunk(s) (--max-chunks): %lld of %lld cells done; rerun the same command to continue\n",
                   chunks_.size(), checkpoint_->done_positions(), positions_);
      return kExitIncomplete;
    }
    checkpoint_->assemble();
    return 0;
  }
  stream_->write(sealer_.line());
  stream_->commit();
  return 0;
}

}  // namespace dfchaos::sweep
