// SPDX-License-Identifier: GPL-3.0-or-later
#include "dfchaos/ode_map.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cmath>
#include <memory>

#include "dfchaos/bisect.hpp"
#include "dfchaos/errors.hpp"
#include "dfchaos/phase.hpp"

namespace dfchaos {

namespace {

struct System {
  const Parameters* p;
  const OdeMapOptions* o;
  bool progression;
  long evaluations = 0;
  double force(double t, double x, double v) const {
    double f = p->F(t);
    if (o->perturbation) f += o->perturbation(t, x, v);
    return progression ? f - p->q() : f;
  }
};

int rhs(double t, const double y[], double dydt[], void* params) {
  auto* s = static_cast<System*>(params);
  ++s->evaluations;
  dydt[0] = y[1];
  dydt[1] = s->force(t, y[0], y[1]);
  return GSL_SUCCESS;
}

/// Integrates (x, v) from t to t_target exactly (a fresh driver: no state carried over).
void integrate_to(System& sys, double& t, double t_target, double y[2], const OdeMapOptions& o) {
  if (t_target <= t) return;
  gsl_odeiv2_system ode{rhs, nullptr, 2, &sys};
  std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> d(
      gsl_odeiv2_driver_alloc_y_new(&ode, gsl_odeiv2_step_rk8pd, std::min(o.max_step, t_target - t), o.eps_abs, o.eps_rel), &gsl_odeiv2_driver_free);
  gsl_odeiv2_driver_set_hmax(d.get(), o.max_step);
  if (gsl_odeiv2_driver_apply(d.get(), &t, t_target, y) != GSL_SUCCESS) throw GaveUp("ode_return_map_step: integration failed");
}

/// Integrates the regime from (t, y) until event(t, y) changes sign from negative to >= 0
/// (the initial value counts as negative). Leaves (t, y) at the right end of the final bracket.
template <class Event>
void integrate_until(System& sys, double& t, double y[2], Event event, long& steps, const OdeMapOptions& o) {
  gsl_odeiv2_system ode{rhs, nullptr, 2, &sys};
  std::unique_ptr<gsl_odeiv2_step, decltype(&gsl_odeiv2_step_free)> st(gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2), &gsl_odeiv2_step_free);
  std::unique_ptr<gsl_odeiv2_control, decltype(&gsl_odeiv2_control_free)> ctl(gsl_odeiv2_control_y_new(o.eps_abs, o.eps_rel),
                                                                              &gsl_odeiv2_control_free);
  std::unique_ptr<gsl_odeiv2_evolve, decltype(&gsl_odeiv2_evolve_free)> ev(gsl_odeiv2_evolve_alloc(2), &gsl_odeiv2_evolve_free);
  double h = o.max_step * 0.1;
  while (true) {
    if (++steps > o.max_steps) throw GaveUp("ode_return_map_step: gave up after " + std::to_string(o.max_steps) + " steps");
    const double t_prev = t, y_prev[2] = {y[0], y[1]};
    const double t_cap = t + o.max_step;
    if (gsl_odeiv2_evolve_apply(ev.get(), ctl.get(), st.get(), &ode, &t, t_cap, &h, y) != GSL_SUCCESS)
      throw GaveUp("ode_return_map_step: integration failed");
    if (h > o.max_step) h = o.max_step;
    if (event(t, y) < 0) continue;
    // Sign change in (t_prev, t]: bisect, re-integrating from the start of the step.
    // The state at the bracket's right end: kept from the last test where the event was reached.
    double y_hi[2] = {y[0], y[1]};
    const auto before_event = [&](double mid) {
      double tm = t_prev, ym[2] = {y_prev[0], y_prev[1]};
      integrate_to(sys, tm, mid, ym, o);
      if (event(mid, ym) < 0) return true;
      y_hi[0] = ym[0];
      y_hi[1] = ym[1];
      return false;
    };
    t = bisect(before_event, t_prev, t, {.abs_tol = o.event_tol}).second;
    y[0] = y_hi[0];
    y[1] = y_hi[1];
    return;
  }
}

}  // namespace

OdeMapStep ode_return_map_step(const Parameters& p, double theta, const OdeMapOptions& o) {
  p.require_return_map();
  if (!p.in_map_domain(theta)) throw InvalidParameter("theta", "t2 <= theta < t3", theta);
  if (!(o.max_step > 0) || !(o.event_tol > 0)) throw InvalidParameter("max_step", "max_step > 0 and event_tol > 0");
  gsl_set_error_handler_off();

  OdeMapStep out;
  System sys{&p, &o, false};
  double t = theta, y[2] = {0.0, 0.0}, delimiter = 0.0;
  out.chain = "f";
  char regime = 'f';
  int restarts = 0;
  auto contact_force = [&](double tt) {
    double f = p.F(tt);
    if (o.perturbation) f += o.perturbation(tt, delimiter, 0.0);
    return f;
  };
  for (int n = 0; n < 8; ++n) {
    if (regime == 'f') {
      sys.progression = false;
      integrate_until(
          sys, t, y, [&](double, const double* yy) { return yy[0] - delimiter; }, out.steps, o);
      if (out.chain == "f") {
        out.T1 = t;
        out.hit_velocity = y[1];
      }
      y[0] = delimiter;
      regime = y[1] > 0 ? 'p' : (contact_force(t) < 0 ? 'f' : 's');
    } else if (regime == 'p') {
      sys.progression = true;
      const double x_start = y[0];
      integrate_until(
          sys, t, y, [&](double, const double* yy) { return -yy[1]; }, out.steps, o);
      out.penetration += y[0] - x_start;
      delimiter = y[0];
      y[1] = 0;
      regime = contact_force(t) < 0 ? 'f' : 's';
    } else {
      // Stop: scan the contact force for leaving [0, q], then bisect.
      auto leaves = [&](double tt) {
        const double f = contact_force(tt);
        return f < 0 || f > p.q();
      };
      double lo = t, hi = t;
      long scans = 0;
      do {
        lo = hi;
        hi = lo + o.max_step;
        if (++scans > o.max_steps) throw GaveUp("ode_return_map_step: a stop never ends");
      } while (!leaves(hi));
      // (bisect also stops at adjacent doubles: at large t the tolerance can be below one ulp)
      t = bisect([&](double mid) { return !leaves(mid); }, lo, hi, {.abs_tol = o.event_tol}).second;
      y[0] = delimiter;
      y[1] = 0;
      if (contact_force(t) < 0)
        regime = 'f';
      else {
        regime = 'p';
        if (++restarts >= 2) throw GaveUp("ode_return_map_step: no return to free flight");
      }
    }
    out.chain += std::string(">") + regime;
    if (regime == 'f') {
      out.T = wrap_phase(t);
      out.elapsed = t - theta;
      out.rhs_evaluations = sys.evaluations;
      return out;
    }
  }
  throw GaveUp("ode_return_map_step: no return to free flight within 8 regime changes");
}

std::pair<double, double> integrate_forced_motion(double a, double C, double t0, double x0, double v0, double t1, double eps) {
  for (double v : {a, C, t0, x0, v0, t1})
    if (!std::isfinite(v)) throw InvalidParameter("integrate_forced_motion", "finite arguments");
  if (!(t1 >= t0)) throw InvalidParameter("t1", "t1 >= t0", t1);
  gsl_set_error_handler_off();
  struct Force {
    double a, C;
  } force{a, C};
  auto rhs = [](double t, const double y[], double dydt[], void* params) -> int {
    const auto* f = static_cast<const Force*>(params);
    dydt[0] = y[1];
    dydt[1] = f->a * std::sin(t) + f->C;
    return GSL_SUCCESS;
  };
  gsl_odeiv2_system sys{rhs, nullptr, 2, &force};
  std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> d(gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, eps, eps),
                                                                          &gsl_odeiv2_driver_free);
  gsl_odeiv2_driver_set_nmax(d.get(), 100'000'000);
  double t = t0, y[2] = {x0, v0};
  if (t1 > t0 && gsl_odeiv2_driver_apply(d.get(), &t, t1, y) != GSL_SUCCESS)
    throw GaveUp("integrate_forced_motion: GSL odeiv2 failed between " + format_double(t0) + " and " + format_double(t1));
  return {y[0], y[1]};
}

}  // namespace dfchaos
