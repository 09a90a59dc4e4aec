// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/certified/laps.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "dfchaos/certified/cover.hpp"
#include "dfchaos/certified/discontinuities.hpp"
#include "dfchaos/certified/graph.hpp"
#include "dfchaos/certified/next_hit.hpp"
#include "dfchaos/certified/oracle.hpp"
#include "dfchaos/certified/parameters.hpp"
#include "dfchaos/certified/progression.hpp"
#include "dfchaos/certified/return_map.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/stop.hpp"

namespace dfchaos::certified {

const char* lap_shape_name(LapShape s) {
  switch (s) {
    case LapShape::Increasing: return "increasing";
    case LapShape::Decreasing: return "decreasing";
    case LapShape::Constant: return "constant";
  }
  return "constant";
}

double EntropyBracket::h_upper() const { return std::min(log_laps.upper(), log_rho_upper.upper()); }
double EntropyBracket::h_lower() const { return rho_lower > 1 ? log_rho_lower.lower() : 0.0; }

namespace {

/// Width (relative) under which a cell with a break inside is accepted; wider ones are split.
constexpr double kNarrow = 1e-9;

bool agree(LapShape lap, LapShape piece) { return lap == LapShape::Constant || piece == LapShape::Constant || lap == piece; }

/// Counts of the cells of a cover.
struct Counts {
  long long cells = 0;
  int jump_cells = 0;
  int turning_cells = 0;
  bool used_lemma1 = false;
  void add(const Counts& o) {
    cells += o.cells, jump_cells += o.jump_cells, turning_cells += o.turning_cells;
    used_lemma1 = used_lemma1 || o.used_lemma1;
  }
};

/// A part of the cover under construction (the parts are built in parallel, then joined in order).
struct Cover {
  const ParameterBalls& m;
  const LapOptions& opt;
  const Lemma1Proof* lemma1;  // proved at the point, or null
  double a, b;                // the point (for the floating guesses)
  Counts r;
  std::vector<LapCell> subs;
  bool joins = true;  // whether the next cell continues T from the previous one
  void push(LapCell s) {
    s.joins = s.joins && joins;
    joins = true;
    subs.push_back(std::move(s));
  }
};

/// The sign of \f$\varphi = v_1 - q(\theta_1 - \theta)\f$ over a cell (file comment): +1, -1, or 0 if not proved;
/// `dphi` gets the sign of \f$\varphi'\f$ when \f$\varphi\f$ has none.
int phi_sign(const ParameterBalls& m, const Ball& th, const Ball& th1, int& dphi) {
  dphi = 0;
  const Ball v1 = dG1_dt(m, th, th1, m.b);
  if (!v1.is_positive()) return 0;
  const Ball phi = v1 - m.q * (th1 - th);
  if (phi.is_positive()) return 1;
  if (phi.is_negative()) return -1;
  const Ball d = (m.q - m.F(th)) + (m.F(th1) - m.q) * (m.F(th) * (th1 - th) / v1);
  dphi = d.is_positive() ? 1 : d.is_negative() ? -1 : 0;
  return 0;
}

/// A cell where certify_T proved T continuous: one monotone piece, or two around one turning point.
bool monotone_cell(Cover& c, const StartSet& set, double x, double y, const MapStepProof& t, const std::vector<std::pair<Ball, Ball>>& skip,
                   bool full) {
  LapCell s{x, y, t.T, LapShape::Constant, true, full, skip};
  if (t.constant_t2) {
    s.image = c.m.t2;
    c.push(std::move(s));
    return true;
  }
  int dphi = 0;
  const int sign = phi_sign(c.m, set.hull(c.m), t.t1.enclosure, dphi);
  if (sign != 0) {
    s.shape = sign > 0 ? LapShape::Increasing : LapShape::Decreasing;
    c.push(std::move(s));
    return true;
  }
  // A turning cell is kept narrow (split further while it is wide), for the cores of its laps.
  if (dphi == 0 || y - x > kNarrow * std::max(1.0, std::fabs(x))) return false;
  // phi increasing: theta2 decreases, then increases (and the reverse).
  s.full = false;
  LapCell second = s;
  s.shape = dphi > 0 ? LapShape::Decreasing : LapShape::Increasing;
  second.shape = dphi > 0 ? LapShape::Increasing : LapShape::Decreasing;
  c.push(std::move(s));
  c.push(std::move(second));
  ++c.r.turning_cells;
  return true;
}

/// A cell where theta2 is proved simple and monotone but crosses one \f$t_3 + 2\pi k\f$ inside
/// \f$[t_1 + 2\pi k, t_2 + 2\pi(k+1))\f$: T jumps once, at the crossing (file comment).
bool jump_cell(Cover& c, const StartSet& set, double x, double y, const MapStepProof& t, const std::vector<std::pair<Ball, Ball>>& skip) {
  const ParameterBalls& m = c.m;
  if (!t.t1.verdict || !t.theta2.verdict || !c.lemma1) return false;
  const Ball& lo = t.theta2.u_lo;
  const Ball& hi = t.theta2.u_hi;
  const long long k = static_cast<long long>(std::floor((lo.mid() - m.t1.mid()) / (2 * M_PI)));
  const Ball shift = Ball(static_cast<double>(k)) * m.two_pi;
  if (!(le(m.t1 + shift, lo) && lt(hi, m.t2 + shift + m.two_pi) && lt(lo, m.t3 + shift) && lt(m.t3 + shift, hi))) return false;
  int dphi = 0;
  const int sign = phi_sign(m, set.hull(m), t.t1.enclosure, dphi);
  if (sign == 0) return false;
  const Ball free = Ball::hull(max(t.theta2.enclosure - shift, m.t2), m.t3);
  LapCell left{x, y, free, sign > 0 ? LapShape::Increasing : LapShape::Constant, true, false, skip};
  LapCell right{x, y, m.t2, sign > 0 ? LapShape::Constant : LapShape::Decreasing, false, false, skip};
  if (sign < 0) left.image = m.t2, right.image = free;
  c.push(std::move(left));
  c.push(std::move(right));
  c.r.used_lemma1 = true;
  ++c.r.jump_cells;
  return true;
}

/// Covers [lo, hi] by cells, left to right (file comment). `t1` (optional): options of the T1 proofs
/// (the tangency window skipped); `guess_limit`: the T1 guesses are taken left of it (the branch
/// of the left limit); `from_t2`: the first cell starts at t2 exactly; cells reaching past
/// `full_below` are not full (they contain a discontinuity of T1).
Outcome cover_by_cells(Cover& c, double lo, double hi, const FirstHitOptions* t1, double guess_limit, bool from_t2, double full_below) {
  const ParameterBalls& m = c.m;
  const std::vector<std::pair<Ball, Ball>> skip = t1 ? t1->skip : std::vector<std::pair<Ball, Ball>>{};
  auto check = [&](const Span& cell, int) {
    const auto [x, y] = cell;
    const bool at_t2 = from_t2 && x == lo;
    const StartSet set = at_t2 ? StartSet::from_t2(m, y) : StartSet::interval(x, y);
    FirstHitOptions o = t1 ? *t1 : FirstHitOptions{};
    if (t1) {
      o.guess_at_max = oracle::T1(c.a, c.b, std::min(y, guess_limit));
      o.guess_at_min = oracle::T1(c.a, c.b, std::min(x, guess_limit));
    }
    Budget budget;
    const MapStepProof t = certify_T(m, set, budget, c.lemma1, false, &o);
    const bool full = !at_t2 && y <= full_below;
    const double width = y - x;
    bool proved = false;
    if (t.verdict) {
      c.r.used_lemma1 = c.r.used_lemma1 || t.used_lemma1;
      proved = monotone_cell(c, set, x, y, t, skip, full);
    } else {
      proved = width <= kNarrow * std::max(1.0, std::fabs(x)) && jump_cell(c, set, x, y, t, skip);
    }
    if (proved) {
      if (++c.r.cells > c.opt.max_cells)
        return CellVerdict::stop(Outcome::fail("laps: cells", "more than " + std::to_string(c.opt.max_cells) + " cells"));
      return CellVerdict::proved();
    }
    Outcome why = Outcome::fail("laps: cell", "T not proved continuous and monotone on [" + format_double(x) + ", " + format_double(y) +
                                                  "]: " + (t.verdict ? std::string("the sign of theta2' is not decided") : t.verdict.describe()));
    return width <= c.opt.min_width * std::max(1.0, std::fabs(x)) ? CellVerdict::stop(std::move(why)) : CellVerdict::split(std::move(why));
  };
  return cover(Span(lo, hi), check, halve, std::numeric_limits<int>::max());
}

/// The cell [z, zr] right of a discontinuity of T1 (file comment); false if its checks fail.
bool right_cell(Cover& c, const Tangency& tz, double zr) {
  const ParameterBalls& m = c.m;
  const Ball z_lo = tz.z.lower_ball(), right = Ball(zr);
  const Ball star_hi = tz.t_star.upper_ball();
  // T1 in [s_lo, t*] for theta in [z, zr]: G1(zr, s_lo) < 0 and dG1/dt(z, s_lo) > 0 (concavity on W).
  Ball s_lo;
  bool found = false;
  double d = tz.t_star.lower() - tz.window_lo.upper();
  for (int j = 0; j < 60 && d > 0; ++j, d *= 0.5) {
    const Ball s(tz.t_star.lower() - d);
    if (!le(tz.window_lo, s) || !G1(m, right, s, m.b).is_negative() || !dG1_dt(m, z_lo, s, m.b).is_positive()) break;
    s_lo = s;
    found = true;
  }
  if (!found) return false;
  const Ball th = Ball::hull(z_lo, right), th1 = Ball::hull(s_lo, star_hi);
  const Ball v1 = dG1_dt(m, th, th1, m.b);
  if (!(m.q * (th1 - th) - v1).is_positive()) return false;  // phi < 0: theta2 decreases
  // The progression stops within Delta of the impact: G2 decreases on [theta1, theta1 + Delta] and is
  // negative at its end, G2(theta1 + Delta) = v1 + 2a sin(theta1 + Delta/2) sin(Delta/2) + 2c Delta.
  for (double delta = 1e-15; delta < 0.5; delta *= 2) {
    const Ball D(delta);
    const Ball end = v1 + Ball(2.0) * m.a * sin(th1 + D * 0.5) * sin(D * 0.5) + m.two_c * D;
    if (!end.is_negative()) continue;
    const Ball th2 = Ball::hull(th1.lower_ball(), (th1 + D).upper_ball());
    if (!(m.F(th2) - m.q).is_negative()) return false;
    const long long k = static_cast<long long>(std::floor((th2.mid() - m.t2.mid()) / (2 * M_PI)));
    const Ball shift = Ball(static_cast<double>(k)) * m.two_pi;
    if (!(lt(m.t2 + shift, th2) && lt(th2, m.t3 + shift))) return false;
    c.joins = false;  // T jumps at z
    c.push(LapCell{z_lo.lower(), zr, th2 - shift, LapShape::Decreasing, false, false, {}});
    ++c.r.cells;
    return true;
  }
  return false;
}

/// T = t2 on [x*, t3) (file comment, the end); false if the checks fail at this x*.
bool end_piece(const ParameterBalls& m, double x_star) {
  const Ball x(x_star), eps = m.t3 - x;
  for (double mult : {2.5, 3.0, 4.0, 6.0}) {
    const Ball t_hit = (m.t3 + Ball(mult) * eps).upper_ball();
    if (!G1(m, x, t_hit, m.b).is_positive()) continue;
    for (double d = 1e-12; d < 1; d *= 2) {
      const Ball t_end = t_hit + Ball(d);
      if (!lt(t_end, m.t0 + m.two_pi)) return false;
      if ((dG1_dt(m, m.t3, t_end, m.b) - m.q * (t_end - t_hit)).is_negative()) return true;
    }
  }
  return false;
}

/// T at the single phase x (with the T1 windows skipped), or the fallback enclosure.
Ball T_at(const ParameterBalls& m, const Lemma1Proof* lemma1, double x, const std::vector<std::pair<Ball, Ball>>& skip, const Ball& fallback,
          double a, double b) {
  FirstHitOptions o;
  o.skip = skip;
  if (!skip.empty()) o.guess_at_max = o.guess_at_min = oracle::T1(a, b, x);
  Budget budget;
  const MapStepProof t = certify_T(m, StartSet::point(x), budget, lemma1, false, &o);
  if (!t.verdict) return fallback;
  return t.constant_t2 ? m.t2 : t.T;
}

/// The laps whose hulls meet [lo, hi]: [first, last] (laps ascending, their ends nondecreasing).
std::pair<std::size_t, std::size_t> laps_met(const std::vector<Lap>& laps, double lo, double hi) {
  const auto first = std::lower_bound(laps.begin(), laps.end(), lo, [](const Lap& k, double v) { return k.hi < v; });
  const auto last = std::upper_bound(laps.begin(), laps.end(), hi, [](double v, const Lap& k) { return v < k.lo; });
  return {static_cast<std::size_t>(first - laps.begin()), static_cast<std::size_t>(last - laps.begin())};
}

/// Splits a whole cell while its image meets more than one lap (T stays continuous and monotone
/// on each half, which certify_T encloses again); a half that is not proved keeps the cell whole.
void split_cell(const ParameterBalls& m, const Lemma1Proof* lemma1, const std::vector<Lap>& laps, const LapCell& cell, double a, double b,
                std::vector<LapCell>& out) {
  const auto [first, last] = laps_met(laps, cell.image.lower(), cell.image.upper());
  const double mid = 0.5 * (cell.lo + cell.hi);
  if (last <= first + 1 || !cell.full || cell.hi - cell.lo <= kNarrow * std::max(1.0, std::fabs(cell.lo)) || !(mid > cell.lo && mid < cell.hi)) {
    out.push_back(cell);
    return;
  }
  LapCell half[2] = {cell, cell};
  half[0].hi = mid;
  half[1].lo = mid;
  for (LapCell& h : half) {
    FirstHitOptions o;
    o.skip = h.skip;
    if (!h.skip.empty()) o.guess_at_max = oracle::T1(a, b, h.hi), o.guess_at_min = oracle::T1(a, b, h.lo);
    Budget budget;
    const MapStepProof t = certify_T(m, StartSet::interval(h.lo, h.hi), budget, lemma1, false, &o);
    if (!t.verdict) {
      out.push_back(cell);
      return;
    }
    h.image = t.constant_t2 ? m.t2 : t.T;
  }
  half[1].joins = true;
  split_cell(m, lemma1, laps, half[0], a, b, out);
  split_cell(m, lemma1, laps, half[1], a, b, out);
}

/// One piece of the refined partition: the points of a lap j that T sends into lap k.
struct Piece {
  double lo = 0, hi = 0;   // hull (exact)
  Ball image;              // T on it, inside the hull of lap k
  std::size_t target = 0;  // k (the pieces of the unrefined laps: unused)
};

/// The partition of the laps by the preimages of the laps (the laps of \f$T^2\f$, each piece
/// over-approximated), per lap j the pieces sent into each lap k, ascending.
/// A closed segment on which T is proved continuous, with T enclosed at its ends (a vertex of the
/// covering graph of the lower bound), inside lap `target` of the blocks' partition when refined.
struct CorePiece {
  double lo = 0, hi = 0;
  Ball T_lo, T_hi;
  std::size_t target = 0;
};

/// The refined partition: per lap j, the pieces sent into each lap k and their cores.
struct Refined {
  std::vector<std::vector<Piece>> pieces;
  std::vector<std::vector<CorePiece>> cores;
};

Refined refine(const ParameterBalls& m, const Lemma1Proof* lemma1, const LapPartition& p) {
  const std::vector<Lap>& laps = p.laps;
  std::vector<std::vector<Piece>> per_lap(laps.size());
  std::vector<std::vector<CorePiece>> cores(laps.size());
  const StopToken* token = current_stop_token();  // installed in each thread; Stopped cannot leave a parallel region
  bool stopped = false;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t j = 0; j < laps.size(); ++j) {
    const StopScope scope(token);
    try {
      std::vector<LapCell> cells;
      for (std::size_t c = laps[j].first_cell; c < laps[j].end_cell; ++c) split_cell(m, lemma1, laps, p.parts[c], p.a, p.b, cells);
      const auto [first, last] = laps_met(laps, laps[j].image.lower(), laps[j].image.upper());
      for (std::size_t k = first; k < last; ++k) {
        Piece q;
        bool any = false;
        for (const LapCell& c : cells) {
          if (c.image.upper() < laps[k].lo || c.image.lower() > laps[k].hi) continue;
          // T on this part lies in lap k too: the image clamped to lap k's hull.
          const Ball part = Ball::hull(max(c.image, Ball(laps[k].lo)).lower_ball(), min(c.image, Ball(laps[k].hi)).upper_ball());
          q.lo = any ? std::min(q.lo, c.lo) : c.lo;
          q.hi = any ? std::max(q.hi, c.hi) : c.hi;
          q.image = any ? Ball::hull(q.image, part) : part;
          any = true;
        }
        q.target = k;
        if (any) per_lap[j].push_back(q);
        // Its core: the first run of whole cells sent into lap k alone.
        std::size_t run_lo = cells.size(), run_hi = cells.size();
        for (std::size_t i = 0; i < cells.size(); ++i) {
          const LapCell& c = cells[i];
          const auto [f, l] = laps_met(laps, c.image.lower(), c.image.upper());
          const bool alone = c.full && f == k && l == k + 1;
          if (alone && run_lo == cells.size())
            run_lo = run_hi = i;
          else if (alone && run_hi + 1 == i)
            run_hi = i;
          else if (run_lo != cells.size() && !alone)
            break;
        }
        if (run_lo < cells.size()) {
          const LapCell& first_cell = cells[run_lo];
          const LapCell& last_cell = cells[run_hi];
          cores[j].push_back(CorePiece{first_cell.lo, last_cell.hi, T_at(m, lemma1, first_cell.lo, first_cell.skip, first_cell.image, p.a, p.b),
                                       T_at(m, lemma1, last_cell.hi, last_cell.skip, last_cell.image, p.a, p.b), k});
        }
      }
    } catch (const Stopped&) {
#pragma omp atomic write
      stopped = true;
    }
  }
  if (stopped) poll_stop();
  for (auto& v : per_lap) std::sort(v.begin(), v.end(), [](const Piece& u, const Piece& w) { return u.lo < w.lo || (u.lo == w.lo && u.hi < w.hi); });
  for (auto& v : cores) std::sort(v.begin(), v.end(), [](const CorePiece& u, const CorePiece& w) { return u.lo < w.lo; });
  return Refined{std::move(per_lap), std::move(cores)};
}

/// The lower bound of the covering graph on cores in blocks (ascending and disjoint in each block):
/// a -> b when core b lies strictly between the enclosures of T at the ends of core a (a contiguous
/// range), b in the block of a's target when `by_target`, else in the one block.
struct LowerBound {
  double rho = 0;  // proved lower bound of rho (0: none above 1)
  int vertices = 0;
  long long edges = 0;
};

LowerBound covering_lower(const std::vector<std::vector<CorePiece>>& blocks, bool by_target) {
  std::vector<double> core_lo, core_hi;
  std::vector<std::size_t> start;
  for (const auto& block : blocks) {
    start.push_back(core_lo.size());
    for (const CorePiece& c : block) core_lo.push_back(c.lo), core_hi.push_back(c.hi);
  }
  start.push_back(core_lo.size());
  const std::size_t nc = core_lo.size();
  BandMatrix A;
  std::vector<std::vector<int>> succ;
  for (const auto& block : blocks)
    for (const CorePiece& c : block) {
      const std::size_t b = by_target ? c.target : 0;
      const auto lo_begin = core_lo.begin() + static_cast<std::ptrdiff_t>(start[b]),
                 lo_end = core_lo.begin() + static_cast<std::ptrdiff_t>(start[b + 1]);
      const auto hi_begin = core_hi.begin() + static_cast<std::ptrdiff_t>(start[b]),
                 hi_end = core_hi.begin() + static_cast<std::ptrdiff_t>(start[b + 1]);
      const double lo = min(c.T_lo, c.T_hi).upper(), hi = max(c.T_lo, c.T_hi).lower();
      const int first = static_cast<int>(std::upper_bound(lo_begin, lo_end, lo) - core_lo.begin());
      const int last = static_cast<int>(std::lower_bound(hi_begin, hi_end, hi) - core_hi.begin()) - 1;
      A.first.push_back(first);
      A.last.push_back(last);
      succ.emplace_back();
      for (int k = first; k <= last; ++k) succ.back().push_back(k);
    }
  const PerronPart part = perron_part(succ);
  succ.clear();
  LowerBound r;
  if (!(part.rho > 1) || part.vertices.empty()) return r;
  // Collatz-Wielandt from below on the part: v = its Perron vector, 0 off the part.
  std::vector<double> w(nc, 0.0);
  for (std::size_t i = 0; i < part.vertices.size(); ++i) w[part.vertices[i]] = part.v[i];
  std::vector<Ball> prefix(nc + 1, Ball(0.0));
  for (std::size_t k = 0; k < nc; ++k) prefix[k + 1] = prefix[k] + Ball(w[k]);
  Ball least;
  for (std::size_t i = 0; i < part.vertices.size(); ++i) {
    const int j = part.vertices[i];
    const Ball ratio = (prefix[A.last[j] + 1] - prefix[A.first[j]]) / Ball(part.v[i]);
    least = i == 0 ? ratio : min(least, ratio);
    r.edges += A.last[j] - A.first[j] + 1;
  }
  r.vertices = static_cast<int>(part.vertices.size());
  if (least.lower() > 1) r.rho = least.lower();
  return r;
}

/// The columns [first, last] of the pieces in [begin, end) (sorted by left ends) whose hulls meet
/// the image: from the first whose running maximum of right ends reaches it to the last whose left
/// end does not pass it (a superset of the true row when the hulls overlap).
void meets_row(const std::vector<double>& lo, const std::vector<double>& reach, std::size_t begin, std::size_t end, const Ball& image,
               BandMatrix& M) {
  M.first.push_back(static_cast<int>(
      std::lower_bound(reach.begin() + static_cast<std::ptrdiff_t>(begin), reach.begin() + static_cast<std::ptrdiff_t>(end), image.lower()) -
      reach.begin()));
  M.last.push_back(static_cast<int>(std::upper_bound(lo.begin() + static_cast<std::ptrdiff_t>(begin), lo.begin() + static_cast<std::ptrdiff_t>(end),
                                                     image.upper()) -
                                    lo.begin()) -
                   1);
}

/// "T(piece a) meets piece b" over pieces in blocks (one block, or one per lap); running maxima
/// of the right ends are taken per block.
BandMatrix meets_matrix(const std::vector<std::vector<Piece>>& blocks, bool by_target) {
  std::vector<double> lo, reach;
  std::vector<std::size_t> start;
  for (const auto& block : blocks) {
    start.push_back(lo.size());
    double running = -std::numeric_limits<double>::infinity();
    for (const Piece& q : block) lo.push_back(q.lo), reach.push_back(running = std::max(running, q.hi));
  }
  start.push_back(lo.size());
  BandMatrix M;
  for (const auto& block : blocks)
    for (const Piece& q : block) {
      // A piece sent into lap k meets only pieces of lap k (the laps are disjoint).
      const std::size_t b = by_target ? q.target : 0;
      meets_row(lo, reach, start[b], start[b + 1], q.image, M);
    }
  return M;
}

}  // namespace

LapPartition prove_laps(double a, double b, double q, const LapOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  LapPartition r;
  r.a = a, r.b = b, r.q = q;
  auto finish = [&](Outcome v) {
    r.verdict = std::move(v);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.verdict) r.laps.clear(), r.parts.clear();
    return r;
  };
  const ParameterBalls m(ParameterBox::point(a, b, q));
  if (Outcome v = m.admissible(); !v) return finish(v);
  const Lemma1Proof l1 = certify_lemma1(m);
  const Lemma1Proof* lemma1 = l1.verdict ? &l1 : nullptr;
  // The end [x*, t3): T = t2.
  double x_star = std::numeric_limits<double>::quiet_NaN();
  for (double eps : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5}) {
    const double x = m.t3.lower() - eps;
    if (lt(m.t2, Ball(x)) && lemma1 && end_piece(m, x)) {
      x_star = x;
      break;
    }
  }
  if (std::isnan(x_star)) return finish(Outcome::fail("laps: end", "T = t2 near t3 not proved (or Lemma 1 not proved at the point)"));
  r.end = x_star;
  // The discontinuities of T1 (Lemma 2) on [lo0, x*].
  const double lo0 = m.t2.upper() + 1e-9 * (m.t3.lower() - m.t2.upper());
  const DiscontinuityProof disc = prove_discontinuities(a, b, Ball(lo0), Ball(x_star), opt.max_tangencies, false);
  if (!disc.verdict) return finish(Outcome::fail("laps: discontinuities of T1", disc.verdict.describe()));
  r.tangencies = static_cast<int>(disc.z.size());
  const std::size_t nz = disc.z.size();
  const double inf = std::numeric_limits<double>::infinity();
  // Parts: [t2, lo0]; per discontinuity z_i, the cell right of it (first, in parallel: the next
  // part starts where it ends), then [z_{i-1} side, z_i]; last [z_n side, x*]. Each part is built
  // alone and the parts are joined in order, so the result does not depend on the threads.
  std::vector<Cover> right(nz, Cover{m, opt, lemma1, a, b, {}, {}});
  std::vector<double> zr(nz, std::numeric_limits<double>::quiet_NaN());
  std::vector<Cover> parts(nz + 2, Cover{m, opt, lemma1, a, b, {}, {}});
  std::vector<Outcome> verdicts(nz + 2, Outcome::ok());
  const StopToken* token = current_stop_token();  // installed in each thread; Stopped cannot leave a parallel region
  bool stopped = false;
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t i = 0; i < nz; ++i) {
    const StopScope scope(token);
    try {
      // Right of z: the largest [z, zr] (zr <= the right piece of Lemma 2) where right_cell holds.
      const Tangency& tz = disc.z[i];
      const double z_hi = tz.z.upper(), eta = tz.right_hi.mid() - z_hi;
      for (int j = 0; j < 12; ++j) {
        const double y = z_hi + eta / std::pow(4.0, j);
        if (y > z_hi && right_cell(right[i], tz, y)) {
          zr[i] = y;
          break;
        }
      }
    } catch (const Stopped&) {
#pragma omp atomic write
      stopped = true;
    }
  }
  if (stopped) poll_stop();
  for (std::size_t i = 0; i < nz; ++i)
    if (std::isnan(zr[i])) return finish(Outcome::fail("laps: right of a discontinuity of T1", "z = " + disc.z[i].z.mid_str(17)));
#pragma omp parallel for schedule(dynamic, 4)
  for (std::size_t i = 0; i < nz + 2; ++i) {
    const StopScope scope(token);
    try {
      Cover& c = parts[i];
      if (i == 0) {
        verdicts[i] = cover_by_cells(c, m.t2.lower(), lo0, nullptr, inf, true, inf);
        continue;
      }
      const double cursor = i == 1 ? lo0 : zr[i - 2];
      if (i == nz + 1) {
        verdicts[i] = cover_by_cells(c, cursor, x_star, nullptr, inf, false, inf);
        continue;
      }
      const Tangency& tz = disc.z[i - 1];
      const double z_lo = tz.z.lower(), z_hi = tz.z.upper();
      const double left_start = z_lo - std::max((z_lo - cursor) / 8, 0.0);
      FirstHitOptions skip;
      skip.skip = {{tz.window_lo, tz.window_hi}};
      const double guess_limit = z_lo - std::max(1e-9, 1e-6 * (z_lo - left_start));
      // The cell that holds z is kept narrow, so that the core of the lap reaches close to z.
      const double near_z = z_lo - std::max(1e-9 * (z_lo - left_start), 1e-15 * z_lo);
      Outcome v = cover_by_cells(c, cursor, left_start, nullptr, inf, false, inf);
      if (v) v = cover_by_cells(c, left_start, near_z, &skip, guess_limit, false, inf);
      if (v) v = cover_by_cells(c, near_z, z_hi, &skip, guess_limit, false, -inf);
      verdicts[i] = v;
    } catch (const Stopped&) {
#pragma omp atomic write
      stopped = true;
    }
  }
  if (stopped) poll_stop();
  Counts counts;
  std::vector<LapCell> subs;
  for (std::size_t i = 0; i < nz + 2; ++i) {
    if (!verdicts[i]) return finish(verdicts[i]);
    counts.add(parts[i].r);
    subs.insert(subs.end(), parts[i].subs.begin(), parts[i].subs.end());
    if (i >= 1 && i <= nz) {
      counts.add(right[i - 1].r);
      subs.insert(subs.end(), right[i - 1].subs.begin(), right[i - 1].subs.end());  // joins = false: T jumps at z
    }
  }
  subs.push_back(LapCell{x_star, m.t3.upper(), m.t2, LapShape::Constant, true, false, {}});
  if (counts.cells > opt.max_cells) return finish(Outcome::fail("laps: cells", "more than " + std::to_string(opt.max_cells) + " cells"));
  r.cells = counts.cells, r.jump_cells = counts.jump_cells, r.turning_cells = counts.turning_cells;
  r.used_lemma1 = counts.used_lemma1;
  // Merge the pieces into laps; the core of a lap is its first closed run of full cells.
  bool core_open = false;  // the current lap's core can still grow
  std::vector<std::pair<const LapCell*, const LapCell*>> core_ends;
  for (const LapCell& s : subs) {
    if (!r.laps.empty() && s.joins && agree(r.laps.back().shape, s.shape)) {
      Lap& l = r.laps.back();
      l.hi = std::max(l.hi, s.hi);
      l.image = Ball::hull(l.image, s.image);
      if (l.shape == LapShape::Constant) l.shape = s.shape;
    } else {
      Lap l;
      l.lo = s.lo, l.hi = s.hi, l.image = s.image, l.shape = s.shape;
      l.first_cell = static_cast<std::size_t>(&s - subs.data());
      r.laps.push_back(l);
      core_ends.emplace_back(nullptr, nullptr);
      core_open = true;
    }
    r.laps.back().end_cell = static_cast<std::size_t>(&s - subs.data()) + 1;
    auto& [first, last] = core_ends.back();
    if (s.full && core_open) {
      if (!first) first = &s;
      last = &s;
    } else if (first) {
      core_open = false;
    }
  }
  // The searches over the laps (laps_met, meets_row) need both ends nondecreasing: widen the hulls
  // where a cell of a break starts after the next lap's first cell (a superset keeps every bound).
  for (std::size_t j = r.laps.size(); j-- > 1;) r.laps[j - 1].lo = std::min(r.laps[j - 1].lo, r.laps[j].lo);
  for (std::size_t j = 1; j < r.laps.size(); ++j) r.laps[j].hi = std::max(r.laps[j].hi, r.laps[j - 1].hi);
  const std::size_t nl = r.laps.size();
#pragma omp parallel for schedule(dynamic, 16)
  for (std::size_t j = 0; j < nl; ++j) {
    const StopScope scope(token);
    const auto [first, last] = core_ends[j];
    if (!first) continue;
    try {
      Lap& l = r.laps[j];
      l.has_core = true;
      l.core_lo = first->lo;
      l.core_hi = last->hi;
      l.T_core_lo = T_at(m, lemma1, first->lo, first->skip, first->image, a, b);
      l.T_core_hi = T_at(m, lemma1, last->hi, last->skip, last->image, a, b);
    } catch (const Stopped&) {
#pragma omp atomic write
      stopped = true;
    }
  }
  if (stopped) poll_stop();
  r.parts = std::move(subs);
  return finish(Outcome::ok());
}

EntropyBracket prove_entropy_bracket(double a, double b, double q, const LapOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  EntropyBracket e;
  e.partition = prove_laps(a, b, q, opt);
  auto finish = [&](Outcome v) {
    e.verdict = std::move(v);
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
  };
  if (!e.partition.verdict) return finish(e.partition.verdict);
  const std::vector<Lap>& laps = e.partition.laps;
  const int n = static_cast<int>(laps.size());
  e.log_laps = log(Ball(static_cast<long>(n)));
  // On the laps: upper, M_jk = 1 when the enclosure of T on lap j meets the hull of lap k; lower,
  // the covering graph on the cores of the laps.
  std::vector<std::vector<Piece>> pieces(1);
  for (const Lap& l : laps) pieces[0].push_back(Piece{l.lo, l.hi, l.image, 0});
  const BandMatrix M = meets_matrix(pieces, false);
  e.ones = M.ones();
  e.rho_upper = collatz_wielandt_upper(M);
  if (!std::isfinite(e.rho_upper)) return finish(Outcome::fail("entropy: upper bound", "no finite Collatz-Wielandt bound"));
  std::vector<std::vector<CorePiece>> cores(1);
  for (const Lap& l : laps)
    if (l.has_core && l.core_lo < l.core_hi) cores[0].push_back(CorePiece{l.core_lo, l.core_hi, l.T_core_lo, l.T_core_hi, 0});
  LowerBound lower = covering_lower(cores, false);
  // Both again on the laps refined by the preimages of the laps, when the gap is wide.
  const bool wide = !(lower.rho > 1) || std::log(lower.rho) < (1 - opt.target_gap) * std::log(e.rho_upper);
  if (opt.refine && wide && static_cast<long long>(n) * static_cast<long long>(n) <= opt.max_refined) {
    const ParameterBalls m(ParameterBox::point(a, b, q));
    const Lemma1Proof l1 = certify_lemma1(m);
    const Refined refined = refine(m, l1.verdict ? &l1 : nullptr, e.partition);
    const BandMatrix M2 = meets_matrix(refined.pieces, true);
    const double rho2 = collatz_wielandt_upper(M2);
    e.refined_pieces = static_cast<long long>(M2.first.size());
    if (rho2 < e.rho_upper) e.rho_upper = rho2, e.ones = M2.ones();
    const LowerBound second = covering_lower(refined.cores, true);
    if (second.rho > lower.rho) lower = second;
  }
  e.log_rho_upper = log(Ball(e.rho_upper));
  e.rho_lower = lower.rho, e.lower_vertices = lower.vertices, e.lower_edges = lower.edges;
  if (e.rho_lower > 1) e.log_rho_lower = log(Ball(e.rho_lower));
  return finish(Outcome::ok());
}

}  // namespace dfchaos::certified
